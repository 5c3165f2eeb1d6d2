#pragma once
// The effects a scene calls for, composed at compile time (docs/DESIGN.md "Effects"). Each effect
// is a class of its own in this directory that owns its parameters, its per-particle state, what
// it adds to a collision, what it adds to the outputs and its part of a checkpoint. The engine
// holds an EffectSet and asks it at fixed points of its loop; the set passes each question to the
// effects that answer it and to no other, so an effect a scene does not compile in costs nothing
// (as the pair evaluators of HOOMD-blue are composed). The questions, each optional for an effect:
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
//   time_to_wall(q), hit(q)           walls: when particle q next meets one, and what the meeting does
//   prefetch(i)                       reads per-particle data in a collision (the look-ahead asks)
//   permute(rank)                     per-particle arrays follow the engine's renumbering
//   save(sink)                        its state in a checkpoint (read back by its constructor)
//   observables(sink[, sample])       its observables at a sample time, if the scene uses it
//   frame_fields(), frame_values(sink)
//                                     its per-particle fields of a snapshot, if the scene uses it
//   kSizes                            a radius and a mass per particle (ParticleSizes)
//
// Adding an effect is a class here and a bit of the key below (docs/DESIGN.md "Where an effect
// lives"): the event loop does not change.
#include <algorithm>
#include <cstdint>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include "gg/box.hpp"
#include "ggsim/aggregation.hpp"
#include "ggsim/boundary.hpp"
#include "ggsim/contact.hpp"
#include "ggsim/effects/effect_state.hpp"
#include "ggsim/effects/image_counts.hpp"
#include "ggsim/effects/particle_sizes.hpp"
#include "ggsim/effects/pressure_virial.hpp"
#include "ggsim/effects/rough_particles.hpp"
#include "ggsim/effects/shear_stress.hpp"
#include "ggsim/effects/tc_model.hpp"
#include "ggsim/effects/velocity_cutoff.hpp"
#include "ggsim/effects/viscoelastic_restitution.hpp"
#include "ggsim/effects/walls.hpp"
#include "ggsim/effects/white_noise_drive.hpp"
#include "ggsim/hot_path.hpp"
#include "ggsim/motion.hpp"
#include "ggsim/prediction.hpp"

namespace ggsim {

template <class U>
concept HoldsSizes = requires { U::kSizes; };
template <class U>
concept Timed = requires(const U& u) { u.next_time(); };
template <class U>
concept HasWalls = requires { &U::time_to_wall; };
template <class U>
concept CountsFolds = requires(const U& u) { u.image(0u); };

// The first of the effects that counts the folds into the box, void if none does.
template <class... Units>
struct FoldCounterOf {
  using type = void;
};
template <class U, class... Rest>
struct FoldCounterOf<U, Rest...> {
  using type = std::conditional_t<CountsFolds<U>, U, typename FoldCounterOf<Rest...>::type>;
};

template <int D, class... Units>
class EffectSet {
 public:
  template <class Parameters>
  EffectSet(const Parameters& par, const EffectStart& s) : units_(Units(par, s)...) {}

  // Whether particles have sizes, whether an effect acts at times of its own, whether one counts
  // the folds into the box: compile-time answers, so that without them no code is left.
  static constexpr bool kSizes = (HoldsSizes<Units> || ...);
  static constexpr bool kTimed = (Timed<Units> || ...);
  using FoldCounter = typename FoldCounterOf<Units...>::type;  // at most one effect counts folds
  static constexpr bool kCountsFolds = !std::is_void_v<FoldCounter>;
  static constexpr bool kWalls = (HasWalls<Units> || ...);

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
  ParticleSizes& sizes() { return get<ParticleSizes>(); }
  const ParticleSizes& sizes() const { return get<ParticleSizes>(); }

  GG_ALWAYS_INLINE void prefetch(std::uint32_t i) const {
    each([&](const auto& u) {
      if constexpr (requires { u.prefetch(i); }) u.prefetch(i);
    });
  }
  template <class Rank>
  void permute(const Rank& rank) {
    each([&](auto& u) {
      if constexpr (requires { u.permute(rank); }) u.permute(rank);
    });
  }
  GG_ALWAYS_INLINE void restitution(double& e, double vn, std::uint32_t ia, std::uint32_t ib, double t) {
    each([&](auto& u) {
      if constexpr (requires { u.restitution(e, vn, ia, ib, t); }) u.restitution(e, vn, ia, ib, t);
    });
  }
  GG_ALWAYS_INLINE void after_impulse(Vec<D>& va, Vec<D>& vb, std::uint32_t ia, std::uint32_t ib, const Vec<D>& n) {
    each([&](auto& u) {
      if constexpr (requires { u.after_impulse(va, vb, ia, ib, n); }) u.after_impulse(va, vb, ia, ib, n);
    });
  }
  GG_ALWAYS_INLINE void add_virial(double w) {
    each([&](auto& u) {
      if constexpr (requires { u.add_virial(w); }) u.add_virial(w);
    });
  }
  GG_ALWAYS_INLINE void add_collision_stress(const Vec<D>& r, double w) {
    each([&](auto& u) {
      if constexpr (requires { u.add_collision_stress(r, w); }) u.add_collision_stress(r, w);
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
  // box's fold, boundary.hpp), or nullptr if no effect counts folds.
  auto image_count(std::uint32_t i) {
    if constexpr (kCountsFolds) return get<FoldCounter>().count(i);
    else return (void)i, nullptr;
  }
  // Particle i's periodic image (0 if no effect counts folds).
  Image<D> image(std::uint32_t i) const {
    if constexpr (kCountsFolds) return get<FoldCounter>().image(i);
    else return (void)i, Image<D>{};
  }

  // Walls (at most one effect has them): how long after its record particle q meets one, and the
  // meeting.
  double time_to_wall(const Particle<D>& q) const {
    double t = kNever;
    each([&](const auto& u) {
      if constexpr (HasWalls<std::decay_t<decltype(u)>>) t = u.time_to_wall(q);
    });
    return t;
  }
  void hit_wall(Particle<D>& q) {
    each([&](auto& u) {
      if constexpr (HasWalls<std::decay_t<decltype(u)>>) u.hit(q);
    });
  }

  // The time of the earliest act of a timed effect (kNever if none).
  double next_time() const {
    double t = kNever;
    each([&](const auto& u) {
      if constexpr (requires { u.next_time(); }) t = std::min(t, u.next_time());
    });
    return t;
  }
  // The timed effect due first (the first of equals) acts: act(effect) with it.
  template <class Act>
  bool act_first_due(Act&& act) {
    const double t = next_time();
    bool done = false, acted = false;
    each([&](auto& u) {
      if constexpr (requires { u.next_time(); })
        if (!acted && u.next_time() == t) acted = true, done = act(u);
    });
    return done;
  }

  void observables(const ObservableSink& out, const Sample& at) {
    each([&](auto& u) {
      if constexpr (requires { u.observables(out, at); }) u.observables(out, at);
      else if constexpr (requires { u.observables(out); }) u.observables(out);
    });
  }

  std::vector<FrameField> frame_fields() const {
    std::vector<FrameField> fields;
    each([&](const auto& u) {
      if constexpr (requires { u.frame_fields(); })
        for (FrameField& f : u.frame_fields()) fields.push_back(std::move(f));
    });
    return fields;
  }
  void frame_values(const FrameSink& out) const {
    each([&](const auto& u) {
      if constexpr (requires { u.frame_values(out); }) u.frame_values(out);
    });
  }

  void save(const EffectSink& out) const {
    each([&](const auto& u) {
      if constexpr (requires { u.save(out); }) u.save(out);
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
template <int D, class Tuple>
struct SetOf;
template <int D, class... U>
struct SetOf<D, std::tuple<U...>> {
  using type = EffectSet<D, U...>;
};
}  // namespace effects_detail

// Each effect an engine may compile in is a bit of its key, the name of a variant (engine_variants.hpp,
// simulate/CMakeLists.txt: "tc+virial" is kTcBit | kVirialBit). Aggregation is not an effect but
// another kind of collision (the ballistic aggregation model, aggregation.hpp: colliding particles
// merge), which brings the sizes its aggregates need.
enum EffectBit : unsigned {
  kPlain = 0,
  kCutoffBit = 1,
  kTcBit = 2,
  kVirialBit = 4,
  kImagesBit = 8,
  kAggregateBit = 16,
  kDrivenBit = 32,
  kRoughBit = 64,
  kMixtureBit = 128,
  kViscoelasticBit = 256,
  kWallsBit = 512,
  kShearBit = 1024,
};

// The effects of the variant Key, in the order a collision asks them: a restitution law first, so
// that the cutoff and the TC model may still make a collision elastic.
template <unsigned Key>
struct Effects {
  // Every variant but the walls' flies freely (motion.hpp); the walls' falls under gravity (which
  // may be 0). Every box is periodic but the sheared one's (boundary.hpp): walls are events, not a
  // boundary (effects/walls.hpp).
  using Motion = std::conditional_t<(Key & kWallsBit) != 0, UniformGravity, FreeFlight>;
  template <int D>
  using Boundary = std::conditional_t<(Key & kShearBit) != 0, ShearedBoundary<D>, PeriodicBoundary<D>>;
  // Every variant's touching pairs collide but the aggregation model's, which merge (contact.hpp).
  template <int D, class Engine>
  using Contact = std::conditional_t<(Key & kAggregateBit) != 0, Aggregates<D, Engine>, Bounce>;
  template <bool On, class U>
  using If = std::conditional_t<On, std::tuple<U>, std::tuple<>>;
  template <int D>
  using Set = typename effects_detail::SetOf<
      D, decltype(std::tuple_cat(std::declval<If<(Key & kViscoelasticBit) != 0, ViscoelasticRestitution>>(),
                                 std::declval<If<(Key & kCutoffBit) != 0, VelocityCutoff>>(),
                                 std::declval<If<(Key & kTcBit) != 0, TcModel>>(),
                                 std::declval<If<(Key & kRoughBit) != 0, RoughParticles<D>>>(),
                                 std::declval<If<(Key & kVirialBit) != 0, PressureVirial>>(),
                                 std::declval<If<(Key & kImagesBit) != 0, ImageCounts<D>>>(),
                                 std::declval<If<(Key & kDrivenBit) != 0, WhiteNoiseDrive<D>>>(),
                                 std::declval<If<(Key & kWallsBit) != 0, Walls<D>>>(),
                                 std::declval<If<(Key & kShearBit) != 0, ShearStress<D>>>(),
                                 std::declval<If<(Key & (kAggregateBit | kMixtureBit)) != 0, ParticleSizes>>()))>::type;
};

// The ballistic aggregation model: no restitution, no cutoff, no pressure, no images.
using Aggregation = Effects<kAggregateBit>;

}  // namespace ggsim
