// Hard rods (1D): exact conservation at e = 1, and the three-particle collapse of McNamara &
// Young, Phys. Fluids A 4, 496 (1992): x = 10, 11.5, 13, v = 1, 0, -1 gives exactly 6
// collisions at e = 0.1 and 11 at e = 0.08; below e = 7 - 4 sqrt(3) = 0.0718 infinitely many.
#include <gtest/gtest.h>

#include "engine_harness.hpp"

namespace {

using Plain = ggsim::Effects<>;

template <class Fx = Plain>
ggsim::StopReason three_rods(double e, std::uint64_t* collisions, ggsim::EngineParameters par = {}) {
  gg::Box<1> box({100.0});
  std::vector<ggsim::Vec<1>> r{{10}, {11.5}, {13}}, v{{1}, {0}, {-1}};
  par.rule.e = e;
  ggsim::Engine<1, Fx> eng(box, r, v, par);
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

// What the collapse models are for: below the threshold the cutoff (relative speeds under delta
// bounce elastically) and the TC model (a collision within t_c of a particle's last one is elastic,
// Luding & McNamara, Granular Matter 1, 113 (1998)) each let the same line run on to t_max after
// finitely many collisions.
TEST(Rods, ThreeParticleLineBelowTheThresholdRunsOnWithACollapseModel) {
  for (double e : {0.05, 0.0}) {
    std::uint64_t n = 0;
    ggsim::EngineParameters cutoff;
    cutoff.rule.effects.set<ggsim::CutoffParameters>().delta = 1e-2;
    EXPECT_EQ(three_rods<ggsim::Effects<ggsim::CutoffEffect>>(e, &n, cutoff), ggsim::StopReason::kTimeReached) << "e = " << e;
    EXPECT_LT(n, 100u) << "e = " << e;
    ggsim::EngineParameters tc;
    tc.rule.effects.set<ggsim::TcParameters>().tc = 1e-4;
    EXPECT_EQ(three_rods<ggsim::Effects<ggsim::TcEffect>>(e, &n, tc), ggsim::StopReason::kTimeReached) << "e = " << e;
    EXPECT_LT(n, 100u) << "e = " << e;
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
