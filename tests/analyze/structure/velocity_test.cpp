// gg-velocity's analyses and g(r), S(k) on hand-built input whose answer is known by hand:
//  - Sonine coefficients of Gaussian velocities (zero, with errors that match their scatter) and of
//    velocities of one speed (a2 = -2/(d+2), a3 = 1 + 3 a2 - d^2/((d+2)(d+4)));
//  - f(c) and its tail fit on samples of f ~ exp(-A c^b) (b = 2: the Maxwellian; b = 1: an
//    exponential tail), A rescaled by the sample's own temperature;
//  - flow fields built by hand: a shear wave (energy fraction, longitudinal and transverse
//    correlations against the isotropic averages 2 J1(z)/z and 2 (J0 - J1/z) in 2D, 3 j1(z)/z in 3D)
//    and a Taylor-Green vortex (vorticity and enstrophy of central differences);
//  - g(r) of a square lattice (4 neighbours at r = 1) and of an ideal gas (1), S_rho of an ideal gas (1).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "correlation.hpp"
#include "gg/density_grid.hpp"
#include "pair_correlation.hpp"
#include "velocity.hpp"

namespace {

constexpr double kPi = std::numbers::pi;

std::vector<double> gaussian_velocities(std::size_t n, int d, std::mt19937_64& rng) {
  std::normal_distribution<double> g(0, 1);
  std::vector<double> v(n * d);
  for (double& x : v) x = g(rng);
  return v;
}

TEST(Sonine, GaussianVelocitiesHaveZeroCoefficientsWithinTheirErrors) {
  std::mt19937_64 rng(3);
  for (int d : {1, 2, 3}) {
    double pull2 = 0, pull3 = 0;
    const int samples = 200;
    for (int s = 0; s < samples; ++s) {
      const auto v = gaussian_velocities(2000, d, rng);
      const gg::SonineResult r = gg::sonine_coefficients(v.data(), nullptr, 2000, d);
      pull2 += std::pow(r.a2 / r.a2_stderr, 2), pull3 += std::pow(r.a3 / r.a3_stderr, 2);
      ASSERT_EQ(r.temperature.size(), static_cast<std::size_t>(d));
      EXPECT_NEAR(r.T, 1, 0.1);
    }
    // The errors are the scatter: rms pull 1 (200 samples: +- 0.05).
    EXPECT_NEAR(std::sqrt(pull2 / samples), 1, 0.15) << "d = " << d;
    EXPECT_NEAR(std::sqrt(pull3 / samples), 1, 0.15) << "d = " << d;
  }
}

TEST(Sonine, OneSpeedGivesTheCoefficientsByHand) {
  std::mt19937_64 rng(5);
  for (int d : {1, 2, 3}) {
    // Pairs +v, -v of unit speed: V = 0 and w = |v|^2 = 1 exactly, whatever the directions.
    auto v = gaussian_velocities(1000, d, rng);
    for (std::size_t i = 0; i < 500; ++i) {
      double s = 0;
      for (int k = 0; k < d; ++k) s += v[i * d + k] * v[i * d + k];
      for (int k = 0; k < d; ++k) v[i * d + k] /= std::sqrt(s), v[(i + 500) * d + k] = -v[i * d + k];
    }
    const gg::SonineResult r = gg::sonine_coefficients(v.data(), nullptr, 1000, d);
    const double a2 = -2.0 / (d + 2), a3 = 1 + 3 * a2 - double(d * d) / ((d + 2) * (d + 4));
    EXPECT_NEAR(r.a2, a2, 1e-12) << "d = " << d;
    EXPECT_NEAR(r.a3, a3, 1e-12) << "d = " << d;
    EXPECT_NEAR(r.T, 1.0 / d, 1e-12);
    EXPECT_NEAR(r.a2_stderr, 0, 1e-6);
  }
}

TEST(Sonine, MassesWeighTheTemperature) {
  // Two particles of masses 1 and 4 with momenta +-2 along x: V = 0, T_x = (4 + 1) / 2, T_y = 0.
  const std::vector<double> v = {2, 0, -0.5, 0}, m = {1, 4};
  const gg::SonineResult r = gg::sonine_coefficients(v.data(), m.data(), 2, 2);
  EXPECT_DOUBLE_EQ(r.temperature[0], 2.5);
  EXPECT_DOUBLE_EQ(r.temperature[1], 0);
}

// Velocities with speed density ~ c^(d-1) exp(-A c^b): u = A c^b is Gamma(d/b) distributed.
std::vector<double> stretched_sample(std::size_t n, int d, double A, double b, std::mt19937_64& rng) {
  std::gamma_distribution<double> gamma(d / b, 1.0);
  auto v = gaussian_velocities(n, d, rng);
  for (std::size_t i = 0; i < n; ++i) {
    double s = 0;
    for (int k = 0; k < d; ++k) s += v[i * d + k] * v[i * d + k];
    const double c = std::pow(gamma(rng) / A, 1 / b);
    for (int k = 0; k < d; ++k) v[i * d + k] *= c / std::sqrt(s);
  }
  return v;
}

TEST(SpeedDistribution, TailFitRecoversStretchedExponentials) {
  std::mt19937_64 rng(7);
  const std::vector<double> edges = gg::speed_bin_edges(0.1, 3, 20, 12);
  for (int d : {2, 3})
    for (double b : {2.0, 1.0}) {
      const double A = 1.5;
      const std::size_t n = 1000000;
      const auto v = stretched_sample(n, d, A, b, rng);
      // The tool's c is |v| / sqrt(2 T), T = <c^2> / d: so A' = A (2 <c^2> / d)^(b/2),
      // <c^2> = Gamma((d+2)/b) / Gamma(d/b) / A^(2/b).
      const double c2 = std::tgamma((d + 2) / b) / std::tgamma(d / b) / std::pow(A, 2 / b);
      const double A_scaled = A * std::pow(2 * c2 / d, b / 2);
      const gg::SpeedDistribution f = gg::speed_distribution(v.data(), nullptr, n, d, edges, 1.0);
      SCOPED_TRACE("d = " + std::to_string(d) + ", b = " + std::to_string(b));
      EXPECT_GE(f.tail_bins, 15);
      EXPECT_NEAR(f.tail_b, b, 0.03 * b);
      EXPECT_NEAR(f.tail_A, A_scaled, 0.05 * A_scaled);
      // The Maxwellian body: f = pi^(-d/2) exp(-c^2) within 2% at c = 1.05.
      if (b == 2) EXPECT_NEAR(f.f[10] / (std::pow(kPi, -d / 2.0) * std::exp(-1.05 * 1.05)), 1, 0.02);
      double total = 0;
      for (double x : f.counts) total += x;
      EXPECT_NEAR(total, n, 1);  // nothing beyond c = 12
    }
}

// Particles one per cell at the cell centres of an n^d lattice of spacing 1, velocities u(x).
struct Lattice {
  std::vector<double> r, v;
};

template <class U>
Lattice lattice(int n, int d, U u) {
  Lattice p;
  std::vector<int> idx(d, 0);
  const std::size_t N = static_cast<std::size_t>(std::pow(n, d));
  for (std::size_t i = 0; i < N; ++i) {
    std::vector<double> x(d);
    for (int k = 0; k < d; ++k) x[k] = idx[k] + 0.5;
    const std::vector<double> w = u(x);
    p.r.insert(p.r.end(), x.begin(), x.end());
    p.v.insert(p.v.end(), w.begin(), w.end());
    for (int k = d - 1; k >= 0; --k) {
      if (++idx[k] < n) break;
      idx[k] = 0;
    }
  }
  return p;
}

// The first z where g(z) falls to 1/2 (bisection after a scan).
template <class G>
double half_point(G g) {
  double lo = 0.01;
  while (g(lo + 0.01) > 0.5) lo += 0.01;
  double hi = lo + 0.01;
  for (int i = 0; i < 60; ++i) {
    const double mid = (lo + hi) / 2;
    (g(mid) > 0.5 ? lo : hi) = mid;
  }
  return lo;
}

TEST(Flow, ShearWaveIn2D) {
  const int n = 128;
  const double U = 0.7, k = 2 * kPi / n;
  const Lattice p = lattice(n, 2, [&](const std::vector<double>& x) { return std::vector<double>{U * std::sin(k * x[1]), 0}; });
  const std::size_t N = n * n;
  for (int w : {0, 1}) {
    gg::DensityGrid grid({double(n), double(n)}, {1.0, w, 0.5});
    gg::FlowAnalyzer flow(grid);
    const gg::FlowResult r = flow.compute(grid, p.r.data(), p.v.data(), nullptr, N, 0.5);
    // Block average of sin over 2w+1 rows: the factor (1 + 2 cos k) / 3 for w = 1.
    const double factor = w == 0 ? 1 : (1 + 2 * std::cos(k)) / 3;
    EXPECT_NEAR(r.energy_fraction, factor * factor, 1e-12);
    EXPECT_EQ(r.empty_fraction, 0);
    // Isotropic averages of the shear wave: C_L = 2 J1(z)/z, C_T = 2 (J0(z) - J1(z)/z), z = k r.
    const auto& radii = flow.radii();
    // (Shells of whole cells sample the directions unevenly: 0.03.)
    for (std::size_t b = 8; b < 50; ++b) {
      const double z = k * radii[b];
      EXPECT_NEAR(r.C_L[b], 2 * std::cyl_bessel_j(1.0, z) / z, 0.03) << "r = " << radii[b];
      EXPECT_NEAR(r.C_T[b], 2 * (std::cyl_bessel_j(0.0, z) - std::cyl_bessel_j(1.0, z) / z), 0.03) << "r = " << radii[b];
    }
    const double zL = half_point([](double z) { return 2 * std::cyl_bessel_j(1.0, z) / z; });
    const double zT = half_point([](double z) { return 2 * (std::cyl_bessel_j(0.0, z) - std::cyl_bessel_j(1.0, z) / z); });
    EXPECT_NEAR(r.length_L, zL / k, 0.02 * zL / k);
    EXPECT_NEAR(r.length_T, zT / k, 0.02 * zT / k);
    // A shear wave u_x(y) has vorticity -du_x/dy = -U k cos(k y) (central differences: sin(k)/k),
    // enstrophy (U sin(k) factor)^2 / 4.
    EXPECT_NEAR(r.enstrophy, std::pow(U * std::sin(k) * factor, 2) / 4, 1e-9);
  }
}

TEST(Flow, ShearWaveIn3DAndSoundWaveIn1D) {
  const int n = 32;
  const double U = 1.3, k = 2 * kPi / n;
  const Lattice p = lattice(n, 3, [&](const std::vector<double>& x) { return std::vector<double>{U * std::sin(k * x[1]), 0, 0}; });
  gg::DensityGrid grid({double(n), double(n), double(n)}, {1.0, 0, 0.5});
  gg::FlowAnalyzer flow(grid);
  const gg::FlowResult r = flow.compute(grid, p.r.data(), p.v.data(), nullptr, p.r.size() / 3, 0.5);
  EXPECT_NEAR(r.energy_fraction, 1, 1e-12);
  for (std::size_t b = 4; b < 14; ++b) {
    const double z = k * flow.radii()[b];
    EXPECT_NEAR(r.C_L[b], 3 * std::sph_bessel(1, z) / z, 0.03) << "r = " << flow.radii()[b];
    EXPECT_NEAR(r.C_T[b], 1.5 * (std::sph_bessel(0, z) - std::sph_bessel(1, z) / z), 0.03) << "r = " << flow.radii()[b];
  }
  EXPECT_NEAR(r.enstrophy, std::pow(U * std::sin(k), 2) / 4, 1e-9);

  const Lattice q = lattice(64, 1, [&](const std::vector<double>& x) { return std::vector<double>{std::sin(2 * kPi * x[0] / 64)}; });
  gg::DensityGrid line({64.0}, {1.0, 0, 0.5});
  gg::FlowAnalyzer flow1(line);
  const gg::FlowResult s = flow1.compute(line, q.r.data(), q.v.data(), nullptr, 64, 0.5);
  for (std::size_t b = 0; b < flow1.radii().size(); ++b)
    EXPECT_NEAR(s.C_L[b], std::cos(2 * kPi * flow1.radii()[b] / 64), 1e-12);
  EXPECT_NEAR(s.length_L, 64.0 / 6, 0.1);  // cos = 1/2 at r = L/6 (linear interpolation between cells)
  EXPECT_TRUE(std::isnan(s.enstrophy));
}

TEST(Flow, TaylorGreenVortex) {
  const int n = 64;
  const double U = 0.9, k = 2 * kPi / n;
  const Lattice p = lattice(n, 2, [&](const std::vector<double>& x) {
    return std::vector<double>{U * std::sin(k * x[0]) * std::cos(k * x[1]), -U * std::cos(k * x[0]) * std::sin(k * x[1])};
  });
  gg::DensityGrid grid({double(n), double(n)}, {1.0, 0, 0.5});
  gg::FlowAnalyzer flow(grid);
  const gg::FlowResult r = flow.compute(grid, p.r.data(), p.v.data(), nullptr, n * n, 0.5);
  EXPECT_NEAR(r.energy_fraction, 1, 1e-12);
  // omega = 2 U sin(kx) sin(ky) sin(k)/1 by central differences; enstrophy U^2 sin^2(k) / 2.
  const auto& omega = flow.vorticity();
  for (int i : {3, 17, 40})
    for (int j : {5, 29}) {
      const double x = i + 0.5, y = j + 0.5;
      EXPECT_NEAR(omega[i * n + j], 2 * U * std::sin(k * x) * std::sin(k * y) * std::sin(k), 1e-12);
    }
  EXPECT_NEAR(r.enstrophy, U * U * std::sin(k) * std::sin(k) / 2, 1e-12);
  EXPECT_NEAR(r.enstrophy, U * U * k * k / 2, 5e-3 * U * U * k * k);  // the continuum: sin^2(k)/k^2 = 0.997
}

TEST(Flow, EmptyCellsAreCountedAndCarryNoFlow) {
  // Two particles in a 4 x 4 grid without blocks: 14 empty cells.
  const std::vector<double> r = {0.5, 0.5, 2.5, 2.5}, v = {1, 0, -1, 0};
  gg::DensityGrid grid({4.0, 4.0}, {1.0, 0, 0.5});
  gg::FlowAnalyzer flow(grid);
  const gg::FlowResult f = flow.compute(grid, r.data(), v.data(), nullptr, 2, 0.5);
  EXPECT_DOUBLE_EQ(f.empty_fraction, 14.0 / 16);
  EXPECT_DOUBLE_EQ(f.energy_fraction, 1);
  // With 3 x 3 blocks (periodic on 4 cells) the block of cell (i, j) misses (0, 0) when i or j is 2
  // and (2, 2) when i or j is 0: only (0, 2) and (2, 0) see neither.
  gg::DensityGrid blocks({4.0, 4.0}, {1.0, 1, 0.5});
  const gg::FlowResult b = gg::FlowAnalyzer(blocks).compute(blocks, r.data(), v.data(), nullptr, 2, 0.5);
  EXPECT_DOUBLE_EQ(b.empty_fraction, 2.0 / 16);
}

TEST(PairCorrelation, SquareLatticeHasFourNeighboursAtContact) {
  for (int n : {5, 40}) {  // 5: fewer than 3 cells of r_max per side (every pair looked at)
    const Lattice p = lattice(n, 2, [](const std::vector<double>&) { return std::vector<double>{0, 0}; });
    const std::size_t N = n * n;
    const gg::RadialDistribution g = gg::radial_distribution(p.r.data(), N, {double(n), double(n)}, 2.5, 0.02);
    // g in the bin [1, 1.02): 4 neighbours of each particle, density (N - 1) / N.
    const double shell = kPi * (1.02 * 1.02 - 1);
    EXPECT_NEAR(g.g[50], 4.0 / ((N - 1.0) / N * shell), 1e-9) << "n = " << n;
    EXPECT_NEAR(g.g[70], 4.0 / ((N - 1.0) / N * kPi * (1.42 * 1.42 - 1.4 * 1.4)), 1e-9);  // sqrt 2 = 1.414
    EXPECT_EQ(g.g[49], 0);
    EXPECT_NEAR(g.r[50], 1.01, 1e-12);
  }
}

TEST(PairCorrelation, IdealGasIsOneAndSoIsItsStructureFactor) {
  std::mt19937_64 rng(11);
  for (int d : {2, 3}) {
    const double L = d == 2 ? 120 : 30;
    const std::size_t N = d == 2 ? 20000 : 30000;
    std::uniform_real_distribution<double> u(0, L);
    std::vector<double> r(N * d);
    for (double& x : r) x = u(rng);
    const std::vector<double> edges(d, L);
    const gg::RadialDistribution g = gg::radial_distribution(r.data(), N, edges, 4, 0.1);
    double mean = 0;
    for (std::size_t b = 10; b < g.g.size(); ++b) mean += g.g[b] / (g.g.size() - 10);
    EXPECT_NEAR(mean, 1, 0.01) << "d = " << d;
    gg::DensityGrid grid(edges, {1.0, 0, 0.5});
    grid.assign(r.data(), N);
    gg::Correlator c(grid);
    const std::vector<double> S = c.density_structure_factor(grid);
    EXPECT_TRUE(std::isnan(S[0]));
    double s = 0;
    for (std::size_t b = 1; b < S.size(); ++b) s += S[b] / (S.size() - 1);
    EXPECT_NEAR(s, 1, 0.03) << "d = " << d;
  }
}

TEST(PairCorrelation, ContactValueIsTheLineAtSigma) {
  gg::RadialDistribution g;
  for (int b = 0; b < 20; ++b) g.r.push_back(0.91 + 0.02 * b), g.g.push_back(g.r.back() > 1 ? 3 - 2 * g.r.back() : 0);
  EXPECT_NEAR(gg::contact_value(g, 1.0, 0.1), 1.0, 1e-12);
}

TEST(StructureFactor, StripesPeakAtTheirWaveNumber) {
  // psi = +1 in stripes 8 cells wide, period 16, along x: S peaks in the shell of k = 2 pi / 16.
  const int n = 64;
  std::vector<double> r;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      if ((i / 8) % 2 == 0) r.push_back(i + 0.5), r.push_back(j + 0.5);
  gg::DensityGrid grid({double(n), double(n)}, {1.0, 0, 0.5});
  grid.assign(r.data(), r.size() / 2);
  gg::Correlator c(grid);
  const gg::CorrelationResult res = c.compute(grid, 0.5);
  const auto& k = c.wave_numbers();
  const std::size_t peak = std::max_element(res.S.begin() + 1, res.S.end()) - res.S.begin();
  EXPECT_NEAR(k[peak], 2 * kPi / 16, 1e-12);
  EXPECT_GT(res.k1, 2 * kPi / 16 * 0.9);
  EXPECT_EQ(res.S[0], 0);
}

}  // namespace
