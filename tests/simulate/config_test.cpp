// A scene's validation (config.hpp, SimConfig::resolve; docs/DESIGN.md "Command lines"): any two
// of N, L, rho give the third; every value out of range is refused with a gg::UsageError that
// names the flag to change, before anything runs.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <sstream>
#include <string>

#include "gg/cli.hpp"
#include "gg/errors.hpp"
#include "ggsim/cli_scene_options.hpp"
#include "ggsim/config.hpp"
#include "ggsim/effects/effect_set.hpp"
#include "ggsim/mixture.hpp"
#include "ggsim/resume_scene.hpp"
#include "ggsim/scene_effect.hpp"

namespace {

using ggsim::RoughParameters;
using ggsim::SimConfig;

// A valid 2D scene: L = 512, rho = 0.37, e = 0.9, run to t = 100.
SimConfig scene() {
  SimConfig c;
  c.L = 512;
  c.rho = 0.37;
  c.e = 0.9;
  c.t_max = 100;
  c.output = "out.h5";
  return c;
}

// The message a scene changed by `change` is refused with (given: which of N, L, rho were named),
// or "accepted".
std::string refusal(const std::function<void(SimConfig&)>& change, bool n = false, bool l = true, bool rho = true) {
  SimConfig c = scene();
  change(c);
  try {
    c.resolve(n, l, rho);
  } catch (const gg::UsageError& e) {
    return e.what();
  }
  return "accepted";
}

void expect_refused(const std::function<void(SimConfig&)>& change, const std::string& names) {
  const std::string m = refusal(change);
  EXPECT_NE(m, "accepted") << "expected a refusal naming " << names;
  EXPECT_NE(m.find(names), std::string::npos) << m;
}

}  // namespace

TEST(SimConfig, AnyTwoOfNLRhoGiveTheThird) {
  SimConfig a = scene();
  a.resolve(false, true, true);
  EXPECT_EQ(a.N, 96993u);  // round(0.37 x 512^2): the paper's system
  EXPECT_DOUBLE_EQ(a.rho, 96993.0 / (512.0 * 512.0));  // rho made consistent with the whole N

  SimConfig b = scene();
  b.N = 96993, b.L = 0;
  b.resolve(true, false, true);
  EXPECT_NEAR(b.L, 512.0, 1e-3);
  EXPECT_DOUBLE_EQ(b.rho, 96993.0 / (b.L * b.L));

  SimConfig c = scene();
  c.dim = 1, c.N = 6000, c.L = 20000, c.rho = 0;
  c.resolve(true, true, false);
  EXPECT_DOUBLE_EQ(c.rho, 0.3);
}

TEST(SimConfig, NotExactlyTwoOfNLRhoIsRefused) {
  EXPECT_NE(refusal([](SimConfig&) {}, true, true, true).find("exactly two of --N, --L, --rho"), std::string::npos);
  EXPECT_NE(refusal([](SimConfig&) {}, false, true, false).find("exactly two of --N, --L, --rho"), std::string::npos);
  // A start from a file fixes all three.
  EXPECT_NE(refusal([](SimConfig& c) { c.init = "start.h5"; }).find("drop --N, --L and --rho"), std::string::npos);
  EXPECT_EQ(refusal([](SimConfig& c) { c.init = "start.h5"; }, false, false, false), "accepted");
}

TEST(SimConfig, ValuesOutOfRangeAreRefusedNamingTheFlag) {
  expect_refused([](SimConfig& c) { c.dim = 4; }, "--dim");
  expect_refused([](SimConfig& c) { c.dim = 0; }, "--dim");
  expect_refused([](SimConfig& c) { c.L = -1; }, "--L");
  expect_refused([](SimConfig& c) { c.L = NAN; }, "--L");
  expect_refused([](SimConfig& c) { c.rho = 0; }, "--rho");
  expect_refused([](SimConfig& c) { c.rho = 1e-9; }, "no particle");
  expect_refused([](SimConfig& c) { c.e = 1.01; }, "--e");
  expect_refused([](SimConfig& c) { c.e = -0.1; }, "--e");
  expect_refused([](SimConfig& c) { c.e = NAN; }, "--e");
  expect_refused([](SimConfig& c) { c.effects.set<ggsim::CutoffParameters>().delta = -1e-3; }, "--delta");
  expect_refused([](SimConfig& c) { c.effects.set<ggsim::TcParameters>().tc = -1e-4; }, "--tc");
  expect_refused([](SimConfig& c) { c.T0 = 0; }, "--T0");
  expect_refused([](SimConfig& c) { c.equilibrate = -1; }, "--equilibrate");
  expect_refused([](SimConfig& c) { c.t_max = 0; }, "--t-max");
  expect_refused([](SimConfig& c) { c.samples_per_decade = 0; }, "--samples-per-decade");
  expect_refused([](SimConfig& c) { c.sample_from = 0; }, "--sample-from");
  expect_refused([](SimConfig& c) { c.snapshots_per_decade = -1; }, "--snapshots-per-decade");
  expect_refused([](SimConfig& c) { c.snapshots_from = 0; }, "--snapshots-from");
  expect_refused([](SimConfig& c) { c.skin = 0; }, "--skin");
  expect_refused([](SimConfig& c) { c.checkpoint_every = -1; }, "--checkpoint-every");
  expect_refused([](SimConfig& c) { c.effects.set<RoughParameters>().beta = 1.5; }, "--beta");
  expect_refused([](SimConfig& c) { c.effects.set<RoughParameters>().beta = -1.01; }, "--beta");
  expect_refused([](SimConfig& c) { c.effects.set<RoughParameters>().beta = 0, c.dim = 1; }, "--beta");
  expect_refused([](SimConfig& c) { c.effects.set<RoughParameters>() = {.beta = 0, .inertia = 0}; }, "--inertia");
  expect_refused([](SimConfig& c) { c.effects.set<RoughParameters>() = {.beta = 0, .inertia = 1.1}; }, "--inertia");
  expect_refused([](SimConfig& c) { c.effects.set<RoughParameters>() = {.beta = 0, .T0_rot = -1}; }, "--T0-rot");
  expect_refused([](SimConfig& c) { c.effects.set<RoughParameters>().T0_rot = 1; }, "--T0-rot");
  expect_refused([](SimConfig& c) { c.effects.set<RoughParameters>().inertia = 0.5; }, "--inertia");
  // The boundaries themselves are valid.
  EXPECT_EQ(refusal([](SimConfig& c) { c.e = 0; }), "accepted");
  EXPECT_EQ(refusal([](SimConfig& c) { c.e = 1; }), "accepted");
  EXPECT_EQ(refusal([](SimConfig& c) { c.effects.set<RoughParameters>().beta = -1; }), "accepted");
  EXPECT_EQ(refusal([](SimConfig& c) { c.effects.set<RoughParameters>() = {.beta = 1, .inertia = 1}; }), "accepted");
}

TEST(SimConfig, RoughParticlesGetTheInertiaOfAUniformDiskOrSphere) {
  for (int dim : {2, 3}) {
    SimConfig c = scene();
    c.dim = dim, c.effects.set<RoughParameters>().beta = 0;
    c.resolve(false, true, true);
    EXPECT_EQ(*c.effects.get<RoughParameters>().inertia, dim == 2 ? 0.5 : 0.4);
  }
}

TEST(SimConfig, ARunThatCouldNeverEndOrRecordIsRefused) {
  expect_refused([](SimConfig& c) { c.t_max = INFINITY; }, "--t-max or --max-collisions");
  EXPECT_EQ(refusal([](SimConfig& c) { c.t_max = INFINITY, c.max_collisions = 1000; }), "accepted");
  expect_refused([](SimConfig& c) { c.snapshots = {1, 200}; }, "beyond --t-max");
  expect_refused([](SimConfig& c) { c.snapshots = {-1}; }, "--snapshots");
  expect_refused([](SimConfig& c) { c.snapshots = {1}, c.snapshots_per_decade = 4; }, "not both");
  expect_refused([](SimConfig& c) { c.output.clear(); }, "-o");
  // Periodic checkpoints of a run to stdout need a file to go to. ("-" is assigned as a
  // std::string: GCC 12 warns falsely, -Wrestrict, on assigning the one-character literal.)
  expect_refused([](SimConfig& c) { c.output = std::string("-"), c.checkpoint_every = 60; }, "--checkpoint FILE");
  EXPECT_EQ(refusal([](SimConfig& c) { c.output = std::string("-"), c.checkpoint_every = 60, c.checkpoint = "c.h5"; }), "accepted");
}

TEST(SimConfig, CheckpointGoesBesideTheOutputUnlessNamed) {
  SimConfig c = scene();
  EXPECT_EQ(c.checkpoint_path(), "out.h5.checkpoint.h5");
  c.checkpoint = "/tmp/c.h5";
  EXPECT_EQ(c.checkpoint_path(), "/tmp/c.h5");
  SimConfig to_stdout = scene();
  to_stdout.output = std::string("-");
  EXPECT_TRUE(to_stdout.checkpoint_path().empty());  // no output file to put it beside
}

TEST(SimConfig, FingerprintChangesWithEveryValueThatShapesTheRun) {
  const std::string base = scene().fingerprint();
  const std::function<void(SimConfig&)> changes[] = {
      [](SimConfig& c) { c.e = 0.8; },
      [](SimConfig& c) { c.effects.set<ggsim::CutoffParameters>().delta = 1e-3; },
      [](SimConfig& c) { c.effects.set<ggsim::TcParameters>().tc = 1e-4; },
      [](SimConfig& c) { c.seed = 2; },
      [](SimConfig& c) { c.t_max = 200; },
      [](SimConfig& c) { c.samples_per_decade = 10; },
      [](SimConfig& c) { c.skin = 0.5; },
      [](SimConfig& c) { c.velocities = true; },
      [](SimConfig& c) { c.effects.set<ggsim::PressureParameters>().on = true; },
      [](SimConfig& c) { c.snapshots = {50}; },
      [](SimConfig& c) { c.effects.set<RoughParameters>().beta = -1; },
      [](SimConfig& c) { c.effects.set<RoughParameters>() = {.beta = 0, .inertia = 0.3}; },
      [](SimConfig& c) { c.effects.set<RoughParameters>() = {.beta = 0, .T0_rot = 1}; },
      [](SimConfig& c) { c.effects.set<ggsim::ViscoelasticParameters>().k = 0.1; },
      [](SimConfig& c) { c.effects.set<ggsim::WallParameters>().height = 20; },
      [](SimConfig& c) { c.effects.set<ggsim::WallParameters>() = {.height = 20, .gravity = 0.1}; },
      [](SimConfig& c) { c.effects.set<ggsim::WallParameters>() = {.height = 20, .temperature = 2}; },
      [](SimConfig& c) { c.effects.set<ggsim::WallParameters>() = {.height = 20, .amplitude = 0.1, .frequency = 2}; }};
  for (const auto& change : changes) {
    SimConfig c = scene();
    change(c);
    EXPECT_NE(c.fingerprint(), base);
  }
  SimConfig same = scene();
  same.output = "elsewhere.h5";  // where the output goes does not shape the run
  EXPECT_EQ(same.fingerprint(), base);
}

// Each effect's scene part (scene_effect.hpp) is whole: every key it puts in a fingerprint names an
// option it adds (so that --resume can say which flag differs and a scene file can set it), reads
// back from its text (adopt_scene), and is written only when the scene uses the effect.
TEST(SceneEffect, EveryKeyIsAnOptionOfItsEffectAndReadsBackFromTheFingerprint) {
  SimConfig used = scene();
  used.effects.set<ggsim::DriveParameters>() = {.kind = "white-noise", .strength = 0.25, .rate = 3};
  used.effects.set<RoughParameters>() = {.beta = 0.5, .inertia = 0.4, .T0_rot = 2};
  used.effects.set<ggsim::MixtureParameters>() = {.radii = "0.5,0.6", .masses = "1,2", .fractions = "0.25,0.75"};
  used.effects.set<ggsim::ViscoelasticParameters>().k = 0.125;
  used.effects.set<ggsim::ImpactSpeedParameters>() = {.speed = 2, .exponent = 0.5};
  used.effects.set<ggsim::CutoffParameters>().delta = 1e-3;
  used.effects.set<ggsim::TcParameters>().tc = 1e-4;
  used.effects.set<ggsim::PressureParameters>().on = true;
  used.effects.set<ggsim::ImageParameters>().on = true;
  used.effects.set<ggsim::WallParameters>() = {.height = 20, .restitution = 0.75, .temperature = 2, .gravity = 0.5,
                                              .amplitude = 0.1, .frequency = 2};
  used.effects.set<ggsim::ShearParameters>().rate = 0.25;
  used.aggregate = true;  // (no scene merges rough or driven particles; the keys are each part's alone)
  for (const ggsim::SceneEffect* effect : ggsim::scene_effects()) {
    CLI::App app;
    ggsim::CliSceneOptions options(app);
    SimConfig bound;
    effect->add_options(options, bound);
    std::ostringstream with, without;
    effect->fingerprint(used, with);
    effect->fingerprint(scene(), without);
    EXPECT_EQ(without.str(), "");
    const auto keys = effect->keys();
    ASSERT_FALSE(keys.empty());
    const std::string text = with.str();
    SimConfig back = scene();  // every key's text set into a scene without the effect
    for (const ggsim::SceneKey& key : keys) {
      EXPECT_NE(app.get_option_no_throw("--" + key.flag), nullptr) << key.name;
      const auto at = text.find(" " + key.name + "=");
      ASSERT_NE(at, std::string::npos) << key.name;
      const auto from = at + key.name.size() + 2;
      key.set(back, text.substr(from, text.find(' ', from) - from));
    }
    std::ostringstream again;
    effect->fingerprint(back, again);
    EXPECT_EQ(again.str(), text);
  }
}

// The scene's own keys (base_scene_keys()) are one table as an effect's: its text is the checkpoint
// format every older checkpoint holds (a --resume compares it), and a --resume that takes every value
// from a checkpoint gets the scene that wrote it.
TEST(SceneKeys, TheSceneReadsBackFromItsFingerprint) {
  SimConfig from_file;  // a start from a file names T0 or not, and may keep the file's clock
  from_file.init = "start.h5", from_file.T0 = 1.5, from_file.T0_given = true, from_file.continue_clock = true;
  from_file.t_max = 100, from_file.snapshots = {10, 50};
  EXPECT_EQ(from_file.fingerprint(),
            "dim=2 N=0 L=0 e=1 T0=1.5 seed=1 init=start.h5 equilibrate=0 t_max=100 max_collisions=18446744073709551615 "
            "samples_per_decade=20 sample_from=0.01 snapshots=10,50, T0_given=1 snapshots_per_decade=0 "
            "snapshots_from=1 velocities=0 float_snapshots=0 skin=0.69999999999999996 continue=1");
  SimConfig drawn;  // every other key away from its default
  drawn.dim = 3, drawn.N = 1000, drawn.L = 12.5, drawn.e = 0.75, drawn.T0 = 2, drawn.seed = ~std::uint64_t{0};
  drawn.equilibrate = 5, drawn.max_collisions = 4000000, drawn.samples_per_decade = 8, drawn.sample_from = 0.5;
  drawn.snapshots_per_decade = 4, drawn.snapshots_from = 2, drawn.velocities = true, drawn.float_snapshots = true;
  drawn.skin = 0.25;
  EXPECT_EQ(drawn.fingerprint().find("T0_given"), std::string::npos);  // a drawn start's T0 is always its own
  EXPECT_EQ(drawn.fingerprint().find("continue"), std::string::npos);
  for (const SimConfig& c : {from_file, drawn}) {
    SimConfig back;
    bool n_given = false, l_given = false;
    ggsim::adopt_scene(back, ggsim::parse_scene(c.fingerprint(), "test"), {}, &n_given, &l_given);
    EXPECT_EQ(back.fingerprint(), c.fingerprint());
    EXPECT_EQ(n_given && l_given, !c.starts_from_file());  // N and L only for a start without a file
  }
}
