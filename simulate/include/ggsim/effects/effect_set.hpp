#pragma once
// The effects a scene calls for, composed at compile time (docs/DESIGN.md "Effects"). Each effect
// is a class of its own in this directory that owns its parameters, its per-particle state, what
// it adds to a collision, what it adds to the outputs and its part of a checkpoint. The engine
// holds an EffectSet and asks it at fixed points of its loop; the set passes each question to the
// effects that declare they answer it (their kHooks, hooks.hpp, checked there) and to no other, so
// an effect a scene does not compile in costs nothing (as the pair evaluators of HOOMD-blue are
// composed). The questions, each optional for an effect, with the hook that declares it:
//
//   restitution(e, n.v_ij, i, j, t)   sets a collision's restitution (a law of the impact speed) or
//                                     makes it elastic (the cutoff, the TC model)
//   after_impulse(v_i, v_j, i, j, n)  adds to a collision's impulse (rough particles)
//   add_virial(w)                     wants r_ij . Delta p_i of every collision (the pressure)
//   add_collision_stress(r_ij, w)     wants Delta p_i = w r_ij of every collision (the pressure tensor)
//   wrap_near(i, k, x, box), wrap()   counts the folds of positions into the box (image counts)
//   image(i)                          and gives them
//   next_time(), pair(), kick(v_i, v_j)
//                                     acts on a pair of particles at its own times (the drive)
//   prefetch(i)                       reads per-particle data in a collision (the look-ahead asks)
//   permute(rank)                     per-particle arrays follow the engine's renumbering
//   save(sink)                        its state in a checkpoint (read back by its constructor)
//   observables(sink[, sample])       its observables at a sample time, if the scene uses it
//   frame_fields(), frame_values(sink)
//                                     its per-particle fields of a snapshot, if the scene uses it
//   fixed_values(sink)                its per-particle values fixed in time (a mixture's species), for
//                                     the output at the end of a run
//   mass(i), radius(i), radius_cap()  a radius and a mass per particle (a mixture's, aggregates'),
//   set_size(i, m, r), set_radius_cap(c)
//                                     which the search, the cells, the collision and the kinetic
//                                     energy read and a merge changes; without them 1/2 and 1
//   compact(kept)                     per-particle arrays keep only the particles kept (a merging
//                                     contact drops those merged away)
//
// Adding an effect is a class here and its entry in the registry (registry.hpp; docs/DESIGN.md
// "Where an effect lives"): the event loop does not change. An engine variant is the set of the
// registered effects it holds (EngineVariant, Effects below).
#include <algorithm>
#include <cstdint>
#include <string>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include "gg/box.hpp"
#include "ggsim/boundary/periodic.hpp"
#include "ggsim/contact/bounce.hpp"
#include "ggsim/effects/effect_state.hpp"
#include "ggsim/effects/hooks.hpp"
#include "ggsim/effects/registry.hpp"
#include "ggsim/hot_path.hpp"
#include "ggsim/motion/free_flight.hpp"
#include "ggsim/prediction.hpp"

namespace ggsim {


// The first of the effects that declares hook H, void if none does.
template <Hooks H, class... Units>
struct FirstDeclaring {
  using type = void;
};
template <Hooks H, class U, class... Rest>
struct FirstDeclaring<H, U, Rest...> {
  using type = std::conditional_t<kDeclares<U, H>, U, typename FirstDeclaring<H, Rest...>::type>;
};

template <int D, EffectUnit... Units>
class EffectSet {
  static_assert((hooks_checked<Units, D>() && ...));

 public:
  template <class Parameters>
  EffectSet(const Parameters& par, const EffectStart& s) : units_(Units(par, s)...) {}

  // Whether particles have sizes, whether an effect acts at times of its own, whether one counts
  // the folds into the box: compile-time answers, so that without them no code is left.
  using Sizes = typename FirstDeclaring<hook::sizes, Units...>::type;  // at most one effect gives sizes
  static constexpr bool kSizes = !std::is_void_v<Sizes>;
  static_assert((0 + ... + kDeclares<Units, hook::sizes>) <= 1, "two effects of a set give particles sizes");
  static constexpr bool kTimed = (kDeclares<Units, hook::timed> || ...);
  using FoldCounter = typename FirstDeclaring<hook::folds, Units...>::type;  // at most one effect counts folds
  static constexpr bool kCountsFolds = !std::is_void_v<FoldCounter>;

  template <class U>
  static constexpr bool kHas = (std::is_same_v<U, Units> || ...);
  // The effect U (tests and benchmarks read an effect's state here).
  template <class U>
  U& get() { return std::get<U>(units_); }
  template <class U>
  const U& get() const { return std::get<U>(units_); }
  // The effect U, or nullptr if the set does not hold it.
  template <class U>
  U* find() {
    if constexpr (kHas<U>) return &get<U>();
    return nullptr;
  }
  template <class U>
  const U* find() const {
    if constexpr (kHas<U>) return &get<U>();
    return nullptr;
  }
  // Particle i's mass and radius, by the effect that gives sizes if there is one (at most one),
  // else 1 and 1/2 (constants: the plain engine's arithmetic).
  GG_ALWAYS_INLINE double mass(std::uint32_t i) const {
    if constexpr (kSizes) return get<Sizes>().mass(i);
    else return (void)i, 1.0;
  }
  GG_ALWAYS_INLINE double radius(std::uint32_t i) const {
    if constexpr (kSizes) return get<Sizes>().radius(i);
    else return (void)i, 0.5;
  }
  // The squared contact distance of particles i and j, (R_i + R_j)^2: exactly 1 for two of radius 1/2.
  GG_ALWAYS_INLINE double contact2(std::uint32_t i, std::uint32_t j) const {
    const double d = radius(i) + radius(j);
    return d * d;
  }
  // No radius exceeds it (1/2 without sizes), and the largest contact distance a search allows for.
  double radius_cap() const {
    if constexpr (kSizes) return get<Sizes>().radius_cap();
    else return 0.5;
  }
  double diameter_cap() const { return 2 * radius_cap(); }
  // A merge changes particle i's size and may raise the cap (a merging contact's; it needs sizes).
  void set_size(std::uint32_t i, double m, double r) { get<Sizes>().set_size(i, m, r); }
  void set_radius_cap(double cap) { get<Sizes>().set_radius_cap(cap); }
  // The particles `kept` (ascending) are renumbered 0, 1, ..., the others dropped.
  void compact(const std::vector<std::uint32_t>& kept) {
    each([&](auto& u) {
      if constexpr (kDeclares<std::decay_t<decltype(u)>, hook::compact>) u.compact(kept);
    });
  }

  GG_ALWAYS_INLINE void prefetch(std::uint32_t i) const {
    each([&](const auto& u) {
      if constexpr (kDeclares<std::decay_t<decltype(u)>, hook::prefetch>) u.prefetch(i);
    });
  }
  template <class Rank>
  void permute(const Rank& rank) {
    each([&](auto& u) {
      if constexpr (kDeclares<std::decay_t<decltype(u)>, hook::permute>) {
        static_assert(requires { u.permute(rank); }, "an effect declares hook::permute but has no void permute(const Rank& rank)");
        u.permute(rank);
      }
    });
  }
  GG_ALWAYS_INLINE void restitution(double& e, double vn, std::uint32_t ia, std::uint32_t ib, double t) {
    each([&](auto& u) {
      if constexpr (kDeclares<std::decay_t<decltype(u)>, hook::restitution>) u.restitution(e, vn, ia, ib, t);
    });
  }
  GG_ALWAYS_INLINE void after_impulse(Vec<D>& va, Vec<D>& vb, std::uint32_t ia, std::uint32_t ib, const Vec<D>& n) {
    each([&](auto& u) {
      if constexpr (kDeclares<std::decay_t<decltype(u)>, hook::after_impulse>) u.after_impulse(va, vb, ia, ib, n);
    });
  }
  GG_ALWAYS_INLINE void add_virial(double w) {
    each([&](auto& u) {
      if constexpr (kDeclares<std::decay_t<decltype(u)>, hook::add_virial>) u.add_virial(w);
    });
  }
  GG_ALWAYS_INLINE void add_collision_stress(const Vec<D>& r, double w) {
    each([&](auto& u) {
      if constexpr (kDeclares<std::decay_t<decltype(u)>, hook::add_collision_stress>) u.add_collision_stress(r, w);
    });
  }
  // Coordinate k of particle i folded into the box, from less than one edge outside (wrap_near)
  // or from anywhere (wrap), by the effect that counts the folds if there is one (at most one).
  GG_ALWAYS_INLINE double wrap_near(std::uint32_t i, int k, double x, const gg::Box<D>& box) {
    if constexpr (kCountsFolds) return get<FoldCounter>().wrap_near(i, k, x, box);
    else return (void)i, box.wrap_near(x, k);
  }
  double wrap(std::uint32_t i, int k, double x, const gg::Box<D>& box) {
    if constexpr (kCountsFolds) return get<FoldCounter>().wrap(i, k, x, box);
    else return (void)i, box.wrap(x, k);
  }
  // Particle i's count of folds, for a boundary that moves it between images itself (a sheared
  // box's fold, boundary/sheared.hpp), or nullptr if no effect counts folds.
  auto image_count(std::uint32_t i) {
    if constexpr (kCountsFolds) return get<FoldCounter>().count(i);
    else return (void)i, nullptr;
  }
  // Particle i's periodic image (0 if no effect counts folds).
  Image<D> image(std::uint32_t i) const {
    if constexpr (kCountsFolds) return get<FoldCounter>().image(i);
    else return (void)i, Image<D>{};
  }

  // The time of the earliest act of a timed effect (kNever if none).
  double next_time() const {
    double t = kNever;
    each([&](const auto& u) {
      if constexpr (kDeclares<std::decay_t<decltype(u)>, hook::timed>) t = std::min(t, u.next_time());
    });
    return t;
  }
  // The timed effect due first (the first of equals) acts: act(effect) with it.
  template <class Act>
  bool act_first_due(Act&& act) {
    const double t = next_time();
    bool done = false, acted = false;
    each([&](auto& u) {
      if constexpr (kDeclares<std::decay_t<decltype(u)>, hook::timed>)
        if (!acted && u.next_time() == t) acted = true, done = act(u);
    });
    return done;
  }

  void observables(const ObservableSink& out, const Sample& at) {
    each([&](auto& u) {
      if constexpr (!kDeclares<std::decay_t<decltype(u)>, hook::observables>) return;
      else if constexpr (requires { u.observables(out, at); }) u.observables(out, at);
      else u.observables(out);
    });
  }

  std::vector<FrameField> frame_fields() const {
    std::vector<FrameField> fields;
    each([&](const auto& u) {
      if constexpr (kDeclares<std::decay_t<decltype(u)>, hook::frame_values>)
        for (FrameField& f : u.frame_fields()) fields.push_back(std::move(f));
    });
    return fields;
  }
  void frame_values(const FrameSink& out) const {
    each([&](const auto& u) {
      if constexpr (kDeclares<std::decay_t<decltype(u)>, hook::frame_values>) u.frame_values(out);
    });
  }

  void fixed_values(const FrameSink& out) const {
    each([&](const auto& u) {
      if constexpr (kDeclares<std::decay_t<decltype(u)>, hook::fixed_values>) u.fixed_values(out);
    });
  }

  void save(const EffectSink& out) const {
    each([&](const auto& u) {
      if constexpr (kDeclares<std::decay_t<decltype(u)>, hook::save>) u.save(out);
    });
  }

 private:
  template <class F>
  GG_ALWAYS_INLINE void each(F&& f) {
    std::apply([&](auto&... u) { (f(u), ...); }, units_);
  }
  template <class F>
  GG_ALWAYS_INLINE void each(F&& f) const {
    std::apply([&](const auto&... u) { (f(u), ...); }, units_);
  }

  std::tuple<Units...> units_;
};

namespace effects_detail {

template <class E, class List>
struct IndexOf;
template <class E, class... Rest>
struct IndexOf<E, EffectList<E, Rest...>> {
  static constexpr unsigned value = 0;
};
template <class E, class First, class... Rest>
struct IndexOf<E, EffectList<First, Rest...>> {
  static constexpr unsigned value = 1 + IndexOf<E, EffectList<Rest...>>::value;
};

// What an entry changes in the engine (registry_entry.hpp), void where it changes nothing.
template <class E>
struct MotionOf {
  using type = void;
};
template <class E>
  requires requires { typename E::Motion; }
struct MotionOf<E> {
  using type = typename E::Motion;
};
template <class E, int D>
struct BoundaryOf {
  using type = void;
};
template <class E, int D>
  requires requires { typename E::template Boundary<D>; }
struct BoundaryOf<E, D> {
  using type = typename E::template Boundary<D>;
};
template <class E, int D, class Engine>
struct ContactOf {
  using type = void;
};
template <class E, int D, class Engine>
  requires requires { typename E::template Contact<D, Engine>; }
struct ContactOf<E, D, Engine> {
  using type = typename E::template Contact<D, Engine>;
};

// The first of Types that is not void, Default if all are.
template <class Default, class... Types>
struct FirstOr {
  using type = Default;
};
template <class Default, class T, class... Rest>
struct FirstOr<Default, T, Rest...> {
  using type = std::conditional_t<std::is_void_v<T>, typename FirstOr<Default, Rest...>::type, T>;
};

// The entries of the registry whose bits are in Key, in the registry's order.
template <unsigned Key, class List>
struct Selected;
template <unsigned Key, class... E>
struct Selected<Key, EffectList<E...>> {
  template <class Entry>
  using If = std::conditional_t<((Key >> IndexOf<Entry, Registry>::value) & 1u) != 0, std::tuple<Entry>, std::tuple<>>;
  using type = decltype(std::tuple_cat(std::declval<If<E>>()...));
};

}  // namespace effects_detail

// The bit of the effect E in the key of an engine variant: its place in the registry.
template <class E>
inline constexpr unsigned kBit = 1u << effects_detail::IndexOf<E, Registry>::value;
// Whether a variant must hold E exactly when a scene asks for it (registry_entry.hpp).
template <class E>
inline constexpr bool kExact = !std::is_void_v<typename effects_detail::MotionOf<E>::type> ||
                               !std::is_void_v<typename effects_detail::BoundaryOf<E, 2>::type> ||
                               !std::is_void_v<typename effects_detail::ContactOf<E, 2, void>::type>;

namespace effects_detail {
template <class... E>
constexpr unsigned count(EffectList<E...>) {
  return sizeof...(E);
}
template <class... E>
constexpr unsigned exact_bits(EffectList<E...>) {
  return (0u | ... | (kExact<E> ? kBit<E> : 0u));
}
// The bit of the registered effect `name`, 0 if none has it.
template <class... E>
constexpr unsigned bit_named(std::string_view name, EffectList<E...>) {
  return (0u | ... | (E::kName == name ? kBit<E> : 0u));
}
}  // namespace effects_detail

// The bits of the effects that must be matched exactly.
inline constexpr unsigned kExactBits = effects_detail::exact_bits(Registry{});

// The key of the effects named by their words joined with "+" ("tc+virial"; "plain": none), and in
// `unknown` the first word no registered effect has (left empty if there is none).
constexpr unsigned effects_named(std::string_view name, std::string_view& unknown) {
  if (name == "plain") return 0u;
  unsigned key = 0;
  while (!name.empty()) {
    const std::size_t plus = name.find('+');
    const unsigned bit = effects_detail::bit_named(name.substr(0, plus), Registry{});
    if (bit == 0 && unknown.empty()) unknown = name.substr(0, plus);
    key |= bit;
    name = plus == std::string_view::npos ? std::string_view{} : name.substr(plus + 1);
  }
  return key;
}

// The words of the effects of `key` joined with "+" in the registry's order ("plain": none), as
// effects_named() reads them (a checkpoint records its engine's effects so).
inline std::string effect_words(unsigned key) {
  std::string words;
  const auto add = [&](unsigned bit, std::string_view name) {
    if ((key & bit) != 0) words.append(words.empty() ? "" : "+").append(name);
  };
  [&]<class... E>(EffectList<E...>) { (add(kBit<E>, E::kName), ...); }(Registry{});
  return words.empty() ? "plain" : words;
}

// The key of the variant named by its effects' words, as effects_named() reads them, or "all": every
// effect that is not exact; as simulate/CMakeLists.txt names the variants it compiles. A word no
// effect has is not a constant expression: the variant's translation unit does not compile.
consteval unsigned variant_key(std::string_view name) {
  if (name == "all") return ((1u << effects_detail::count(Registry{})) - 1) & ~kExactBits;
  std::string_view unknown;
  const unsigned key = effects_named(name, unknown);
  if (!unknown.empty()) throw "an engine variant names an effect the registry does not have (effects/registry.hpp)";
  return key;
}

namespace effects_detail {
// What the effects E change and hold: the motion, boundary and contact of the exact one among
// them, else the plain engine's, and their units.
template <class Entries>
struct Compose;
template <class... E>
struct Compose<std::tuple<E...>> {
  using Motion = typename FirstOr<FreeFlight, typename MotionOf<E>::type...>::type;
  template <int D>
  using Boundary = typename FirstOr<PeriodicBoundary<D>, typename BoundaryOf<E, D>::type...>::type;
  template <int D, class Engine>
  using Contact = typename FirstOr<Bounce, typename ContactOf<E, D, Engine>::type...>::type;
  template <int D>
  using Set = EffectSet<D, typename E::template Unit<D>...>;
};
}  // namespace effects_detail

// The engine variant of the effects whose bits are in Key (engine.hpp reads its Motion,
// Boundary<D>, Contact<D, Engine> and Set<D>).
template <unsigned Key>
struct EngineVariant : effects_detail::Compose<typename effects_detail::Selected<Key, Registry>::type> {
  static constexpr unsigned kKey = Key;
};

// The engine variant of the effects E (entries of the registry; none: the plain engine), in any order.
template <class... E>
using Effects = EngineVariant<(0u | ... | kBit<E>)>;

}  // namespace ggsim
