// Viscoelastic particles (effects/viscoelastic_restitution.hpp) against theory no code here wrote
// (docs/PHYSICS.md "Viscoelastic particles"):
//  - epsilon(kappa) of the dissipative Hertz law: the series 1 - 1.15344 kappa + 0.79826 kappa^2 of
//    Ramirez, Poschel, Brilliantov & Schwager (PRE 60, 4465 (1999)) at small kappa, and this test's
//    own integration of the law (plain time steps) at every kappa;
//  - one collision takes its restitution from its normal impact speed;
//  - a dilute gas cools as the kinetic theory of viscoelastic gases says (Schwager & Poschel, PRE 57,
//    650 (1998); speed_dependent_cooling.hpp), which at late times gives T ~ t^(-5/3);
//  - a dense gas that collapses at constant e = 0.5 runs through without any cutoff.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "engine_harness.hpp"
#include "ggsim/effects/viscoelastic_restitution.hpp"
#include "speed_dependent_cooling.hpp"

namespace {

using Viscoelastic = ggsim::Effects<ggsim::ViscoelasticEffect>;

// The law integrated in time from x = 0, x' = 1 with small RK4 steps until x < 0 (linear
// interpolation of x' at the crossing): the right side's sqrt(x) costs the steps at both ends
// their order, so the steps are small.
double epsilon_by_time_steps(double kappa) {
  const double h = 2e-6;
  double x = 0, v = 1;
  const auto acc = [kappa](double x_, double v_) {
    const double s = std::sqrt(std::max(x_, 0.0));
    return -x_ * s - kappa * s * v_;
  };
  for (;;) {
    const double ax = v, av = acc(x, v);
    const double bx = v + h / 2 * av, bv = acc(x + h / 2 * ax, v + h / 2 * av);
    const double cx = v + h / 2 * bv, cv = acc(x + h / 2 * bx, v + h / 2 * bv);
    const double dx = v + h * cv, dv = acc(x + h * cx, v + h * cv);
    const double x1 = x + h / 6 * (ax + 2 * bx + 2 * cx + dx), v1 = v + h / 6 * (av + 2 * bv + 2 * cv + dv);
    if (x1 < 0 && v1 < 0) return -(v + (v1 - v) * x / (x - x1));
    x = x1, v = v1;
  }
}

TEST(Viscoelastic, EpsilonFollowsThePublishedSeriesAtSmallKappa) {
  // (1 - epsilon) / kappa = C1 - C2 kappa + O(kappa^2): C1 and C2 from two small kappa.
  const double k1 = 1e-3, k2 = 2e-3;
  const double y1 = (1 - ggsim::viscoelastic_epsilon(k1)) / k1, y2 = (1 - ggsim::viscoelastic_epsilon(k2)) / k2;
  const double c2 = -(y2 - y1) / (k2 - k1), c1 = y1 + c2 * k1;
  EXPECT_NEAR(c1, 1.15344, 2e-5);
  EXPECT_NEAR(c2, 0.79826, 0.01);
  EXPECT_EQ(ggsim::viscoelastic_epsilon(0), 1.0);
}

TEST(Viscoelastic, EpsilonIsTheHertzLawAtEverySpeed) {
  double last = 1;
  for (double kappa : {0.05, 0.3, 1.0, 2.5, 3.999, 4.0, 6.0}) {
    const double eps = ggsim::viscoelastic_epsilon(kappa);
    EXPECT_NEAR(eps, epsilon_by_time_steps(kappa), 2e-6) << "kappa = " << kappa;
    EXPECT_LT(eps, last);  // faster impacts lose more
    last = eps;
  }
}

TEST(Viscoelastic, OneCollisionTakesItsRestitutionFromItsImpactSpeed) {
  gg::Box<3> box({20.0, 20.0, 20.0});
  std::vector<ggsim::Vec<3>> r{{5.0, 5.0, 5.0}, {8.0, 5.6, 5.3}}, v{{1.3, 0.2, 0.1}, {-0.4, -0.1, 0.0}};
  ggsim::EngineParameters par;
  par.rule.effects.set<ggsim::ViscoelasticParameters>().k = 0.2;
  ggsim::Engine<3, Viscoelastic> eng(box, r, v, par);
  const double E0 = 2 * eng.kinetic_energy();
  ggtest::Silent none;
  eng.run(ggsim::kNever, 1, none);
  ASSERT_EQ(eng.collisions(), 1u);
  const auto o = ggtest::observed(eng, eng.now());
  ggsim::Vec<3> n;
  for (int k = 0; k < 3; ++k) n[k] = o.r[0][k] - o.r[1][k];
  double vn = 0, vn_after = 0;
  for (int k = 0; k < 3; ++k) vn += (v[0][k] - v[1][k]) * n[k], vn_after += (o.v[0][k] - o.v[1][k]) * n[k];
  const double eps = ggsim::viscoelastic_epsilon(0.2 * std::pow(std::abs(vn), 0.2));
  EXPECT_NEAR(-vn_after / vn, eps, 1e-13);
  EXPECT_NEAR(E0 - 2 * eng.kinetic_energy(), (1 - eps * eps) / 4 * vn * vn, 1e-13);
}

// Independent gases of N particles against the kinetic theory of their cooling
// (speed_dependent_cooling.hpp), eps(g) = epsilon(K g^(1/5)): eps falls with g, so cooling slows down
// as T does, T ~ t^(-5/3). Their mean T within 3% at every time, the late local exponent
// d ln T / d ln t within 2% of the theory's, and the theory's own within 5% of -5/3.
template <int D>
void expect_kinetic_theory_cooling(double N, int runs, double phi, double K, const std::vector<double>& times) {
  const auto eps = [K](double g) { return ggsim::viscoelastic_epsilon(K * std::pow(g, 0.2)); };
  const std::vector<double> theory = ggtest::theory_temperatures<D>(phi, eps, times);
  ggsim::EngineParameters par;
  par.rule.effects.set<ggsim::ViscoelasticParameters>().k = K;
  const std::vector<double> mean = ggtest::measured_temperatures<D, Viscoelastic>(N, runs, phi, par, times);
  for (std::size_t j = 0; j < times.size(); ++j) EXPECT_NEAR(mean[j] / theory[j], 1.0, 0.03) << "t = " << times[j];
  const double slope_theory = ggtest::late_exponent(theory, times);
  EXPECT_NEAR(ggtest::late_exponent(mean, times) / slope_theory, 1.0, 0.02);
  EXPECT_NEAR(slope_theory, -5.0 / 3, 0.05 * 5 / 3);
}

TEST(Viscoelastic, DiluteGasCoolsAsKineticTheorySaysAndReachesTheFiveThirdsLaw3D) {
  expect_kinetic_theory_cooling<3>(4000, 2, 0.05, 0.05, {10, 30, 100, 300, 1000, 2000, 4000});
}

TEST(Viscoelastic, DiluteGasCoolsAsKineticTheorySaysAndReachesTheFiveThirdsLaw2D) {
  expect_kinetic_theory_cooling<2>(1000, 8, 0.05, 0.05, {10, 30, 100, 300, 1000, 2000, 4000});
}

TEST(Viscoelastic, ADenseGasThatCollapsesAtConstantRestitutionRunsThrough) {
  auto s = ggtest::random_start<1>(400.0, 0.3, 21);
  ggsim::EngineParameters constant;
  constant.rule.e = 0.5;
  ggsim::Engine<1, ggsim::Effects<>> plain(s.box, s.r, s.v, constant);
  ggtest::Silent none;
  ASSERT_EQ(plain.run(200.0, ~0ull, none), ggsim::StopReason::kCollapse);
  // K such that a typical first impact (g ~ 1.5) has e ~ 0.5.
  ggsim::EngineParameters law;
  law.rule.effects.set<ggsim::ViscoelasticParameters>().k = 0.55;
  ASSERT_NEAR(ggsim::viscoelastic_epsilon(0.55 * std::pow(1.5, 0.2)), 0.5, 0.05);
  ggsim::Engine<1, Viscoelastic> eng(s.box, s.r, s.v, law);
  EXPECT_EQ(eng.run(200.0, ~0ull, none), ggsim::StopReason::kTimeReached);
  EXPECT_GT(eng.collisions(), 100 * s.r.size());
  EXPECT_LT(eng.kinetic_energy(), 0.01 * 0.5);
}

}  // namespace
