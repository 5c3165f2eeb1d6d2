// Rough particles (gg-sim --beta; effects/rough_particles.hpp, docs/PHYSICS.md "Rough particles") against
// their defining relations and the kinetic theory of Huthmann & Zippelius, PRE 56, R6275 (1997)
// and Luding, Huthmann, McNamara & Zippelius, PRE 58, 3416 (1998):
//  - one collision turns the contact-point velocity g into g_n' = -e g_n, g_t' = -beta g_t and
//    keeps the momentum;
//  - beta = -1 is the smooth rule bit for bit, and no particle's spin changes;
//  - e = 1, beta = 1 keeps the total energy, and a gas started without rotation reaches
//    equipartition T_rot = T_tr;
//  - the homogeneous cooling state keeps the ratio T_rot / T_tr of the Maxwellian theory.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "engine_harness.hpp"
#include "ggsim/engine_variants.hpp"

namespace {

using namespace ggsim;

using RoughOnly = Effects<RoughEffect>;

constexpr int rotations(int d) { return d == 3 ? 3 : 1; }

// (sigma/2) (w_i + w_j) x n, and the contact-point velocity g = v_ij - that.
template <int D>
Vec<D> contact_velocity(const Vec<D>& vi, const Vec<D>& vj, const Spin<D>& wi, const Spin<D>& wj, const Vec<D>& n) {
  Vec<D> g;
  for (int k = 0; k < D; ++k) g[k] = vi[k] - vj[k];
  if constexpr (D == 2) {
    const double w = 0.5 * (wi + wj);
    g[0] -= -w * n[1];
    g[1] -= w * n[0];
  } else {
    Vec<3> w;
    for (int k = 0; k < 3; ++k) w[k] = 0.5 * (wi[k] + wj[k]);
    g[0] -= w[1] * n[2] - w[2] * n[1];
    g[1] -= w[2] * n[0] - w[0] * n[2];
    g[2] -= w[0] * n[1] - w[1] * n[0];
  }
  return g;
}

template <int D>
void one_collision_has_the_defining_relations(const Vec<D>& r_ij, const Vec<D>& vi, const Vec<D>& vj,
                                              const Spin<D>& wi, const Spin<D>& wj) {
  for (const auto& [e, beta] : {std::pair{1.0, 1.0}, {0.9, 0.0}, {0.5, 0.6}, {0.8, -0.5}, {0.3, -1.0}})
    for (double q : {0.4, 0.5, 1.0}) {
      EngineParameters par;
      par.rule.e = e;
      par.rule.effects.set<RoughParameters>() = {.beta = beta, .inertia = q};
      RoughOnly::Set<D> effects(par, EffectStart{.n = 2});
      std::vector<Spin<D>>& spin = effects.template get<RoughParticles<D>>().spins();
      spin = {wi, wj};
      Particle<D> a{}, b{};
      a.v = vi, b.v = vj;
      collide<D>(a, b, 0, 1, r_ij, 0, e, effects);
      Vec<D> n;
      const double dist = std::sqrt(dot<D>(r_ij, r_ij));
      for (int k = 0; k < D; ++k) n[k] = r_ij[k] / dist;
      const Vec<D> g0 = contact_velocity<D>(vi, vj, wi, wj, n), g1 = contact_velocity<D>(a.v, b.v, spin[0], spin[1], n);
      const double gn0 = dot<D>(g0, n), gn1 = dot<D>(g1, n);
      EXPECT_NEAR(gn1, -e * gn0, 1e-13) << "e " << e << " beta " << beta << " q " << q;
      for (int k = 0; k < D; ++k) {
        EXPECT_NEAR(g1[k] - gn1 * n[k], -beta * (g0[k] - gn0 * n[k]), 1e-13) << "e " << e << " beta " << beta;
        EXPECT_NEAR(a.v[k] + b.v[k], vi[k] + vj[k], 1e-14);
      }
      // The angular momentum about the contact point: I (w_i' - w_i) = (sigma/2) (-n) x (m dv_i), so
      // each spin changes by -(2 / (q sigma)) n x dv_i, the same for both.
      Vec<D> dv;
      for (int k = 0; k < D; ++k) dv[k] = a.v[k] - vi[k];
      if constexpr (D == 2) {
        const double expected = -(2 / q) * (n[0] * dv[1] - n[1] * dv[0]);
        EXPECT_NEAR(spin[0] - wi, expected, 1e-13);
        EXPECT_NEAR(spin[1] - wj, expected, 1e-13);
      } else {
        const Vec<3> expected{-(2 / q) * (n[1] * dv[2] - n[2] * dv[1]), -(2 / q) * (n[2] * dv[0] - n[0] * dv[2]),
                              -(2 / q) * (n[0] * dv[1] - n[1] * dv[0])};
        for (int k = 0; k < 3; ++k) {
          EXPECT_NEAR(spin[0][k] - wi[k], expected[k], 1e-13);
          EXPECT_NEAR(spin[1][k] - wj[k], expected[k], 1e-13);
        }
      }
    }
}

TEST(Rough, OneCollisionTurnsTheContactVelocity2D) {
  one_collision_has_the_defining_relations<2>({0.6, -0.8}, {-1.3, 0.7}, {0.4, -0.2}, 0.9, -2.1);
}
TEST(Rough, OneCollisionTurnsTheContactVelocity3D) {
  one_collision_has_the_defining_relations<3>({0.48, -0.6, 0.64}, {-1.3, 0.7, 0.2}, {0.4, -0.2, -0.9},
                                              {0.9, -2.1, 0.3}, {-0.5, 1.1, 1.7});
}

// Angular velocities of a Maxwellian at rotational temperature T (I <w_k^2> = T).
template <int D>
std::vector<Spin<D>> maxwellian_spins(std::size_t n, double T, double q, std::uint64_t seed) {
  Random rng(seed);
  std::vector<Spin<D>> w(n);
  const double sd = std::sqrt(T / moment_of_inertia(q));
  for (auto& x : w) {
    if constexpr (D == 3) for (double& c : x) c = sd * rng.normal();
    else x = sd * rng.normal();
  }
  return w;
}

template <int D, class Fx>
double rotational_energy(const Engine<D, Fx>& eng) {
  return eng.effects().template get<RoughParticles<D>>().rotational_energy();
}

// Translational and rotational temperature, 2 E / (degrees of freedom).
template <int D, class Fx>
std::pair<double, double> temperatures(const Engine<D, Fx>& eng) {
  return {2 * eng.kinetic_energy() / D, 2 * rotational_energy(eng) / rotations(D)};
}

// Runs `eng` to `to` collisions per particle in steps of one, T_rot / T_tr averaged over the steps
// from `from` on.
template <int D, class Fx>
double mean_ratio(Engine<D, Fx>& eng, int from, int to) {
  ggtest::Silent none;
  double ratio = 0;
  for (int step = 1; step <= to; ++step) {
    eng.run(kNever, static_cast<std::uint64_t>(0.5 * step * static_cast<double>(eng.size())), none);
    const auto [Ttr, Trot] = temperatures(eng);
    if (step >= from) ratio += Trot / Ttr;
  }
  return ratio / (to - from + 1);
}

template <int D, class Fx>
std::vector<Spin<D>> spins(const Engine<D, Fx>& eng) {
  std::vector<Spin<D>> w(eng.size());
  eng.for_each_labelled(eng.effects().template get<RoughParticles<D>>().spins(),
                        [&](std::uint32_t i, const Spin<D>& x) { w[i] = x; });
  return w;
}

template <int D>
void smooth_when_beta_is_minus_one(double L, double rho) {
  const auto s = ggtest::random_start<D>(L, rho, 5);
  const auto w0 = maxwellian_spins<D>(s.r.size(), 1.0, default_inertia(D), 9);
  EngineParameters par;
  par.rule.e = 0.5;
  par.rule.effects.set<RoughParameters>().beta = -1;
  par.rule.effects.set<RoughParameters>().inertia = default_inertia(D);
  Engine<D, Effects<>> smooth(s.box, s.r, s.v, par);
  EffectRecords start;
  start.real["spin"] = flatten_spins<D>(w0);
  Engine<D, RoughOnly> rough(s.box, s.r, s.v, par, start);
  ggtest::Silent none;
  const auto budget = static_cast<std::uint64_t>(10 * s.r.size());  // 20 collisions per particle
  smooth.run(kNever, budget, none);
  rough.run(kNever, budget, none);
  ASSERT_EQ(smooth.collisions(), rough.collisions());
  ASSERT_EQ(smooth.now(), rough.now());
  const auto a = ggtest::observed(smooth, smooth.now()), b = ggtest::observed(rough, rough.now());
  const auto w = spins(rough);
  for (std::size_t i = 0; i < s.r.size(); ++i) {
    for (int k = 0; k < D; ++k) {
      ASSERT_EQ(a.r[i][k], b.r[i][k]) << "particle " << i;
      ASSERT_EQ(a.v[i][k], b.v[i][k]) << "particle " << i;
    }
    ASSERT_EQ(w[i], w0[i]) << "particle " << i;
  }
}

TEST(Rough, BetaMinusOneIsTheSmoothRuleBitForBit2D) { smooth_when_beta_is_minus_one<2>(40, 0.37); }
TEST(Rough, BetaMinusOneIsTheSmoothRuleBitForBit3D) { smooth_when_beta_is_minus_one<3>(12, 0.5); }

// e = 1, beta = 1 from translation alone: the total energy and momentum stay, and the
// rotational temperature comes up to the translational one.
template <int D>
Engine<D, RoughOnly> rough_gas(double L, double rho, double e, double beta, std::uint64_t seed) {
  const auto s = ggtest::random_start<D>(L, rho, seed);
  EngineParameters par;
  par.rule.e = e;
  par.rule.effects.set<RoughParameters>().beta = beta;
  par.rule.effects.set<RoughParameters>().inertia = default_inertia(D);
  return Engine<D, RoughOnly>(s.box, s.r, s.v, par);
}

template <int D>
void perfectly_rough_elastic_gas(double L, double rho) {
  auto eng = rough_gas<D>(L, rho, 1, 1, 3);
  const double E0 = eng.kinetic_energy() + rotational_energy(eng);
  // 20 collisions per particle to relax, then 40 more.
  const double ratio = mean_ratio(eng, 21, 60);
  EXPECT_NEAR((eng.kinetic_energy() + rotational_energy(eng)) / E0 - 1, 0, 1e-12);
  double abs_sum = 0;
  for (double p : ggtest::total_momentum(eng, &abs_sum)) EXPECT_LT(std::abs(p), 1e-12 * abs_sum);
  EXPECT_NEAR(ratio, 1, 0.02);
  std::printf("%dD, e = beta = 1: T_rot / T_tr = %.4f, energy drift %.2g\n", D, ratio,
              (eng.kinetic_energy() + rotational_energy(eng)) / E0 - 1);
}

TEST(Rough, PerfectlyRoughElasticGasKeepsEnergyAndReachesEquipartition2D) {
  perfectly_rough_elastic_gas<2>(std::sqrt(8000 / 0.05), 0.05);
}
TEST(Rough, PerfectlyRoughElasticGasKeepsEnergyAndReachesEquipartition3D) {
  perfectly_rough_elastic_gas<3>(std::cbrt(4000 / 0.08), 0.08);
}

// The steady T_rot / T_tr of a homogeneous cooling gas in the Maxwellian mean field (docs/PHYSICS.md
// "Rough particles"): per collision, with r = T_rot / T_tr, a = d - 1 tangential directions and
// k = q (1 + beta) / (1 + q),
//   <dE_tr> / T_tr = -(1 - e^2) - k a + (k^2 a / 2)(1 + r/q),
//   <dE_rot> / T_tr = a [-k r/q + (k^2 / (2q))(1 + r/q)],
// and the ratio stays where d <dE_rot> = d_rot r <dE_tr>: a quadratic in r, of which one root is positive.
double steady_ratio(int d, double e, double beta, double q) {
  const double a = d - 1, dr = rotations(d), k = q * (1 + beta) / (1 + q);
  const double c2 = dr * k * k * a / (2 * q);
  const double c1 = dr * (-(1 - e * e) - k * a + k * k * a / 2) - d * a * (-k / q + k * k / (2 * q * q));
  const double c0 = -d * a * k * k / (2 * q);
  return (-c1 + std::sqrt(c1 * c1 - 4 * c2 * c0)) / (2 * c2);
}

TEST(Rough, SteadyRatioOfTheTheoryHasItsLimits) {
  // Equipartition for e = beta = 1 (the energy is then conserved), in 2D and 3D and for any q.
  for (int d : {2, 3})
    for (double q : {0.4, 0.5, 1.0}) EXPECT_NEAR(steady_ratio(d, 1, 1, q), 1, 1e-12);
  // Luding et al.'s 3D equations dT_tr/dt = G [-A T_tr + B T_rot] T_tr^(1/2), dT_rot/dt =
  // G [B T_tr - C T_rot] T_tr^(1/2) keep r where -A + B r = B / r - C, eta = q (1 + beta) / (2 (1 + q)).
  const double e = 0.8, beta = 0.3, q = 0.4, eta = q * (1 + beta) / (2 * (1 + q));
  const double A = (1 - e * e) / 4 + eta * (1 - eta), B = eta * eta / q, C = (eta / q) * (1 - eta / q);
  const double r = (A - C + std::sqrt((A - C) * (A - C) + 4 * B * B)) / (2 * B);
  EXPECT_NEAR(steady_ratio(3, e, beta, q), r, 1e-12);
}

// A dilute gas (packing fraction ~0.04) cooling from T_tr = 1 without rotation: T_rot / T_tr,
// averaged over 10 to 40 collisions per particle (past the transient of a few collisions, before
// the shear and clustering instabilities), against steady_ratio(). The Maxwellian mean field
// holds to 2.5% for these weakly dissipative cases; where the tangential loss is larger
// (beta ~ 0, or e = 0.9) the measured ratio falls up to 7% below it (docs/PHYSICS.md "Rough
// particles").
template <int D>
double measured_steady_ratio(double L, double rho, double e, double beta) {
  auto eng = rough_gas<D>(L, rho, e, beta, 17);
  return mean_ratio(eng, 10, 40);
}

TEST(Rough, HomogeneousCoolingStateKeepsTheTheoreticalRatio2D) {
  const double L = std::sqrt(10000 / 0.05);
  for (const auto& [e, beta] : {std::pair{0.95, 0.8}, {0.97, 0.7}, {0.99, 0.9}}) {
    const double theory = steady_ratio(2, e, beta, 0.5);
    const double measured = measured_steady_ratio<2>(L, 0.05, e, beta);
    EXPECT_NEAR(measured / theory, 1, 0.03) << "e " << e << " beta " << beta << " theory " << theory;
    std::printf("e = %g, beta = %g: T_rot / T_tr = %.4f, theory %.4f\n", e, beta, measured, theory);
  }
}
TEST(Rough, HomogeneousCoolingStateKeepsTheTheoreticalRatio3D) {
  const double theory = steady_ratio(3, 0.95, 0.8, 0.4);
  const double measured = measured_steady_ratio<3>(std::cbrt(8000 / 0.08), 0.08, 0.95, 0.8);
  EXPECT_NEAR(measured / theory, 1, 0.03) << theory;
  std::printf("3D, e = 0.95, beta = 0.8: T_rot / T_tr = %.4f, theory %.4f\n", measured, theory);
}

}  // namespace
