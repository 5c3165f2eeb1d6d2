// Impact-speed restitution (effects/impact_speed_restitution.hpp) against theory no code here wrote
// (docs/PHYSICS.md "Impact-speed restitution"):
//  - one collision takes e(g) = 1 - (1 - e)(g/V)^p below V and e above it (Bizon et al., PRL 80,
//    57 (1998));
//  - a dilute gas cools as the kinetic theory of speed-dependent restitution says
//    (speed_dependent_cooling.hpp), with every impact below V from the start (3D) or only after the
//    gas has cooled below V (2D), and at late times as T ~ t^(-2/(1+p)) = t^(-8/7).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "engine_harness.hpp"
#include "ggsim/effects/impact_speed_restitution.hpp"
#include "speed_dependent_cooling.hpp"

namespace {

using ImpactSpeed = ggsim::Effects<ggsim::ImpactSpeedEffect>;

// Two spheres that collide once: their normal impact speed g = |n.v_ij| at contact (n: the unit
// vector between the centres, the diameter being 1) and the restitution -n.v_ij' / n.v_ij.
struct OneCollision {
  double g, e;
};
OneCollision one_collision(double speed, double e) {
  gg::Box<3> box({20.0, 20.0, 20.0});
  std::vector<ggsim::Vec<3>> r{{5.0, 5.0, 5.0}, {8.0, 5.6, 5.3}}, v{{1.3, 0.2, 0.1}, {-0.4, -0.1, 0.0}};
  ggsim::EngineParameters par;
  par.rule.e = e;
  par.rule.effects.set<ggsim::ImpactSpeedParameters>().speed = speed;
  ggsim::Engine<3, ImpactSpeed> eng(box, r, v, par);
  const double E0 = 2 * eng.kinetic_energy();
  ggtest::Silent none;
  eng.run(ggsim::kNever, 1, none);
  EXPECT_EQ(eng.collisions(), 1u);
  const auto o = ggtest::observed(eng, eng.now());
  double vn = 0, vn_after = 0;
  for (int k = 0; k < 3; ++k) {
    const double n = o.r[0][k] - o.r[1][k];
    vn += (v[0][k] - v[1][k]) * n, vn_after += (o.v[0][k] - o.v[1][k]) * n;
  }
  const double eps = -vn_after / vn;
  EXPECT_NEAR(E0 - 2 * eng.kinetic_energy(), (1 - eps * eps) / 4 * vn * vn, 1e-13);  // paper eq. (7)
  return {std::abs(vn), eps};
}

TEST(ImpactSpeed, ACollisionBelowTheSpeedTakesTheLawAndOneAboveItTheScenesRestitution) {
  const OneCollision slow = one_collision(4.0, 0.5);
  ASSERT_LT(slow.g, 4.0);
  EXPECT_NEAR(slow.e, 1 - 0.5 * std::pow(slow.g / 4.0, 0.75), 1e-13);
  const OneCollision fast = one_collision(0.5, 0.5);
  ASSERT_GT(fast.g, 0.5);
  EXPECT_NEAR(fast.e, 0.5, 1e-13);
}

// Independent gases against the theory: mean T within 3% at every time, the late local exponent
// within 2% of the theory's.
template <int D>
void expect_kinetic_theory_cooling(double N, int runs, double phi, double e, double speed, const std::vector<double>& times) {
  const auto eps = [e, speed](double g) { return g < speed ? 1 - (1 - e) * std::pow(g / speed, 0.75) : e; };
  const std::vector<double> theory = ggtest::theory_temperatures<D>(phi, eps, times);
  ggsim::EngineParameters par;
  par.rule.e = e;
  par.rule.effects.set<ggsim::ImpactSpeedParameters>().speed = speed;
  const std::vector<double> mean = ggtest::measured_temperatures<D, ImpactSpeed>(N, runs, phi, par, times);
  for (std::size_t j = 0; j < times.size(); ++j) EXPECT_NEAR(mean[j] / theory[j], 1.0, 0.03) << "t = " << times[j];
  EXPECT_NEAR(ggtest::late_exponent(mean, times) / ggtest::late_exponent(theory, times), 1.0, 0.02);
  EXPECT_NEAR(ggtest::late_exponent(theory, times), -8.0 / 7, 0.02 * 8 / 7);
}

TEST(ImpactSpeed, DiluteGasBelowTheSpeedCoolsAsKineticTheorySaysWithTheEightSeventhsLaw3D) {
  expect_kinetic_theory_cooling<3>(4000, 2, 0.05, 0.6, 10.0, {10, 30, 100, 300, 1000, 3000, 10000});
}

TEST(ImpactSpeed, DiluteGasCoolsFromHaffsLawIntoTheEightSeventhsLaw2D) {
  expect_kinetic_theory_cooling<2>(1000, 8, 0.05, 0.9, 1.0, {3, 10, 30, 100, 300, 1000, 3000, 10000});
}

}  // namespace
