// Inelastic disks and rods against exact results and Haff's law (docs/PHYSICS.md):
//  - each collision removes exactly (1 - e^2)/4 (n.v_ij)^2 and conserves momentum;
//  - from elastic equilibrium, dT/dt(0) = -(1 - e^2) omega0 T0 / 2 (Haff 1983, Enskog omega0);
//  - below the clustering instability T(t) = T0 / (1 + t/t0)^2, t0 = 4 / ((1 - e^2) omega0).
#include <gtest/gtest.h>

#include <cstdio>
#include <numbers>
#include <utility>

#include "engine_harness.hpp"

namespace {

constexpr double kOmega0 = 2.2739;  // Enskog, rho = 0.37, T = 1 (docs/PHYSICS.md)

using Plain = ggsim::Effects<>;

// Elastic equilibrium at rho = 0.37, T = 1, in a box of edge L.
ggtest::Start<2> equilibrium(double L, std::uint64_t seed) { return ggtest::equilibrium<2>(L, 0.37, seed); }

TEST(Cooling, OneCollisionRemovesExactlyTheTheoreticalEnergy) {
  // Two disks on an oblique course; the loss depends only on the normal relative speed.
  gg::Box<2> box({20.0, 20.0});
  std::vector<ggsim::Vec<2>> r{{5.0, 5.0}, {8.0, 5.7}}, v{{1.3, 0.2}, {-0.4, -0.1}};
  for (double e : {0.0, 0.3, 0.9}) {
    ggsim::EngineParameters par;
    par.rule.e = e;
    ggsim::Engine<2, Plain> eng(box, r, v, par);
    const double E0 = 2 * eng.kinetic_energy();
    ggtest::Silent none;
    eng.run(ggsim::kNever, 1, none);
    ASSERT_EQ(eng.collisions(), 1u);
    // Reconstruct the contact normal from the positions at the collision.
    const auto o = ggtest::observed(eng, eng.now());
    const auto &a = o.r[0], &b = o.r[1];
    const double nx = a[0] - b[0], ny = a[1] - b[1], d = std::hypot(nx, ny);
    EXPECT_NEAR(d, 1.0, 1e-12);
    const double vn = ((v[0][0] - v[1][0]) * nx + (v[0][1] - v[1][1]) * ny) / d;
    const double loss = (1 - e * e) / 4 * vn * vn;
    EXPECT_NEAR(E0 - 2 * eng.kinetic_energy(), loss, 1e-13);
    const auto& p = o.v[0];
    const auto& q = o.v[1];
    EXPECT_NEAR(p[0] + q[0], v[0][0] + v[1][0], 1e-15);
    EXPECT_NEAR(p[1] + q[1], v[0][1] + v[1][1], 1e-15);
  }
}

TEST(Cooling, InitialCoolingRateIsHaffWithEnskogFrequency) {
  const double e = 0.5, t0 = 4 / ((1 - e * e) * kOmega0);
  auto s = equilibrium(std::sqrt(65536 / 0.37), 11);
  ggsim::EngineParameters par;
  par.rule.e = e;
  ggsim::Engine<2, Plain> eng(s.box, s.r, s.v, par);
  ggtest::EnergyAt obs;
  const double t1 = 0.05 * t0;
  obs.times = {t1};
  eng.run(t1, ~0ull, obs);
  ASSERT_EQ(obs.energy.size(), 1u);
  // T(t1) against Haff at t1 << t0: a comparison of the initial slope, curvature included.
  const double drop = 1 - obs.energy[0], drop_haff = 1 - 1 / std::pow(1 + t1 / t0, 2);
  EXPECT_NEAR(drop / drop_haff, 1.0, 0.03);
  double abs_sum = 0;
  for (double p : ggtest::total_momentum(eng, &abs_sum)) EXPECT_LT(std::abs(p), 1e-12 * abs_sum);
}

TEST(Cooling, SmallBoxFollowsHaffsLawUpToT0) {
  // L = 15 is below both instability lengths at e = 0.9 (L_perp = 21, L_par = 46), so the gas
  // stays homogeneous; an ensemble of 200 runs tames the noise of N = 83 (to ~0.8% at t0). Measured
  // T / T_Haff = 0.999, 1.011, 1.022 at t0 / 4, t0 / 2, t0; held to 5%: a cooling rate off by 7%
  // fails (T(t0) / T_Haff = 4 / (1 + k)^2 for a rate k times Haff's).
  const double e = 0.9, t0 = 4 / ((1 - e * e) * kOmega0);
  std::vector<double> times{0.25 * t0, 0.5 * t0, t0};
  std::vector<double> mean(times.size(), 0.0);
  const int runs = 200;
  for (int k = 0; k < runs; ++k) {
    auto s = equilibrium(15.0, 100 + k);
    ggsim::EngineParameters par;
    par.rule.e = e;
    ggsim::Engine<2, Plain> eng(s.box, s.r, s.v, par);
    ggtest::EnergyAt obs;
    obs.times = times;
    const auto why = eng.run(t0, ~0ull, obs);
    ASSERT_EQ(why, ggsim::StopReason::kTimeReached);
    for (std::size_t j = 0; j < times.size(); ++j) mean[j] += obs.energy[j] / runs;
    EXPECT_GE(ggtest::min_distance(eng, eng.now()), 1 - ggsim::kOverlapTolerance);
  }
  for (std::size_t j = 0; j < times.size(); ++j) {
    const double haff = 1 / std::pow(1 + times[j] / t0, 2);
    std::printf("t = %.3g t0: T / T_Haff = %.4f\n", times[j] / t0, mean[j] / haff);
    EXPECT_NEAR(mean[j] / haff, 1.0, 0.05) << "t = " << times[j];
    EXPECT_LT(mean[j], j == 0 ? 1.0 : mean[j - 1]);  // it does cool
  }
}

TEST(Cooling, EnergyNeverRisesAndMomentumStaysZero) {
  auto s = ggtest::random_start<2>(40.0, 0.37, 5);
  ggsim::EngineParameters par;
  par.rule.e = 0.7;
  ggsim::Engine<2, Plain> eng(s.box, s.r, s.v, par);
  ggtest::EnergyAt obs;
  for (int k = 0; k < 50; ++k) obs.times.push_back(0.5 * k);
  eng.run(25.0, ~0ull, obs);
  ASSERT_EQ(obs.energy.size(), 50u);
  for (std::size_t k = 1; k < obs.energy.size(); ++k) EXPECT_LE(obs.energy[k], obs.energy[k - 1]);
  double abs_sum = 0;
  for (double p : ggtest::total_momentum(eng, &abs_sum)) EXPECT_LT(std::abs(p), 1e-12 * abs_sum);
  EXPECT_GE(ggtest::min_distance(eng, eng.now()), 1 - ggsim::kOverlapTolerance);
}

}  // namespace
