// The composition of effects (effects/effect_set.hpp; docs/DESIGN.md "Where an effect lives"): an
// effect the library does not have, written here as a test would write a new one, runs in the
// unchanged engine through the questions the engine asks every effect. A collision effect makes
// every collision elastic; a timed effect swaps the velocities of two particles at times of its
// own. Both keep the kinetic energy and the momentum exactly (paper eqs. (6)-(7) at e = 1; a swap
// permutes velocities), so an engine that failed to ask them would lose energy, miss or misplace
// a swap, or let particles overlap.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <utility>

#include "engine_harness.hpp"
#include "ggsim/effects/effect_set.hpp"
#include "ggsim/engine.hpp"

namespace {

// Every collision elastic, whatever the scene's e.
class AlwaysElastic {
 public:
  template <class Parameters>
  AlwaysElastic(const Parameters&, const ggsim::EffectStart&) {}
  void restitution(double& e, double, std::uint32_t, std::uint32_t, double) { e = 1; }
};

// Every `period` from t = period on, the velocities of particles k and k + 1 (k = 0, 1, ... in
// turn) swap; counts its acts.
template <int D>
class VelocitySwap {
 public:
  template <class Parameters>
  VelocitySwap(const Parameters&, const ggsim::EffectStart& s) : n_(static_cast<std::uint32_t>(s.n)), next_(kPeriod) {}
  double next_time() const { return next_; }
  std::pair<std::uint32_t, std::uint32_t> pair() const { return {k_ % (n_ - 1), k_ % (n_ - 1) + 1}; }
  void kick(ggsim::Vec<D>& va, ggsim::Vec<D>& vb) {
    std::swap(va, vb);
    ++k_;
    next_ = kPeriod * static_cast<double>(k_ + 1);
  }
  std::uint64_t acts() const { return k_; }
  static constexpr double kPeriod = 0.01;

 private:
  std::uint32_t n_;
  std::uint64_t k_ = 0;
  double next_;
};

// The effects of a scene, as engine_variants.hpp composes the library's.
template <class... Units>
struct TestEffects {
  static constexpr bool kAggregate = false;
  template <int D>
  using Set = ggsim::EffectSet<D, Units...>;
};

}  // namespace

TEST(EffectSet, ANewCollisionEffectIsAskedAtEveryCollision) {
  auto s = ggtest::random_start<2>(60, 0.3, 4);
  ggsim::EngineParameters par;
  par.rule.e = 0.5;  // an inelastic scene: without the effect, energy would go
  ggsim::Engine<2, TestEffects<AlwaysElastic>> eng(s.box, s.r, s.v, par);
  const double E0 = eng.kinetic_energy();
  ggtest::Silent none;
  eng.run(ggsim::kNever, 20 * s.r.size(), none);
  ASSERT_EQ(eng.collisions(), 20 * s.r.size());
  ggtest::expect_elastic_invariants(eng, E0, 1e-12);
}

TEST(EffectSet, ANewTimedEffectActsAtItsTimesBetweenEvents) {
  auto s = ggtest::random_start<2>(60, 0.3, 5);
  ggsim::EngineParameters par;
  ggsim::Engine<2, TestEffects<VelocitySwap<2>>> eng(s.box, s.r, s.v, par);
  const double E0 = eng.kinetic_energy();
  ggtest::Silent none;
  const double t_end = 2.005;
  eng.run(t_end, ~0ull, none);
  const auto& swap = eng.effects().get<VelocitySwap<2>>();
  EXPECT_EQ(swap.acts(), 200u);  // at 0.01, 0.02, ..., 2.00
  EXPECT_GT(swap.next_time(), t_end);
  ggtest::expect_elastic_invariants(eng, E0, 1e-12);
}
