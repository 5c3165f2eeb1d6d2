// The composition of effects (effects/effect_set.hpp; docs/DESIGN.md "Where an effect lives"): an
// effect the library does not have, written here as a test would write a new one, runs in the
// unchanged engine through the questions the engine asks every effect. A collision effect makes
// every collision elastic; a timed effect swaps the velocities of two particles at times of its
// own. Both keep the kinetic energy and the momentum exactly (paper eqs. (6)-(7) at e = 1; a swap
// permutes velocities), so an engine that failed to ask them would lose energy, miss or misplace
// a swap, or let particles overlap. A fourth effect comes with its scene part, as a new effect of
// the library does (docs/DESIGN.md "Where an effect lives"): its option reaches its class through
// the scene's parameters, and its count goes into a checkpoint and the output.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <utility>
#include <vector>

#include "engine_harness.hpp"
#include "gg/cli.hpp"
#include "gg/errors.hpp"
#include "gg/h5file.hpp"
#include "ggsim/checkpoint.hpp"
#include "ggsim/cli_scene_options.hpp"
#include "ggsim/effects/effect_set.hpp"
#include "ggsim/engine.hpp"
#include "ggsim/permutation.hpp"
#include "ggsim/recorder.hpp"
#include "ggsim/scene_effect.hpp"

namespace {

// Every collision elastic, whatever the scene's e.
class AlwaysElastic {
 public:
  static constexpr ggsim::Hooks kHooks = ggsim::hook::restitution;
  template <class Parameters>
  AlwaysElastic(const Parameters&, const ggsim::EffectStart&) {}
  void restitution(double& e, double, std::uint32_t, std::uint32_t, double) { e = 1; }
};

// Every `period` from t = period on, the velocities of particles k and k + 1 (k = 0, 1, ... in
// turn) swap; counts its acts.
template <int D>
class VelocitySwap {
 public:
  static constexpr ggsim::Hooks kHooks = ggsim::hook::timed;
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
  static constexpr ggsim::Hooks kHooks = ggsim::hook::permute | ggsim::hook::frame_values;
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

// A collision slower than --elastic-below is elastic (a cutoff of the test's own), and the effect
// counts them: an observable, and state a checkpoint keeps.
struct ElasticBelowParameters {
  double speed = 0;
};

class ElasticBelow {
 public:
  static constexpr ggsim::Hooks kHooks = ggsim::hook::restitution | ggsim::hook::observables | ggsim::hook::save;
  template <class Parameters>
  ElasticBelow(const Parameters& par, const ggsim::EffectStart& s)
      : speed_(ggsim::effect_parameters<ElasticBelowParameters>(par).speed) {
    if (!s.records) return;
    if (const auto saved = s.records->take_all_integer(kRecord); !saved.empty()) count_ = saved.at(0);
  }
  void restitution(double& e, double vn, std::uint32_t, std::uint32_t, double) {
    if (std::abs(vn) < speed_) e = 1, ++count_;
  }
  void observables(const ggsim::ObservableSink& out) const { out(kRecord, "1", static_cast<double>(count_)); }
  void save(const ggsim::EffectSink& out) const { out.integer(kRecord, {count_}); }
  std::int64_t count() const { return count_; }

 private:
  static constexpr const char* kRecord = "elastic_below";
  double speed_;
  std::int64_t count_ = 0;
};

// Its part of a scene: the option, its check, its key (for the fingerprint and /parameters) and whether it is used.
class ElasticBelowScene final : public ggsim::SceneEffect {
 public:
  void add_options(ggsim::SceneOptions& options, ggsim::SimConfig& c) const override {
    options.number("--elastic-below", c.effects.set<ElasticBelowParameters>().speed, "elastic below this speed");
  }
  std::string option() const override { return "--elastic-below"; }
  void check(ggsim::SimConfig& c) const override {
    if (speed(c) < 0) throw gg::UsageError("--elastic-below must be >= 0");
  }
  std::vector<ggsim::SceneKey> keys() const override {
    return {ggsim::scene_key("elastic_below", &ElasticBelowParameters::speed, "0")};
  }
  bool used(const ggsim::SimConfig& c) const override { return speed(c) > 0; }

 private:
  static double speed(const ggsim::SimConfig& c) { return c.effects.get<ElasticBelowParameters>().speed; }
};

// The effects of a scene, as engine_variants.hpp composes the library's.
template <class... Units>
struct TestEffects {
  using Motion = ggsim::FreeFlight;
  template <int D, class Engine>
  using Contact = ggsim::Bounce;
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
  ggsim::Recorder rec(cfg, n, 2, {40, 40}, nullptr, 0, eng.effects().frame_fields());
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

TEST(EffectSet, ANewEffectsOptionReachesItsClassAndItsCountGoesIntoACheckpointAndTheOutput) {
  const ElasticBelowScene scene;
  ggsim::SimConfig cfg;
  CLI::App app;
  ggsim::CliSceneOptions options(app);
  scene.add_options(options, cfg);
  app.parse("--elastic-below 0.3", false);
  scene.check(cfg);
  EXPECT_TRUE(scene.used(cfg));
  ggsim::SimConfig negative = cfg;
  negative.effects.set<ElasticBelowParameters>().speed = -1;
  EXPECT_THROW(scene.check(negative), gg::UsageError);

  const auto dir = std::filesystem::temp_directory_path();
  cfg.output = (dir / "gg_effect_option_test.h5").string();
  cfg.checkpoint = (dir / "gg_effect_option_test.checkpoint.h5").string();
  cfg.t_max = 1e6;  // the run ends at its budget of collisions
  auto s = ggtest::random_start<2>(60, 0.3, 7);
  ggsim::EngineParameters par;
  par.rule = {0.5, cfg.effects};  // as simulate_impl.hpp hands the scene's parameters to the engine
  using Fx = TestEffects<ElasticBelow>;
  ggsim::Engine<2, Fx> eng(s.box, s.r, s.v, par);
  ggsim::Recorder rec(cfg, s.r.size(), 2, {s.box.L[0], s.box.L[1]}, nullptr, 0, eng.effects().frame_fields());
  ggtest::Silent none;
  eng.run(ggsim::kNever, 10 * s.r.size(), none);
  const std::int64_t before = eng.effects().get<ElasticBelow>().count();
  ASSERT_GT(before, 0);  // the option's speed reached the effect

  // A checkpoint keeps the count; the engine resumed from it goes on as the one that wrote it.
  ggsim::write_checkpoint<2>(cfg, s.box, eng.view(), rec, {}, 0);  // a test effect: none registered
  gg::Box<2> box;
  ggsim::Engine<2, Fx> resumed(box, ggsim::SavedRun(cfg.checkpoint).engine_state<2>(&box), par);
  std::filesystem::remove(cfg.checkpoint);
  EXPECT_EQ(resumed.effects().get<ElasticBelow>().count(), before);
  eng.run(cfg.t_max, 20 * s.r.size(), rec);
  resumed.run(cfg.t_max, 20 * s.r.size(), none);
  EXPECT_EQ(resumed.effects().get<ElasticBelow>().count(), eng.effects().get<ElasticBelow>().count());

  // The output: its observable as the recorder samples it, and its /parameters.
  rec.finish(eng);
  const auto& observed = rec.effect_observables().at("elastic_below").series.value;
  EXPECT_EQ(observed.back(), static_cast<double>(eng.effects().get<ElasticBelow>().count()));
  {
    gg::H5Output out(cfg.output);
    scene.write_parameters(out, cfg);
    out.commit();
  }
  EXPECT_EQ(gg::H5Input(cfg.output).attr_double("/parameters", "elastic_below"), 0.3);
  std::filesystem::remove(cfg.output);
}
