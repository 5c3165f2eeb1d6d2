// gg-correlate's analysis (analyze/structure/correlation): C(r) of stripes against the analytic triangle
// (trapezoid) wave, l_C, the FFT against the direct sum, homogeneous decay.
#include <gtest/gtest.h>

#include <cmath>

#include "correlation.hpp"
#include "density_grid_fixtures.hpp"

namespace gg {
namespace {

// Stripes normal to axis 0: cells with (i0 mod (a+b)) < a are rich (`per` particles each), the next
// b cells empty. With w = 1 and a, b >= 2, psi is exactly the stripe pattern (edge cells see 2 of 3
// rich rows: 2/3 > 0.5; their poor neighbours 1/3).
DensityGrid stripes(int d, double L, double grid, int a, int b, int per = 1, int w = 1) {
  return test::make_grid(d, L, {grid, w, 0.5}, [=](const test::Cell& c) { return c[0] % (a + b) < a ? per : 0; });
}

// Analytic C of a periodic square wave (widths a, b cells, values +1/-1) at a shift of s cells:
// the fraction of mismatched pairs is 2 min(s', a, b) / P, s' = distance to the nearest multiple of P;
// <psi psi(s)> = 1 - 2 mismatch, <psi> = (a - b) / P; C = (<psi psi(s)> - <psi>^2) / (1 - <psi>^2).
// For a = b it is the triangle wave 1 - 4 s' / P.
double square_wave_C(int s, int a, int b) {
  const int P = a + b;
  const int sp = test::ring_distance(s, 0, P);
  const double mismatch = 2.0 * std::min({sp, a, b}) / P;
  const double m = double(a - b) / P;
  return (1 - 2 * mismatch - m * m) / (1 - m * m);
}

TEST(Correlation, StripesAlongTheNormalFollowTheTriangleWave) {
  const int a = 6, b = 6, n = 48;
  const auto g = stripes(2, n, 1.0, a, b);
  Correlator corr(g);
  const auto& f = corr.field(g);
  for (int s = 0; s < n; ++s) {
    EXPECT_NEAR(f[s * n], 1.0 - 4.0 * test::ring_distance(s, 0, a + b) / (a + b), 1e-12) << s;  // normal
    EXPECT_NEAR(f[s], 1.0, 1e-12) << s;                                                        // along stripes
  }
}

TEST(Correlation, UnequalStripesFollowTheTrapezoidWave) {
  const int a = 4, b = 12, n = 64;
  const auto g = stripes(2, n, 1.0, a, b);
  Correlator corr(g);
  const auto& f = corr.field(g);
  for (int s = 0; s < n; ++s) EXPECT_NEAR(f[s * n], square_wave_C(s, a, b), 1e-12) << s;
  EXPECT_NEAR(f[8 * n], -1.0 / 3.0, 1e-12);  // hand value: s = P/2, mismatch 1/2, <psi>^2 = 1/4
}

TEST(Correlation, OneDimensionShellAverageAndLengthMatchTheAnalyticWave) {
  // 1D: the shell average is the wave itself (shells of +-s). a = b = 6: C = 1 - s/3, so
  // C = 0.5 at s = 1.5 cells, C = 0.25 at 2.25.
  const auto g = stripes(1, 48, 1.0, 6, 6);
  Correlator corr(g);
  const auto r = corr.compute(g, 0.5);
  ASSERT_EQ(r.C.size(), 25u);  // shells 0 .. n/2
  for (std::size_t s = 0; s < r.C.size(); ++s) {
    EXPECT_DOUBLE_EQ(r.r[s], double(s));
    EXPECT_NEAR(r.C[s], square_wave_C(int(s), 6, 6), 1e-12) << s;
  }
  EXPECT_NEAR(r.length, 1.5, 1e-12);
  EXPECT_NEAR(corr.compute(g, 0.25).length, 2.25, 1e-12);

  // Unequal widths a = 4, b = 12: C = 1 - s/3 for s <= 4 as well, so again 1.5.
  const auto g2 = stripes(1, 64, 1.0, 4, 12);
  Correlator corr2(g2);
  EXPECT_NEAR(corr2.compute(g2, 0.5).length, 1.5, 1e-12);
}

TEST(Correlation, LengthIsInUnitsOfSigmaNotCells) {
  // grid = 2: same 48-cell pattern in a box of 96 (2 particles per cell of length 2: density 1);
  // l_C doubles to 3.
  const auto g = stripes(1, 96, 2.0, 6, 6, 2);
  Correlator corr(g);
  const auto r = corr.compute(g, 0.5);
  EXPECT_DOUBLE_EQ(r.r[1], 2.0);
  EXPECT_NEAR(r.length, 3.0, 1e-12);
}

TEST(Correlation, FftMatchesTheDirectSumAndShellRule) {
  // 2D stripes plus a patch (not separable): FFT result vs <psi(y) psi(y+x)> - <psi>^2 summed directly,
  // shells |x| rounded to the nearest cell.
  const int n = 24;
  const auto g = test::make_grid(2, n, {}, [](const test::Cell& c) {
    return c[0] % 8 < 3 || (c[0] >= 12 && c[0] < 18 && c[1] >= 4 && c[1] < 12) ? 1 : 0;
  });
  const auto& psi = g.psi();
  double mean = 0;
  for (auto p : psi) mean += p;
  mean /= psi.size();
  std::vector<double> direct(n * n);
  for (int x0 = 0; x0 < n; ++x0)
    for (int x1 = 0; x1 < n; ++x1) {
      double s = 0;
      for (int y0 = 0; y0 < n; ++y0)
        for (int y1 = 0; y1 < n; ++y1) s += psi[y0 * n + y1] * psi[((y0 + x0) % n) * n + (y1 + x1) % n];
      direct[x0 * n + x1] = s / (n * n) - mean * mean;
    }
  std::vector<double> shell(n / 2 + 1, 0.0), count(n / 2 + 1, 0.0);
  for (int x0 = 0; x0 < n; ++x0)
    for (int x1 = 0; x1 < n; ++x1) {
      const int d0 = test::ring_distance(x0, 0, n), d1 = test::ring_distance(x1, 0, n);
      const long b = std::lround(std::sqrt(double(d0 * d0 + d1 * d1)));
      if (b <= n / 2) {
        shell[b] += direct[x0 * n + x1] / direct[0];
        count[b] += 1;
      }
    }
  Correlator corr(g);
  const auto& f = corr.field(g);
  for (int c = 0; c < n * n; ++c) ASSERT_NEAR(f[c], direct[c] / direct[0], 1e-12) << c;
  const auto r = corr.compute(g, 0.5);
  ASSERT_EQ(r.C.size(), shell.size());
  for (std::size_t b = 0; b < shell.size(); ++b) EXPECT_NEAR(r.C[b], shell[b] / count[b], 1e-12) << b;
  for (std::size_t b = 0; b < shell.size(); ++b) shell[b] /= count[b];
  EXPECT_NEAR(r.length, crossing_length(r.r, shell, 0.5), 1e-12);
  EXPECT_GT(r.length, 1.0);  // a real crossing, not the fallback
}

TEST(Correlation, HomogeneousRandomDecaysToZeroWithinAFewCells) {
  // Uniform random, rho = 0.37: psi is correlated only through overlapping 3x3 blocks (|x| <= 2 cells
  // along an axis, 2 diagonally), so C must vanish (to noise) from r = 4 on.
  const auto g = test::random_grid_2d(256, 0.37, 99);
  Correlator corr(g);
  const auto r = corr.compute(g, 0.5);
  EXPECT_DOUBLE_EQ(r.C[0], 1.0);
  EXPECT_LT(r.C[1], 0.5);  // measured 0.38
  EXPECT_LT(r.C[3], 0.1);
  for (std::size_t b = 4; b < r.C.size(); ++b) EXPECT_LT(std::abs(r.C[b]), 0.01) << b;
  EXPECT_LT(r.length, 1.0);  // measured 0.81
}

TEST(Correlation, ThreeDimensionsIsTheSameCode) {
  // 3D slabs a = b = 4 normal to axis 0 (L = 16): the triangle wave along the normal, 1 along the slabs.
  const auto g = stripes(3, 16, 1.0, 4, 4);
  Correlator corr(g);
  const auto& f = corr.field(g);
  for (int s = 0; s < 16; ++s) {
    EXPECT_NEAR(f[s * 256], 1.0 - 4.0 * test::ring_distance(s, 0, 8) / 8, 1e-12) << s;
    EXPECT_NEAR(f[s * 16 + s], 1.0, 1e-12) << s;  // a shift within the slab plane
  }
}

TEST(Correlation, UniformPsiHasNoCorrelationAndNoLength) {
  const auto g = test::make_grid(2, 16, {}, [](const test::Cell&) { return 0; });
  Correlator corr(g);
  const auto r = corr.compute(g, 0.5);
  EXPECT_TRUE(std::isnan(r.C[1]));
  EXPECT_TRUE(std::isnan(r.length));
}

TEST(Correlation, PlansAreReusedAcrossFramesWithoutMemory) {
  // The same Correlator on frame A, then B, then A again: A's result must come back bit for bit.
  const auto a = stripes(2, 32, 1.0, 4, 4);
  const auto b = stripes(2, 32, 1.0, 2, 14);
  Correlator corr(a);
  const auto first = corr.compute(a, 0.5);
  const auto other = corr.compute(b, 0.5);
  const auto again = corr.compute(a, 0.5);
  EXPECT_EQ(first.C, again.C);
  EXPECT_NE(first.C, other.C);
}

TEST(Correlation, CrossingLengthInterpolatesLinearly) {
  const std::vector<double> r = {0, 1, 2, 3};
  EXPECT_DOUBLE_EQ(crossing_length(r, {1.0, 0.8, 0.4, 0.1}, 0.5), 1.75);
  EXPECT_DOUBLE_EQ(crossing_length(r, {1.0, 0.5, 0.4, 0.1}, 0.5), 1.0);  // exactly a at a shell
  EXPECT_TRUE(std::isnan(crossing_length(r, {1.0, 0.9, 0.8, 0.7}, 0.5)));  // never falls to a
}

TEST(Correlation, ThreeDimensionsShellAverageIsTheSphericalMeanOfTheTriangleWave) {
  // The slabs above (a = b = 4, L = 16): C(x) = 1 - |x_0'|/2 with x_0' the periodic distance along
  // the normal, in units of the period 8, i.e. the triangle wave of axis 0 alone. The spherical
  // average of shell b is its mean over the cells with round(|x|) = b, |x| <= 8 - summed here
  // directly from the formula, not through an FFT. Slabs normal to axis 2 must give the same shells.
  std::vector<double> sum(9, 0.0), count(9, 0.0);
  for (int i = 0; i < 16; ++i)
    for (int j = 0; j < 16; ++j)
      for (int k = 0; k < 16; ++k) {
        const int di = test::ring_distance(i, 0, 16), dj = test::ring_distance(j, 0, 16), dk = test::ring_distance(k, 0, 16);
        const long b = std::lround(std::sqrt(double(di * di + dj * dj + dk * dk)));
        if (b > 8) continue;
        sum[b] += square_wave_C(i, 4, 4);
        count[b] += 1;
      }
  const auto normal_to_0 = stripes(3, 16, 1.0, 4, 4);
  const auto normal_to_2 = test::make_grid(3, 16, {1.0, 1, 0.5}, [](const test::Cell& c) { return c[2] % 8 < 4 ? 1 : 0; });
  for (const DensityGrid* g : {&normal_to_0, &normal_to_2}) {
    Correlator corr(*g);
    const auto r = corr.compute(*g, 0.5);
    ASSERT_EQ(r.C.size(), 9u);
    for (int b = 0; b <= 8; ++b) {
      EXPECT_DOUBLE_EQ(r.r[b], b);
      EXPECT_NEAR(r.C[b], sum[b] / count[b], 1e-12) << b;
    }
    EXPECT_GT(r.length, 1.0);
    EXPECT_LT(r.length, 4.0);
  }
}

}  // namespace
}  // namespace gg
