// Which engine variant a scene runs (engine_variants.hpp), and why any variant that holds a
// scene's effects is as good as the one with exactly them: with the effects present but unused
// (delta = 0, t_c = 0, virial and images not read) the trajectory is the same bit for bit.
#include <gtest/gtest.h>

#include <array>
#include <stdexcept>
#include <type_traits>

#include "engine_harness.hpp"
#include "ggsim/engine_variants.hpp"

namespace {

using namespace ggsim;

constexpr std::array<unsigned, 5> kSome{0u, kBit<VirialEffect>, kBit<TcEffect> | kBit<VirialEffect>, kBit<CutoffEffect> | kBit<TcEffect> | kBit<VirialEffect> | kBit<ImagesEffect>,
                                        kBit<AggregateEffect>};

TEST(EngineVariants, AnExactMatchIsChosen) {
  EXPECT_EQ(choose_variant(0u, kSome), 0u);
  EXPECT_EQ(choose_variant(kBit<VirialEffect>, kSome), 1u);
  EXPECT_EQ(choose_variant(kBit<TcEffect> | kBit<VirialEffect>, kSome), 2u);
  EXPECT_EQ(choose_variant(kBit<AggregateEffect>, kSome), 4u);
}

TEST(EngineVariants, OtherwiseTheSmallestThatHoldsEveryEffect) {
  EXPECT_EQ(choose_variant(kBit<TcEffect>, kSome), 2u);       // t_c + virial, not all four
  EXPECT_EQ(choose_variant(kBit<CutoffEffect>, kSome), 3u);   // only the one with all four holds a cutoff
  EXPECT_EQ(choose_variant(kBit<ImagesEffect> | kBit<VirialEffect>, kSome), 3u);
}

TEST(EngineVariants, AggregationIsNeverAddedNorDropped) {
  constexpr std::array<unsigned, 2> with_aggregation{kBit<AggregateEffect> | kBit<VirialEffect>, kBit<CutoffEffect>};
  EXPECT_THROW(choose_variant(kBit<VirialEffect>, with_aggregation), std::logic_error);
  EXPECT_THROW(choose_variant(kBit<AggregateEffect> | kBit<CutoffEffect>, with_aggregation), std::logic_error);
}

// Variant names as simulate/CMakeLists.txt writes them: each effect's word, in any order; "all" is
// every effect but the three that change the engine itself.
TEST(EngineVariants, NamesGiveTheirEffects) {
  static_assert(variant_key("plain") == 0u);
  static_assert(variant_key("tc+virial") == (kBit<TcEffect> | kBit<VirialEffect>));
  static_assert(variant_key("virial+tc") == variant_key("tc+virial"));
  static_assert(variant_key("shear+images") == (kBit<ShearEffect> | kBit<ImagesEffect>));
  static_assert(kExactBits == (kBit<AggregateEffect> | kBit<WallsEffect> | kBit<ShearEffect>));
  static_assert((variant_key("all") & kExactBits) == 0u);
  static_assert((variant_key("all") & (kBit<ViscoelasticEffect> | kBit<MixtureEffect> | kBit<ImagesEffect>)) ==
                (kBit<ViscoelasticEffect> | kBit<MixtureEffect> | kBit<ImagesEffect>));
  static_assert(std::is_same_v<Effects<VirialEffect, TcEffect>, EngineVariant<variant_key("tc+virial")>>);
  SUCCEED();
}

TEST(EngineVariants, SceneFlagsGiveTheirBits) {
  SimConfig cfg;
  EXPECT_EQ(wanted_effects(cfg), 0u);
  cfg.effects.set<CutoffParameters>().delta = 1e-4;
  cfg.effects.set<PressureParameters>().on = true;
  EXPECT_EQ(wanted_effects(cfg), kBit<CutoffEffect> | kBit<VirialEffect>);
  cfg = SimConfig{};
  cfg.effects.set<TcParameters>().tc = 1e-4;
  cfg.effects.set<ImageParameters>().on = true;
  EXPECT_EQ(wanted_effects(cfg), kBit<TcEffect> | kBit<ImagesEffect>);
  cfg = SimConfig{};
  cfg.aggregate = true;
  EXPECT_EQ(wanted_effects(cfg), unsigned{kBit<AggregateEffect>});
  cfg = SimConfig{};
  cfg.effects.set<RoughParameters>().beta = -1;  // rough particles as soon as --beta is given, even the smooth value
  EXPECT_EQ(wanted_effects(cfg), unsigned{kBit<RoughEffect>});
  cfg = SimConfig{};
  cfg.effects.set<MixtureParameters>().radii = "0.5,0.7";
  EXPECT_EQ(wanted_effects(cfg), unsigned{kBit<MixtureEffect>});
  cfg = SimConfig{};
  cfg.effects.set<MixtureParameters>().masses = "1,2";
  EXPECT_EQ(wanted_effects(cfg), unsigned{kBit<MixtureEffect>});
  cfg = SimConfig{};
  cfg.effects.set<ViscoelasticParameters>().k = 0.1;
  EXPECT_EQ(wanted_effects(cfg), unsigned{kBit<ViscoelasticEffect>});
  cfg = SimConfig{};
  cfg.effects.set<ggsim::WallParameters>().height = 20;  // gravity and a thermal wall are the same variant's values
  EXPECT_EQ(wanted_effects(cfg), unsigned{kBit<WallsEffect>});
}

// An inelastic gas (e = 0.5, many collisions per particle, clusters forming) run by the plain
// engine and by the variant "all", every registered effect that is not exact compiled in but off: a
// law of the restitution at its "none" (K = 0, V = 0: the scene's e), no cutoff, no t_c, virial and
// images not read, no drive, beta = -1 (smooth), every radius 1/2 and every mass 1 (the mixture's
// contact distance and impulse reduce to the plain ones exactly). A new effect is in "all" as soon as
// it is registered, so this holds it to the same.
template <int D>
void same_trajectory_with_unused_effects(double L, double rho) {
  ggtest::expect_plain_trajectory<D, EngineVariant<variant_key("all")>>(L, rho, {});
}

TEST(EngineVariants, UnusedEffectsLeaveTheTrajectoryBitForBit1D) { same_trajectory_with_unused_effects<1>(2000, 0.3); }
TEST(EngineVariants, UnusedEffectsLeaveTheTrajectoryBitForBit2D) { same_trajectory_with_unused_effects<2>(40, 0.37); }
TEST(EngineVariants, UnusedEffectsLeaveTheTrajectoryBitForBit3D) { same_trajectory_with_unused_effects<3>(12, 0.5); }

}  // namespace
