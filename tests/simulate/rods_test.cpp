// Hard rods (1D): exact conservation at e = 1, and the three-particle collapse of McNamara &
// Young, Phys. Fluids A 4, 496 (1992): x = 10, 11.5, 13, v = 1, 0, -1 gives exactly 6
// collisions at e = 0.1 and 11 at e = 0.08; below e = 7 - 4 sqrt(3) = 0.0718 infinitely many.
#include <gtest/gtest.h>

#include "engine_harness.hpp"

namespace {

using Plain = ggsim::Effects<>;

ggsim::StopReason three_rods(double e, std::uint64_t* collisions) {
  gg::Box<1> box({100.0});
  std::vector<ggsim::Vec<1>> r{{10}, {11.5}, {13}}, v{{1}, {0}, {-1}};
  ggsim::EngineParameters par;
  par.rule.e = e;
  ggsim::Engine<1, Plain> eng(box, r, v, par);
  ggtest::Silent none;
  const auto why = eng.run(10.0, ~0ull, none);
  *collisions = eng.collisions();
  return why;
}

TEST(Rods, ThreeParticleLineCollidesFinitelyOftenAboveTheThreshold) {
  std::uint64_t n = 0;
  EXPECT_EQ(three_rods(0.1, &n), ggsim::StopReason::kTimeReached);
  EXPECT_EQ(n, 6u);
  EXPECT_EQ(three_rods(0.08, &n), ggsim::StopReason::kTimeReached);
  EXPECT_EQ(n, 11u);
  const double ec = 7 - 4 * std::sqrt(3.0);
  EXPECT_EQ(three_rods(ec + 0.003, &n), ggsim::StopReason::kTimeReached);
  EXPECT_GT(n, 11u);
}

TEST(Rods, ThreeParticleLineCollapsesBelowTheThreshold) {
  const double ec = 7 - 4 * std::sqrt(3.0);
  for (double e : {ec - 0.002, 0.05, 0.0}) {
    std::uint64_t n = 0;
    EXPECT_EQ(three_rods(e, &n), ggsim::StopReason::kCollapse) << "e = " << e;
  }
}

TEST(Rods, ElasticGasConservesEnergyAndMomentum) {
  auto s = ggtest::random_start<1>(3000.0, 0.3, 9);
  ggsim::Engine<1, Plain> eng(s.box, s.r, s.v, {});
  const double E0 = eng.kinetic_energy();
  ggtest::Silent none;
  eng.run(ggsim::kNever, 200000, none);
  ASSERT_EQ(eng.collisions(), 200000u);
  // Equal masses in 1D swap velocities: the set of speeds is conserved exactly.
  ggtest::expect_elastic_invariants(eng, E0, 1e-13);
}

}  // namespace
