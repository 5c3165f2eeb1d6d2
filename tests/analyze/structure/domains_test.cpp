// gg-domains' analysis (analyze/structure/domains): stripes give domain lengths exactly a or b.
#include <gtest/gtest.h>

#include <cmath>

#include "domains.hpp"
#include "gg/errors.hpp"
#include "density_grid_fixtures.hpp"

namespace gg {
namespace {

DensityGrid stripes(int d, double L, double grid, int a, int b, int per = 1) {
  return test::make_grid(d, L, {grid, 1, 0.5}, [=](const test::Cell& c) { return c[0] % (a + b) < a ? per : 0; });
}

TEST(Domains, StripesGiveLengthsExactlyAOrB) {
  // a = 4, b = 12 in L = 64: 4 periods on each of the 64 lines along axis 0; the 64 lines along
  // axis 1 lie inside one stripe and hold no interface.
  const auto g = stripes(2, 64, 1.0, 4, 12);
  const auto both = measure_domains(g, Phase::both);
  EXPECT_EQ(both.count, 2 * 4 * 64);
  ASSERT_EQ(both.histogram.size(), 63u);  // lengths 1 .. 63 cells
  for (std::size_t j = 0; j < both.histogram.size(); ++j) {
    const int len = static_cast<int>(j) + 1;
    EXPECT_DOUBLE_EQ(both.histogram[j], len == 4 || len == 12 ? 0.5 : 0.0) << len;
  }
  EXPECT_DOUBLE_EQ(both.length, 8.0);

  const auto rich = measure_domains(g, Phase::rich);
  EXPECT_EQ(rich.count, 4 * 64);
  EXPECT_DOUBLE_EQ(rich.histogram[3], 1.0);
  EXPECT_DOUBLE_EQ(rich.length, 4.0);
  const auto poor = measure_domains(g, Phase::poor);
  EXPECT_DOUBLE_EQ(poor.histogram[11], 1.0);
  EXPECT_DOUBLE_EQ(poor.length, 12.0);
}

TEST(Domains, HistogramIsADensityInBinsOfOneSpacing) {
  // grid = 2: the same pattern in a box of 128; lengths 8 and 24, P = 0.5 / h in their bins.
  const auto g = stripes(2, 128, 2.0, 4, 12, 4);
  const auto r = measure_domains(g, Phase::both);
  EXPECT_DOUBLE_EQ(r.bin_edges[0], 1.0);
  EXPECT_DOUBLE_EQ(r.bin_edges[1], 3.0);  // (j - 1/2) h
  EXPECT_DOUBLE_EQ(r.histogram[3], 0.25);  // bin [7, 9)
  EXPECT_DOUBLE_EQ(r.histogram[11], 0.25);
  double integral = 0;
  for (std::size_t j = 0; j < r.histogram.size(); ++j) integral += r.histogram[j] * (r.bin_edges[j + 1] - r.bin_edges[j]);
  EXPECT_DOUBLE_EQ(integral, 1.0);
  EXPECT_DOUBLE_EQ(r.length, 16.0);
}

TEST(Domains, OneDimensionPeriodicRuns) {
  // w = 0, 1 particle per rich cell, L = 16: runs rich 3 (cells 14, 15, 0), poor 2, rich 5, poor 6.
  const auto g = test::make_grid(1, 16, {1.0, 0, 0.5}, [](const test::Cell& c) {
    const int i = c[0];
    return i == 14 || i == 15 || i == 0 || (i >= 3 && i <= 7) ? 1 : 0;
  });
  const auto both = measure_domains(g, Phase::both);
  EXPECT_EQ(both.count, 4);
  EXPECT_DOUBLE_EQ(both.length, (3 + 2 + 5 + 6) / 4.0);
  EXPECT_DOUBLE_EQ(both.histogram[1], 0.25);  // length 2
  EXPECT_DOUBLE_EQ(both.histogram[2], 0.25);  // length 3 (across the boundary)
  const auto rich = measure_domains(g, Phase::rich);
  EXPECT_DOUBLE_EQ(rich.length, 4.0);
  const auto poor = measure_domains(g, Phase::poor);
  EXPECT_DOUBLE_EQ(poor.length, 4.0);
  EXPECT_EQ(poor.count, 2);
}

TEST(Domains, RowsAndColumnsBothCount) {
  // A 6x6 patch (2 per cell, w = 1) at cells 10..15 -> rich cells (see cluster_test.cpp): rows 11..14
  // span 8 cells (9..16), rows 10 and 15 span 6 (10..15), the halo rows 9 and 16 span 4 (11..14).
  // 8 rows with one rich and one poor domain each; the same for columns.
  const auto g = test::make_grid(2, 32, {}, [](const test::Cell& c) {
    return c[0] >= 10 && c[0] < 16 && c[1] >= 10 && c[1] < 16 ? 2 : 0;
  });
  const auto r = measure_domains(g, Phase::rich);
  EXPECT_EQ(r.count, 2 * 8);
  EXPECT_DOUBLE_EQ(r.length, (4 * 8 + 2 * 6 + 2 * 4) / 8.0);
  const auto p = measure_domains(g, Phase::poor);
  EXPECT_DOUBLE_EQ(p.length, (4 * 24 + 2 * 26 + 2 * 28) / 8.0);
}

TEST(Domains, NoInterfaceMeansNoDomain) {
  const auto g = test::make_grid(2, 16, {}, [](const test::Cell&) { return 0; });
  const auto r = measure_domains(g, Phase::both);
  EXPECT_EQ(r.count, 0);
  EXPECT_TRUE(std::isnan(r.length));
  for (double p : r.histogram) EXPECT_EQ(p, 0.0);
}

TEST(Domains, PhaseNames) {
  EXPECT_EQ(parse_phase("rich"), Phase::rich);
  EXPECT_EQ(parse_phase("poor"), Phase::poor);
  EXPECT_EQ(parse_phase("both"), Phase::both);
  EXPECT_THROW(parse_phase("dense"), UsageError);
}

TEST(Domains, ThreeDimensionsSlabAndCube) {
  // A slab 5 cells thick normal to axis 1 in L = 16: each of the 16 x 16 lines along axis 1 holds a
  // rich domain of 5 and a poor one of 11; the lines along axes 0 and 2 none.
  const auto slab = test::make_grid(3, 16, {1.0, 1, 0.5}, [](const test::Cell& c) { return c[1] >= 3 && c[1] < 8 ? 1 : 0; });
  const auto both = measure_domains(slab, Phase::both);
  EXPECT_EQ(both.count, 2 * 256);
  EXPECT_DOUBLE_EQ(both.length, 8.0);
  const auto rich = measure_domains(slab, Phase::rich);
  EXPECT_EQ(rich.count, 256);
  EXPECT_DOUBLE_EQ(rich.length, 5.0);
  EXPECT_DOUBLE_EQ(rich.histogram[4], 1.0);  // all in the bin of length 5 (unit spacing)
  // A cube of 4^3 cells (w = 0): 4 x 4 lines through it along each of the 3 axes, each with a rich
  // domain of 4 and a poor one of 12.
  const auto cube = test::make_grid(3, 16, {1.0, 0, 0.5}, [](const test::Cell& c) {
    return c[0] >= 6 && c[0] < 10 && c[1] >= 6 && c[1] < 10 && c[2] >= 6 && c[2] < 10 ? 1 : 0;
  });
  const auto in_cube = measure_domains(cube, Phase::rich);
  EXPECT_EQ(in_cube.count, 3 * 16);
  EXPECT_DOUBLE_EQ(in_cube.length, 4.0);
  const auto around = measure_domains(cube, Phase::poor);
  EXPECT_EQ(around.count, 3 * 16);
  EXPECT_DOUBLE_EQ(around.length, 12.0);
}

}  // namespace
}  // namespace gg
