// Mixtures (Fx::kMixture; mixture.hpp): one collision of unequal particles against the
// conservation laws, equal particles against the plain engine bit for bit, and gases against
// published theory (docs/PHYSICS.md "Mixtures"): the BMCSL equation of state of an elastic binary
// mixture of spheres, equipartition at e = 1, and the temperature ratio of the homogeneous
// cooling state against Garzo & Dufty's.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "engine_harness.hpp"
#include "ggsim/engine_variants.hpp"
#include "ggsim/mixture.hpp"

namespace {

using namespace ggsim;
using Mix = Effects<MixtureEffect>;
using MixVirial = Effects<MixtureEffect, VirialEffect>;

// What the engine's sizes effect starts from, for the given sizes.
EffectRecords start_with(Sizes sizes) {
  EffectRecords records;
  ParticleSizes::add_start(std::move(sizes), records);
  return records;
}

// A mixture at number density rho in a cubic box of edge L, T = T0, from draw_sizes and the
// random start, as gg-sim draws one.
template <int D>
struct MixtureStart {
  gg::Box<D> box;
  std::vector<Vec<D>> r, v;
  Sizes sizes;
  EngineParameters par(double e) const {
    EngineParameters p;
    p.rule.e = e;
    return p;
  }
  // What the engine's sizes effect starts from.
  EffectRecords start() const { return start_with(sizes); }
};

template <int D>
MixtureStart<D> mixture_start(const MixtureSpec& spec, double L, double rho, std::uint64_t seed) {
  MixtureStart<D> s;
  std::array<double, D> edges;
  edges.fill(L);
  s.box = gg::Box<D>(edges);
  Random rng(seed);
  const auto n = static_cast<std::size_t>(std::llround(rho * std::pow(L, D)));
  s.sizes = draw_sizes(spec, n, D, rng);
  s.r = random_positions<D>(s.box, n, rng, &s.sizes);
  s.v = maxwellian_velocities<D>(s.sizes.mass, 1.0, rng);
  return s;
}

MixtureSpec binary(const std::string& radii, const std::string& masses) { return MixtureSpec::parse(radii, masses, ""); }

// The temperature of each species, T_s = sum m v^2 / (d N_s), at time t.
template <int D, class Fx>
std::vector<double> species_temperatures(const Engine<D, Fx>& eng, const Sizes& sizes, double t) {
  std::vector<double> sum(sizes.species_count), count(sizes.species_count);
  const auto o = ggtest::observed(eng, t);
  for (std::size_t i = 0; i < o.v.size(); ++i) {
    sum[sizes.species[i]] += sizes.mass[i] * dot<D>(o.v[i], o.v[i]);
    count[sizes.species[i]] += 1;
  }
  for (std::size_t s = 0; s < sum.size(); ++s) sum[s] /= D * count[s];
  return sum;
}

// a. One oblique collision of radii 0.3 and 0.8, masses 1 and 3, e = 0.7: contact at R_i + R_j,
// momentum kept, and the energy lost (1 - e^2)/2 mu (n.v_ij)^2 with mu = m_i m_j/(m_i + m_j).
TEST(Mixture, OneCollisionOfUnequalParticles) {
  const double Ra = 0.3, Rb = 0.8, ma = 1, mb = 3, e = 0.7;
  const gg::Box<2> box({20.0, 20.0});
  const std::vector<Vec<2>> r{{5.0, 5.0}, {9.0, 5.6}}, v{{1.3, 0.2}, {-0.4, -0.1}};
  EngineParameters par;
  par.rule.e = e;
  Engine<2, Mix> eng(box, r, v, par, start_with({.radius = {Ra, Rb}, .mass = {ma, mb}}));
  ggtest::Silent none;
  eng.run(kNever, 1, none);  // stops at the first collision
  ASSERT_EQ(eng.collisions(), 1u);
  const auto o = ggtest::observed(eng, eng.now());
  Vec<2> d{o.r[0][0] - o.r[1][0], o.r[0][1] - o.r[1][1]};
  const double dist = std::sqrt(dot<2>(d, d));
  EXPECT_NEAR(dist, Ra + Rb, 1e-13);
  const Vec<2> n{d[0] / dist, d[1] / dist};
  const double vn = n[0] * (v[0][0] - v[1][0]) + n[1] * (v[0][1] - v[1][1]);  // before
  for (int k = 0; k < 2; ++k) EXPECT_NEAR(ma * o.v[0][k] + mb * o.v[1][k], ma * v[0][k] + mb * v[1][k], 1e-13);
  const auto energy = [&](const std::vector<Vec<2>>& u) { return 0.5 * (ma * dot<2>(u[0], u[0]) + mb * dot<2>(u[1], u[1])); };
  const double mu = ma * mb / (ma + mb);
  EXPECT_NEAR(energy(v) - energy(o.v), 0.5 * (1 - e * e) * mu * vn * vn, 1e-13);
  // The normal relative velocity reverses with the factor e; the tangential one is kept.
  const double vn_after = n[0] * (o.v[0][0] - o.v[1][0]) + n[1] * (o.v[0][1] - o.v[1][1]);
  EXPECT_NEAR(vn_after, -e * vn, 1e-13);
}

// b. Radii 1/2 and masses 1, given explicitly: the mixture engine runs the plain engine's
// trajectory bit for bit (an inelastic gas, clusters forming), in 2D and 3D.
template <int D>
void equal_particles_as_plain(double L, double rho) {
  ggtest::expect_plain_trajectory<D, Mix>(L, rho, {}, true);
}
TEST(Mixture, EqualParticlesRunThePlainTrajectoryBitForBit2D) { equal_particles_as_plain<2>(40, 0.37); }
TEST(Mixture, EqualParticlesRunThePlainTrajectoryBitForBit3D) { equal_particles_as_plain<3>(12, 0.5); }

// The random start of a mixture: no pair closer than R_i + R_j, species counts by the fractions.
TEST(Mixture, RandomStartPlacesEveryPairApart) {
  const auto s = mixture_start<2>(MixtureSpec::parse("0.5,1.2", "", "0.8,0.2"), 60, 0.3, 5);
  std::size_t big = 0;
  for (std::size_t i = 0; i < s.r.size(); ++i) {
    big += s.sizes.species[i];
    for (std::size_t j = 0; j < i; ++j) {
      Vec<2> d;
      for (int k = 0; k < 2; ++k) d[k] = s.box.min_image(s.r[i][k] - s.r[j][k], k);
      ASSERT_GE(std::sqrt(dot<2>(d, d)), s.sizes.radius[i] + s.sizes.radius[j]);
    }
  }
  EXPECT_EQ(big, std::size_t(std::llround(0.2 * s.r.size())));
  EXPECT_EQ(s.sizes.mass.front(), s.sizes.species.front() ? std::pow(2.4, 2) : 1.0);  // by area
}

// d. Equipartition at e = 1: masses 1 and 4, radii 0.5 and 0.7, started at T_1 = 1/2, T_2 = 3/2;
// after 50 N collisions (100 per particle) the two temperatures agree (time average over 200 per particle more).
TEST(Mixture, ElasticSpeciesShareOneTemperature) {
  auto s = mixture_start<2>(binary("0.5,0.7", "1,4"), 100, 0.25, 3);
  for (std::size_t i = 0; i < s.v.size(); ++i)
    for (double& x : s.v[i]) x *= s.sizes.species[i] ? std::sqrt(1.5) : std::sqrt(0.5);
  set_temperature<2>(s.v, 1.0, s.sizes.mass);  // at rest again (zero total momentum), the ratio kept
  Engine<2, Mix> eng(s.box, s.r, s.v, s.par(1.0), s.start());
  const auto T0 = species_temperatures(eng, s.sizes, 0);
  ASSERT_NEAR(T0[1] / T0[0], 3, 0.3);
  ggtest::Silent none;
  const auto n = s.r.size();
  eng.run(kNever, 50 * n, none);
  double ratio = 0;
  const int samples = 100;
  for (int k = 1; k <= samples; ++k) {
    eng.run(kNever, (50 + k) * n, none);
    const auto T = species_temperatures(eng, s.sizes, eng.now());
    ratio += T[1] / T[0] / samples;
  }
  std::printf("T2/T1 = %.4f (N = %zu)\n", ratio, n);
  EXPECT_NEAR(ratio, 1, 0.015);
}

// c. The equation of state of an elastic binary mixture of hard spheres (diameters 1 and 1.4,
// equal numbers, packing fraction 0.3) against Boublik-Mansoori-Carnahan-Starling-Leland
// (Mansoori et al., J. Chem. Phys. 54, 1523 (1971)), from the collisional virial:
// Z = P/(n T) = 1 + sum r_ij . Delta p_i / (d N T t).
TEST(Mixture, ElasticBinarySpheresFollowBMCSL) {
  const double phi = 0.3, s1 = 1, s2 = 1.4;
  const double rho = phi / (std::numbers::pi / 6 * 0.5 * (s1 * s1 * s1 + s2 * s2 * s2));
  auto s = mixture_start<3>(binary("0.5,0.7", ""), 18, rho, 9);
  Engine<3, MixVirial> eng(s.box, s.r, s.v, s.par(1.0), s.start());
  ggtest::Silent none;
  const auto n = s.r.size();
  eng.run(kNever, 20 * n, none);
  const double virial0 = eng.effects().template get<ggsim::PressureVirial>().virial();
  const double t0 = eng.now();
  eng.run(kNever, 520 * n, none);
  const double T = 2 * eng.kinetic_energy() / 3;
  const double virial = eng.effects().template get<ggsim::PressureVirial>().virial() - virial0;
  const double Z = 1 + virial / (3.0 * static_cast<double>(n) * T * (eng.now() - t0));
  // BMCSL: xi_k = (pi/6) sum_i n_i sigma_i^k (number densities n_i, here n/2 each).
  const auto xi = [&](int k) { return std::numbers::pi / 6 * rho * 0.5 * (std::pow(s1, k) + std::pow(s2, k)); };
  const double x0 = xi(0), x1 = xi(1), x2 = xi(2), x3 = xi(3);
  const double Z_bmcsl = 1 / (1 - x3) + 3 * x1 * x2 / (x0 * (1 - x3) * (1 - x3)) +
                         (3 - x3) * x2 * x2 * x2 / (x0 * std::pow(1 - x3, 3));
  std::printf("Z = %.4f, BMCSL %.4f (phi = %.4f, N = %zu)\n", Z, Z_bmcsl, x3, n);
  EXPECT_NEAR(Z / Z_bmcsl, 1, 0.01);
}

// Garzo & Dufty, PRE 60, 5706 (1999), in the Maxwellian approximation (docs/PHYSICS.md
// "Mixtures"): the cooling rate of species i, up to a factor common to both species,
//   zeta_i ~ sum_j x_j chi_ij sigma_ij^(d-1) mu_ji (1 + e) sqrt(T_i/m_i + T_j/m_j)
//            [2 - mu_ji (1 + e) (1 + m_i T_j / (m_j T_i))],   mu_ji = m_j / (m_i + m_j),
// and the ratio T_1/T_2 of the homogeneous cooling state, where zeta_1 = zeta_2 (chi_ij = 1).
double gd_cooling_rate(int i, const double T[2], const double m[2], const double sigma[2], const double x[2], double e,
                       int d) {
  double z = 0;
  for (int j = 0; j < 2; ++j) {
    const double s = 0.5 * (sigma[i] + sigma[j]), mu = m[j] / (m[i] + m[j]);
    z += x[j] * std::pow(s, d - 1) * mu * (1 + e) * std::sqrt(T[i] / m[i] + T[j] / m[j]) *
         (2 - mu * (1 + e) * (1 + m[i] * T[j] / (m[j] * T[i])));
  }
  return z;
}

double gd_temperature_ratio(const double m[2], const double sigma[2], const double x[2], double e, int d) {
  double lo = 0.05, hi = 20;  // zeta_1 - zeta_2 changes sign once in between
  const auto gap = [&](double g) {
    const double T[2] = {g, 1};
    return gd_cooling_rate(0, T, m, sigma, x, e, d) - gd_cooling_rate(1, T, m, sigma, x, e, d);
  };
  for (int k = 0; k < 200; ++k) {
    const double mid = std::sqrt(lo * hi);
    (gap(mid) > 0) == (gap(lo) > 0) ? lo = mid : hi = mid;
  }
  return std::sqrt(lo * hi);
}

TEST(Mixture, GarzoDuftyRatioIsOneForEqualSpeciesOrElastic) {
  const double sigma[2] = {1, 1.4}, x[2] = {0.3, 0.7}, m[2] = {1, 4}, same[2] = {2, 2}, same_sigma[2] = {1, 1};
  EXPECT_NEAR(gd_temperature_ratio(m, sigma, x, 1.0, 2), 1, 1e-9);
  EXPECT_NEAR(gd_temperature_ratio(same, same_sigma, x, 0.5, 3), 1, 1e-9);
  EXPECT_LT(gd_temperature_ratio(m, sigma, x, 0.9, 2), 1);  // the lighter species is colder
}

// e. The homogeneous cooling state of a dilute inelastic binary mixture of disks (e = 0.9, equal
// radii, masses 1 and 4, equal numbers, packing fraction 0.05): T_1/T_2 settles within a few
// collisions per particle at Garzo & Dufty's ratio.
TEST(Mixture, CoolingRatioFollowsGarzoDufty) {
  const double e = 0.9, m[2] = {1, 4}, sigma[2] = {1, 1}, x[2] = {0.5, 0.5};
  const double expected = gd_temperature_ratio(m, sigma, x, e, 2);
  const double rho = 0.05 / (std::numbers::pi / 4);
  double ratio = 0;
  int samples = 0;
  for (std::uint64_t seed : {21, 22, 23, 24}) {
    auto s = mixture_start<2>(binary("0.5,0.5", "1,4"), 200, rho, seed);
    Engine<2, Mix> eng(s.box, s.r, s.v, s.par(e), s.start());
    ggtest::Silent none;
    const auto n = s.r.size();
    eng.run(kNever, 5 * n, none);  // T_1/T_2 relaxes within a few collisions per particle
    for (int k = 1; k <= 20; ++k) {
      eng.run(kNever, (5 + k) * n, none);
      const auto T = species_temperatures(eng, s.sizes, eng.now());
      ratio += T[0] / T[1], ++samples;
    }
  }
  ratio /= samples;
  std::printf("T1/T2 = %.4f, Garzo-Dufty %.4f\n", ratio, expected);
  EXPECT_NEAR(ratio / expected, 1, 0.03);
}

}  // namespace
