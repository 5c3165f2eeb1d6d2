#pragma once
// The questions an effect may answer (effect_set.hpp), each a bit of Hooks. A unit declares the
// ones it answers, as a LAMMPS fix's setmask() does but at compile time:
//   static constexpr Hooks kHooks = hook::restitution | hook::save;
// and EffectSet asks it those and no other. HooksChecked<U, D> holds each declared hook to its
// name and signature, and each member named as a hook to its declaration, so that a misspelled or
// mistyped hook stops the build with a message naming it instead of compiling to nothing
// (tests/simulate/hook_check_test.cmake proves it).
#include <array>
#include <concepts>
#include <cstdint>
#include <utility>
#include <vector>

#include "gg/box.hpp"
#include "ggsim/effects/effect_state.hpp"
#include "ggsim/particles.hpp"

namespace ggsim {

using Hooks = unsigned;

namespace hook {
enum : Hooks {
  restitution = 1u << 0,           // void restitution(double& e, double n.v_ij, uint32 i, uint32 j, double t)
  after_impulse = 1u << 1,         // void after_impulse(Vec& v_i, Vec& v_j, uint32 i, uint32 j, const Vec& n)
  add_virial = 1u << 2,            // void add_virial(double w)
  add_collision_stress = 1u << 3,  // void add_collision_stress(const Vec& r_ij, double w)
  folds = 1u << 4,                 // wrap_near(i, k, x, box), wrap(i, k, x, box), image(i) const, count(i)
  timed = 1u << 5,                 // double next_time() const, pair(), void kick(Vec& v_i, Vec& v_j)
  prefetch = 1u << 6,              // void prefetch(uint32 i) const
  permute = 1u << 7,               // void permute(const Rank& rank)
  save = 1u << 8,                  // void save(const EffectSink&) const
  observables = 1u << 9,           // void observables(const ObservableSink&[, const Sample&])
  frame_values = 1u << 10,         // std::vector<FrameField> frame_fields() const, void frame_values(const FrameSink&) const
  fixed_values = 1u << 11,         // void fixed_values(const FrameSink&) const
  sizes = 1u << 12,                // double mass(uint32 i) const, double radius(uint32 i) const,
                                   // double radius_cap() const, void set_size(uint32 i, double m, double r),
                                   // void set_radius_cap(double)
  compact = 1u << 13,              // void compact(const std::vector<uint32>& kept)
};
}  // namespace hook

// The parameters and result of a member function, R(A...), const or not.
template <class M>
struct MemberSignature {
  using type = void;
};
template <class C, class R, class... A>
struct MemberSignature<R (C::*)(A...)> {
  using type = R(A...);
};
template <class C, class R, class... A>
struct MemberSignature<R (C::*)(A...) const> {
  using type = R(A...);
};
template <class M, class F>
concept Signature = std::same_as<typename MemberSignature<M>::type, F>;

// Whether unit U declares hook H.
template <class U, Hooks H>
inline constexpr bool kDeclares = (U::kHooks & H) != 0;

// A unit of an EffectSet: it declares its hooks.
template <class U>
concept EffectUnit = requires {
  { U::kHooks } -> std::convertible_to<Hooks>;
};

template <class U, int D>
consteval bool hooks_checked() {
  using V = Vec<D>;
  using u32 = std::uint32_t;
  using Image = std::array<std::int32_t, D>;  // image_counts.hpp's Image<D>
  static_assert(!kDeclares<U, hook::restitution> ||
                    requires { requires Signature<decltype(&U::restitution), void(double&, double, u32, u32, double)>; },
                "an effect declares hook::restitution but has no "
                "void restitution(double& e, double vn, std::uint32_t i, std::uint32_t j, double t)");
  static_assert(!kDeclares<U, hook::after_impulse> ||
                    requires { requires Signature<decltype(&U::after_impulse), void(V&, V&, u32, u32, const V&)>; },
                "an effect declares hook::after_impulse but has no "
                "void after_impulse(Vec<D>& va, Vec<D>& vb, std::uint32_t i, std::uint32_t j, const Vec<D>& n)");
  static_assert(!kDeclares<U, hook::add_virial> || requires { requires Signature<decltype(&U::add_virial), void(double)>; },
                "an effect declares hook::add_virial but has no void add_virial(double w)");
  static_assert(!kDeclares<U, hook::add_collision_stress> ||
                    requires { requires Signature<decltype(&U::add_collision_stress), void(const V&, double)>; },
                "an effect declares hook::add_collision_stress but has no "
                "void add_collision_stress(const Vec<D>& r, double w)");
  static_assert(!kDeclares<U, hook::folds> ||
                    requires(U& u, const U& cu, const gg::Box<D>& box) {
                      { u.wrap_near(u32{}, 0, 0.0, box) } -> std::same_as<double>;
                      { u.wrap(u32{}, 0, 0.0, box) } -> std::same_as<double>;
                      { cu.image(u32{}) } -> std::same_as<Image>;
                      { u.count(u32{}) } -> std::same_as<Image*>;
                    },
                "an effect declares hook::folds but lacks double wrap_near(i, k, x, box), double wrap(i, k, x, box), "
                "Image<D> image(i) const or Image<D>* count(i)");
  static_assert(!kDeclares<U, hook::timed> ||
                    requires(U& u, const U& cu, V& v) {
                      { cu.next_time() } -> std::same_as<double>;
                      { u.pair() } -> std::same_as<std::pair<u32, u32>>;
                      requires Signature<decltype(&U::kick), void(V&, V&)>;
                    },
                "an effect declares hook::timed but lacks double next_time() const, "
                "std::pair<std::uint32_t, std::uint32_t> pair() or void kick(Vec<D>& va, Vec<D>& vb)");
  static_assert(!kDeclares<U, hook::prefetch> || requires { requires Signature<decltype(&U::prefetch), void(u32)>; },
                "an effect declares hook::prefetch but has no void prefetch(std::uint32_t i) const");
  static_assert(!kDeclares<U, hook::save> || requires { requires Signature<decltype(&U::save), void(const EffectSink&)>; },
                "an effect declares hook::save but has no void save(const EffectSink&) const");
  static_assert(!kDeclares<U, hook::observables> || requires(U& u, const ObservableSink& out, const Sample& at) {
    u.observables(out);
  } || requires(U& u, const ObservableSink& out, const Sample& at) { u.observables(out, at); },
                "an effect declares hook::observables but has no "
                "void observables(const ObservableSink&) or observables(const ObservableSink&, const Sample&)");
  static_assert(!kDeclares<U, hook::frame_values> ||
                    requires {
                      requires Signature<decltype(&U::frame_fields), std::vector<FrameField>()>;
                      requires Signature<decltype(&U::frame_values), void(const FrameSink&)>;
                    },
                "an effect declares hook::frame_values but lacks std::vector<FrameField> frame_fields() const or "
                "void frame_values(const FrameSink&) const");
  static_assert(!kDeclares<U, hook::fixed_values> ||
                    requires { requires Signature<decltype(&U::fixed_values), void(const FrameSink&)>; },
                "an effect declares hook::fixed_values but has no void fixed_values(const FrameSink&) const");
  static_assert(!kDeclares<U, hook::sizes> ||
                    requires {
                      requires Signature<decltype(&U::mass), double(u32)>;
                      requires Signature<decltype(&U::radius), double(u32)>;
                      requires Signature<decltype(&U::radius_cap), double()>;
                      requires Signature<decltype(&U::set_size), void(u32, double, double)>;
                      requires Signature<decltype(&U::set_radius_cap), void(double)>;
                    },
                "an effect declares hook::sizes but lacks double mass(std::uint32_t i) const, double "
                "radius(std::uint32_t i) const, double radius_cap() const, void set_size(std::uint32_t i, double m, "
                "double r) or void set_radius_cap(double)");
  static_assert(!kDeclares<U, hook::compact> ||
                    requires { requires Signature<decltype(&U::compact), void(const std::vector<u32>&)>; },
                "an effect declares hook::compact but has no void compact(const std::vector<std::uint32_t>& kept)");
  // A member named as a hook is declared: else it would never be asked.
  static_assert(kDeclares<U, hook::restitution> || !requires { &U::restitution; },
                "an effect has restitution() but does not declare hook::restitution in its kHooks");
  static_assert(kDeclares<U, hook::after_impulse> || !requires { &U::after_impulse; },
                "an effect has after_impulse() but does not declare hook::after_impulse in its kHooks");
  static_assert(kDeclares<U, hook::add_virial> || !requires { &U::add_virial; },
                "an effect has add_virial() but does not declare hook::add_virial in its kHooks");
  static_assert(kDeclares<U, hook::add_collision_stress> || !requires { &U::add_collision_stress; },
                "an effect has add_collision_stress() but does not declare hook::add_collision_stress in its kHooks");
  static_assert(kDeclares<U, hook::timed> || !requires { &U::next_time; },
                "an effect has next_time() but does not declare hook::timed in its kHooks");
  static_assert(kDeclares<U, hook::prefetch> || !requires { &U::prefetch; },
                "an effect has prefetch() but does not declare hook::prefetch in its kHooks");
  static_assert(kDeclares<U, hook::save> || !requires { &U::save; },
                "an effect has save() but does not declare hook::save in its kHooks");
  static_assert(kDeclares<U, hook::frame_values> || !requires { &U::frame_values; },
                "an effect has frame_values() but does not declare hook::frame_values in its kHooks");
  static_assert(kDeclares<U, hook::fixed_values> || !requires { &U::fixed_values; },
                "an effect has fixed_values() but does not declare hook::fixed_values in its kHooks");
  static_assert(kDeclares<U, hook::observables> || !requires { &U::observables; },
                "an effect has observables() but does not declare hook::observables in its kHooks");
  static_assert(kDeclares<U, hook::folds> || !requires { &U::wrap_near; },
                "an effect has wrap_near() but does not declare hook::folds in its kHooks");
  static_assert(kDeclares<U, hook::sizes> || !requires { &U::radius_cap; },
                "an effect has radius_cap() but does not declare hook::sizes in its kHooks");
  static_assert(kDeclares<U, hook::compact> || !requires { &U::compact; },
                "an effect has compact() but does not declare hook::compact in its kHooks");
  return true;
}

}  // namespace ggsim
