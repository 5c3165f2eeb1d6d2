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
#include <filesystem>
#include <utility>
#include <vector>

#include "engine_harness.hpp"
#include "ggsim/effects/effect_set.hpp"
#include "ggsim/engine.hpp"
#include "ggsim/permutation.hpp"
#include "ggsim/recorder.hpp"

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

// Each particle's number in the start, kept through the engine's renumbering, as a per-particle
// field of the snapshots; a second field goes with the velocities only.
class StartNumber {
 public:
  template <class Parameters>
  StartNumber(const Parameters&, const ggsim::EffectStart& s) : number_(s.n) {
    for (std::uint32_t i = 0; i < s.n; ++i) number_[i] = s.start_number(i);
  }
  template <class Rank>
  void permute(const Rank& rank) { ggsim::permute_by_rank(number_, rank); }
  std::vector<ggsim::FrameField> frame_fields() const {
    return {{.name = "number", .unit = "1"}, {.name = "twice_number", .components = 2, .unit = "1", .with_velocities = true}};
  }
  void frame_values(const ggsim::FrameSink& out) const {
    out("number", number_);
    std::vector<double> twice;
    for (double x : number_) twice.insert(twice.end(), {x, x});
    out("twice_number", twice);
  }
  const std::vector<double>& numbers() const { return number_; }

 private:
  std::vector<double> number_;
};

// The effects of a scene, as engine_variants.hpp composes the library's.
template <class... Units>
struct TestEffects {
  static constexpr bool kAggregate = false;
  using Motion = ggsim::FreeFlight;
  template <int D>
  using Boundary = ggsim::PeriodicBoundary<D>;
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

// The recorder writes an effect's field by the number in the start, whatever order the engine
// keeps its particles in (it renumbers them in space as they move), and keeps a field that goes
// with the velocities only when the velocities are kept.
TEST(EffectSet, ANewEffectsFieldGoesWithTheSnapshotsByTheNumberInTheStart) {
  auto s = ggtest::random_start<2>(40, 0.3, 6);
  ggsim::EngineParameters par;
  ggsim::Engine<2, TestEffects<StartNumber>> eng(s.box, s.r, s.v, par);
  ggsim::SimConfig cfg;
  cfg.output = (std::filesystem::temp_directory_path() / "gg_effect_field_test.h5").string();
  cfg.snapshots = {1.0, 30.0};  // ~40 collisions per particle: renumbered at 16 events each
  cfg.t_max = 30;
  const std::size_t n = s.r.size();
  ggsim::Recorder rec(cfg, n, 2, {40, 40}, nullptr, 0, {}, eng.effects().frame_fields());
  eng.run(cfg.t_max, ~0ull, rec);
  const std::vector<double>& in_engine_order = eng.effects().get<StartNumber>().numbers();
  std::size_t moved = 0;
  for (std::uint32_t i = 0; i < n; ++i) moved += in_engine_order[i] != i;
  ASSERT_GT(moved, n / 2);  // the engine has renumbered its particles

  const ggsim::SnapshotStore& snaps = rec.snapshots();
  ASSERT_EQ(snaps.more_fields().size(), 1u);  // no velocities, so no twice_number
  EXPECT_EQ(snaps.more_fields()[0].name, "number");
  ASSERT_EQ(snaps.index().frames(), 2u);
  std::vector<double> frame(n);
  for (std::size_t k = 0; k < 2; ++k) {
    snaps.more(0)(k, frame.data());
    for (std::uint32_t i = 0; i < n; ++i) ASSERT_EQ(frame[i], i) << "frame " << k;
  }
}
