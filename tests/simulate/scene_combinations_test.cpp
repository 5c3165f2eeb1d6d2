// Which effects a scene may use together (scene_effect.hpp: each scene part's exclusions(), checked
// by check_combinations() in SimConfig::resolve()): a pair that one of its effects declares it cannot
// be combined with is refused in one line naming both options, the reason and the fix; a combination
// no declaration refuses has an engine compiled for it.
#include <gtest/gtest.h>

#include <bit>
#include <functional>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "engine_variant_list.hpp"  // generated: EngineVariants<D>::kKeys, the variants compiled
#include "gg/cli.hpp"
#include "gg/errors.hpp"
#include "ggsim/cli_scene_options.hpp"
#include "ggsim/engine_variants.hpp"
#include "ggsim/scene_effect.hpp"

namespace {

using namespace ggsim;

// A valid 2D scene of 400 particles in a box of edge 40 (N and L given, as walls need them), with a
// snapshot (which --unwrapped needs).
SimConfig scene() {
  SimConfig c;
  c.N = 400, c.L = 40, c.e = 0.9, c.t_max = 10, c.snapshots = {10}, c.output = "out.h5";
  return c;
}

// How this test switches on each effect, by the option a refusal names it by (written here, so that
// a new effect without a line here fails below rather than going untested).
const std::map<std::string, std::function<void(SimConfig&)>>& switch_on() {
  static const std::map<std::string, std::function<void(SimConfig&)>> on{
      {"--viscoelastic", [](SimConfig& c) { c.effects.set<ViscoelasticParameters>().k = 0.1; }},
      {"--e-speed", [](SimConfig& c) { c.effects.set<ImpactSpeedParameters>().speed = 1; }},
      {"--delta", [](SimConfig& c) { c.effects.set<CutoffParameters>().delta = 1e-4; }},
      {"--tc", [](SimConfig& c) { c.effects.set<TcParameters>().tc = 1e-4; }},
      {"--beta", [](SimConfig& c) { c.effects.set<RoughParameters>().beta = 0.5; }},
      {"--pressure", [](SimConfig& c) { c.effects.set<PressureParameters>().on = true; }},
      {"--unwrapped", [](SimConfig& c) { c.effects.set<ImageParameters>().on = true; }},
      {"--drive", [](SimConfig& c) { c.effects.set<DriveParameters>() = {.kind = "white-noise", .strength = 0.1}; }},
      {"--walls", [](SimConfig& c) { c.effects.set<WallParameters>().height = 20; }},
      {"--shear-rate", [](SimConfig& c) { c.effects.set<ShearParameters>().rate = 0.1; }},
      {"--radii or --masses", [](SimConfig& c) { c.effects.set<MixtureParameters>().radii = "0.5,0.7"; }},
      {"--aggregate", [](SimConfig& c) { c.aggregate = true; }},
  };
  return on;
}

// The scene with the effects named by their options, as SimConfig::resolve() takes it: "accepted",
// or the message it is refused with.
std::string verdict(const std::vector<std::string>& options) {
  SimConfig c = scene();
  for (const std::string& option : options) switch_on().at(option)(c);
  try {
    c.resolve(true, true, false);
  } catch (const gg::UsageError& e) {
    return e.what();
  }
  return "accepted";
}

unsigned registered() { return (1u << scene_effects().size()) - 1; }

}  // namespace

TEST(SceneCombinations, NamedPairsAreRefusedInOneLineWithTheReasonAndTheFix) {
  const std::pair<std::vector<std::string>, std::string> cases[] = {
      {{"--walls", "--shear-rate"},
       "--walls cannot be combined with --shear-rate (a box with walls runs with no other effect; drop one of them)"},
      // Whichever is named first, the declaring effect speaks.
      {{"--shear-rate", "--walls"},
       "--walls cannot be combined with --shear-rate (a box with walls runs with no other effect; drop one of them)"},
      {{"--aggregate", "--e-speed"},
       "--aggregate cannot be combined with --e-speed (aggregation merges at contact; drop one of them)"},
      {{"--shear-rate", "--e-speed"},
       "--shear-rate cannot be combined with --e-speed (a sheared box runs with no other effect but --unwrapped; drop "
       "one of them)"},
      {{"--walls", "--e-speed"},
       "--walls cannot be combined with --e-speed (a box with walls runs with no other effect; drop one of them)"},
      {{"--e-speed", "--viscoelastic"},
       "--e-speed cannot be combined with --viscoelastic (both are laws of the restitution; drop one of them)"},
      {{"--aggregate", "--unwrapped"},
       "--aggregate cannot be combined with --unwrapped (a merged particle has no single image; drop one of them)"},
      {{"--pressure", "--aggregate"},
       "--aggregate cannot be combined with --pressure (aggregation merges at contact; drop one of them)"},
      {{"--drive", "--radii or --masses"},
       "--drive cannot be combined with --radii or --masses (its kicks keep the momentum of equal masses only; drop "
       "one of them)"},
      // What no declaration refuses.
      {{"--shear-rate", "--unwrapped"}, "accepted"},
      {{"--e-speed", "--tc"}, "accepted"},
      {{"--beta", "--pressure", "--delta", "--drive"}, "accepted"},
      {{"--viscoelastic", "--radii or --masses"}, "accepted"},
  };
  for (const auto& [options, expected] : cases) EXPECT_EQ(verdict(options), expected);
}

// Each option a refusal names is an option its scene part adds.
TEST(SceneCombinations, EachEffectIsNamedByItsOwnOption) {
  for (const SceneEffect* effect : scene_effects()) {
    CLI::App app;
    CliSceneOptions options(app);
    SimConfig bound;
    effect->add_options(options, bound);
    std::istringstream words(effect->option());
    std::string word;
    int named = 0;
    while (words >> word)
      if (word.rfind("--", 0) == 0) {
        EXPECT_NE(app.get_option_no_throw(word), nullptr) << effect->option();
        ++named;
      }
    EXPECT_GT(named, 0) << effect->option();
    EXPECT_TRUE(switch_on().count(effect->option())) << "no way to switch on " << effect->option() << " in this test";
  }
}

// Every pair a declaration names, generated from the declarations: resolve() refuses the scene with
// both, with the line combination_refusal() makes of the declaration.
TEST(SceneCombinations, EveryDeclaredPairIsRefused) {
  const std::vector<const SceneEffect*>& parts = scene_effects();
  int pairs = 0;
  for (std::size_t k = 0; k < parts.size(); ++k)
    for (const Exclusion& x : parts[k]->exclusions())
      for (unsigned others = x.effects & registered() & ~(1u << k); others != 0; others &= others - 1) {
        const std::size_t j = std::countr_zero(others);
        SCOPED_TRACE(parts[k]->option() + " with " + parts[j]->option());
        SimConfig c = scene();
        switch_on().at(parts[k]->option())(c);
        switch_on().at(parts[j]->option())(c);
        ASSERT_EQ(used_effects(c), (1u << k) | (1u << j));
        const std::string refusal = combination_refusal(used_effects(c));
        EXPECT_NE(refusal.find(" cannot be combined with "), std::string::npos) << refusal;
        EXPECT_NE(refusal.find(parts[k]->option()), std::string::npos) << refusal;
        EXPECT_NE(refusal.find(parts[j]->option()), std::string::npos) << refusal;
        EXPECT_NE(refusal.find("; drop one of them)"), std::string::npos) << refusal;
        EXPECT_EQ(verdict({parts[k]->option(), parts[j]->option()}), refusal);
        ++pairs;
      }
  // Walls, the shear and aggregation each exclude (nearly) every other effect.
  EXPECT_GE(pairs, 3 * 10);
}

// A combination that no declaration refuses runs: a compiled engine variant holds it (in 1D, where
// walls and the shear are not, among those without them). The declarations are what keeps a scene
// from the variants that were not compiled.
TEST(SceneCombinations, EveryAcceptedCombinationHasAnEngine) {
  const unsigned not_in_1d = kBit<WallsEffect> | kBit<ShearEffect>;
  int accepted = 0;
  for (unsigned used = 0; used <= registered(); ++used) {
    if (!combination_refusal(used).empty()) continue;
    ++accepted;
    EXPECT_NO_THROW(choose_variant(used, EngineVariants<2>::kKeys)) << used;
    EXPECT_NO_THROW(choose_variant(used, EngineVariants<3>::kKeys)) << used;
    if ((used & not_in_1d) == 0) {
      EXPECT_NO_THROW(choose_variant(used, EngineVariants<1>::kKeys)) << used;
    }
  }
  EXPECT_GT(accepted, 1);
  EXPECT_FALSE(combination_refusal(kBit<WallsEffect> | kBit<AggregateEffect>).empty());
}
