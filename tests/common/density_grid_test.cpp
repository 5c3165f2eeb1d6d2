// The shared coarse-graining (common/density_grid): cell count, binning, periodic block sums,
// the psi threshold and its tie rule, validation.
#include <gtest/gtest.h>

#include <numeric>
#include <string>

#include "gg/density_grid.hpp"
#include "gg/errors.hpp"
#include "density_grid_fixtures.hpp"

namespace gg {
namespace {

// The UsageError a grid of `box` with `p` is refused with ("no UsageError" if it is built).
std::string refusal(const std::vector<double>& box, const CoarseGrain& p) {
  try {
    DensityGrid(box, p);
  } catch (const UsageError& e) {
    return e.what();
  }
  return "no UsageError";
}

TEST(DensityGrid, CellsPerSideIsRoundedLOverGridAndTilesTheBox) {
  const DensityGrid a({10.0}, {3.0, 1, 0.5});  // 10/3 = 3.33 -> 3 cells of 3.333
  EXPECT_EQ(a.cells_per_side()[0], 3);
  EXPECT_DOUBLE_EQ(a.spacing()[0], 10.0 / 3.0);
  const DensityGrid b({10.0, 10.0}, {4.0, 1, 0.5});  // 2.5 -> 3 (round half away from zero)
  EXPECT_EQ(b.cells_per_side()[1], 3);
  const DensityGrid c({10.0, 10.0}, {10.0, 0, 0.5});  // grid = L: one cell (so no block wider than it)
  EXPECT_EQ(c.cells_per_side()[0], 1);
  EXPECT_EQ(c.size(), 1u);
  const DensityGrid d({512.0, 512.0}, {});  // defaults: grid 1
  EXPECT_EQ(d.size(), 512u * 512u);
  EXPECT_EQ(d.strides()[0], 512u);
  EXPECT_EQ(d.strides()[1], 1u);
  EXPECT_DOUBLE_EQ(d.block_volume(), 9.0);
}

TEST(DensityGrid, ParticleBelongsToTheCellHoldingItsCentreWithPeriodicWrap) {
  DensityGrid g({4.0, 4.0}, {1.0, 0, 0.5});
  // (x, y): cell index x * 4 + y.
  const std::vector<double> x = {0.0, 0.0,                  // cell (0,0)
                                 3.9999999999999996, 0.5,   // just below L: cell (3,0)
                                 -0.5, 1.5,                 // wraps to x = 3.5: cell (3,1)
                                 4.25, 2.5,                 // wraps to x = 0.25: cell (0,2)
                                 1.0, 3.0};                 // on a cell edge: the upper cell (1,3)
  g.assign(x.data(), 5);
  std::vector<std::int32_t> want(16, 0);
  want[0 * 4 + 0] = 1;
  want[3 * 4 + 0] = 1;
  want[3 * 4 + 1] = 1;
  want[0 * 4 + 2] = 1;
  want[1 * 4 + 3] = 1;
  EXPECT_EQ(g.counts(), want);
}

TEST(DensityGrid, BlockSumIsPeriodic3x3Block) {
  DensityGrid g({5.0, 5.0}, {1.0, 1, 0.5});
  const std::vector<double> x = {0.5, 0.5};  // one particle in cell (0,0)
  g.assign(x.data(), 1);
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j) {
      const bool in_block = test::ring_distance(i, 0, 5) <= 1 && test::ring_distance(j, 0, 5) <= 1;
      EXPECT_EQ(g.block_counts()[i * 5 + j], in_block ? 1 : 0) << i << "," << j;
    }
  EXPECT_DOUBLE_EQ(g.rho_loc(4 * 5 + 4), 1.0 / 9.0);  // the corner across both boundaries
}

TEST(DensityGrid, EveryParticleCountsInExactlyBlockCellsBlocks) {
  for (int d = 1; d <= 3; ++d) {
    const double L = d == 3 ? 16 : 64;
    for (int w : {0, 1, 2}) {
      DensityGrid g(std::vector<double>(d, L), {1.0, w, 0.5});
      const std::size_t n = 500;
      const auto x = test::random_positions(d, L, n, 7 + d);
      g.assign(x.data(), n);
      const long sum = std::accumulate(g.counts().begin(), g.counts().end(), 0L);
      const long block = std::accumulate(g.block_counts().begin(), g.block_counts().end(), 0L);
      long cells = 1;
      for (int k = 0; k < d; ++k) cells *= 2 * w + 1;
      EXPECT_EQ(sum, static_cast<long>(n));
      EXPECT_EQ(block, cells * static_cast<long>(n)) << "d = " << d << ", w = " << w;
    }
  }
}

TEST(DensityGrid, WidestBlockCountsEveryCellOnce) {
  // 5 cells per side, w = 2: the 5x5 block is the whole box, each cell in it once.
  const auto g = test::make_grid(2, 5.0, {1.0, 2, 0.5}, [](const test::Cell& c) { return c[0] == 1 ? 2 : 0; });
  for (std::size_t c = 0; c < g.size(); ++c) EXPECT_EQ(g.block_counts()[c], 10) << c;
}

// A block of 2w+1 cells wider than the n cells of an axis would wrap onto itself and count cells twice
// (the audit's box of 37 cells: w = 19 gave one cluster of every particle, w = 100 none at all).
TEST(DensityGrid, RefusesABlockWiderThanTheGrid) {
  EXPECT_NO_THROW(DensityGrid({37.0, 37.0}, {1.0, 18, 0.5}));  // 37 cells: the whole row, once
  EXPECT_EQ(refusal({37.0, 37.0}, {1.0, 19, 0.5}),
            "--coarse 19 makes blocks of 39 cells per side, more than the 37 cells per side of the grid "
            "(box 37 x 37, --grid 1), so cells would count twice; choose --coarse <= 18 (or a smaller --grid)");
  EXPECT_NE(refusal({37.0, 37.0}, {1.0, 100, 0.5}).find("choose --coarse <= 18"), std::string::npos);
  EXPECT_NE(refusal({37.0, 37.0}, {1.0, 1 << 30, 0.5}).find("choose --coarse <= 18"), std::string::npos);
  // Even cell counts: 10 cells hold a block of 9, not 11; the narrowest axis decides.
  EXPECT_NO_THROW(DensityGrid({10.0}, {1.0, 4, 0.5}));
  EXPECT_NE(refusal({10.0}, {1.0, 5, 0.5}).find("choose --coarse <= 4"), std::string::npos);
  EXPECT_NE(refusal({37.0, 20.0}, {1.0, 10, 0.5}).find("choose --coarse <= 9"), std::string::npos);
  // One cell (grid = L): only w = 0.
  EXPECT_NE(refusal({10.0, 10.0}, {10.0, 1, 0.5}).find("choose --coarse <= 0"), std::string::npos);
  EXPECT_NO_THROW(validate({1.0, 19, 0.5}, {}));  // no box yet: only w >= 0 can be checked
}

TEST(DensityGrid, PsiIsPlusOneOnlyAboveRhoCAndTheTieIsPoor) {
  // Cells of area 4 without averaging (w = 0): 2 particles give rho_loc = 0.5 = rho_c exactly.
  const auto g = test::make_grid(2, 8.0, {2.0, 0, 0.5}, [](const test::Cell& c) { return c[0] + c[1] == 0 ? 2 : c[0] == 1 && c[1] == 0 ? 3 : 0; });
  EXPECT_DOUBLE_EQ(g.rho_loc(0), 0.5);
  EXPECT_EQ(g.psi()[0], -1);            // rho_loc == rho_c: poor
  EXPECT_EQ(g.psi()[1 * 4 + 0], +1);    // 3 / 4 > 0.5: rich
  EXPECT_EQ(g.psi()[2 * 4 + 2], -1);    // empty
}

// With weights (each particle's area: a file with radii) rho_loc is the packing fraction of the
// block, psi compares it with rho_c, and counts() still counts particles.
TEST(DensityGrid, WeightsGiveThePackingFraction) {
  DensityGrid g({8.0, 8.0}, {2.0, 0, 0.5});  // 4 x 4 cells of area 4, no averaging
  const std::vector<double> positions{1, 1, 1.5, 1.5, 5, 1};  // two in cell (0,0), one in (2,0)
  const std::vector<double> area{0.5, 1.5, 2.5};
  g.assign(positions.data(), 3, area.data());
  EXPECT_DOUBLE_EQ(g.rho_loc(0), 2.0 / 4);  // (0.5 + 1.5) / 4 = rho_c: poor
  EXPECT_EQ(g.psi()[0], -1);
  EXPECT_DOUBLE_EQ(g.rho_loc(2 * 4), 2.5 / 4);
  EXPECT_EQ(g.psi()[2 * 4], 1);
  EXPECT_EQ(g.counts()[0], 2);
  g.assign(positions.data(), 3);  // without weights: counts again (2 / 4 = rho_c, 1 / 4)
  EXPECT_DOUBLE_EQ(g.rho_loc(2 * 4), 1.0 / 4);
  EXPECT_EQ(g.psi()[2 * 4], -1);
}

TEST(DensityGrid, OneDimension) {
  // 10 cells; particles at 1 per cell in cells 3..6; w = 1.
  const auto g = test::make_grid(1, 10.0, {}, [](const test::Cell& c) { return c[0] >= 3 && c[0] <= 6 ? 1 : 0; });
  const std::vector<std::int32_t> block = {0, 0, 1, 2, 3, 3, 2, 1, 0, 0};
  EXPECT_EQ(g.block_counts(), block);
  const std::vector<std::int8_t> psi = {-1, -1, -1, 1, 1, 1, 1, -1, -1, -1};  // 2/3 > 0.5 > 1/3
  EXPECT_EQ(g.psi(), psi);
}

TEST(DensityGrid, RejectsBadParametersWithUsageError) {
  const std::vector<double> box = {32.0, 32.0};
  EXPECT_THROW(DensityGrid(box, {33.0, 1, 0.5}), UsageError);  // grid larger than the box
  EXPECT_THROW(DensityGrid(box, {0.0, 1, 0.5}), UsageError);
  EXPECT_THROW(DensityGrid(box, {std::nan(""), 1, 0.5}), UsageError);
  EXPECT_THROW(DensityGrid(box, {1.0, -1, 0.5}), UsageError);
  EXPECT_THROW(DensityGrid(box, {1.0, 1, 0.0}), UsageError);
  EXPECT_THROW(DensityGrid(box, {1.0, 1, -0.5}), UsageError);
  EXPECT_NO_THROW(DensityGrid(box, {32.0, 0, 1e-9}));
  try {
    DensityGrid(box, {40.0, 1, 0.5});
    FAIL();
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("larger than the box"), std::string::npos) << e.what();
  }
}

// round(L/grid) of an absurd box fits no int (1D, 2^32 + 1 cells once wrapped to 1 cell), and 10^12
// cells would be allocated before anything failed: refused, with a --grid that fits.
TEST(DensityGrid, RefusesMoreCellsThanKMaxCells) {
  auto message = [](const std::vector<double>& box, double grid) { return refusal(box, {grid, 1, 0.5}); };
  EXPECT_EQ(message({1e6, 1e6}, 1),
            "--grid 1 gives 1e+12 cells for the box 1e+06 x 1e+06, more than 67108864; choose --grid >= 123.3");
  EXPECT_EQ(message({4294967297.0}, 1),
            "--grid 1 gives 4.29497e+09 cells for the box 4.29497e+09, more than 67108864; choose --grid >= 64.65");
  EXPECT_NE(message({1e300}, 1).find("--grid 1 gives 1e+300 cells"), std::string::npos);
  // validate() alone: these grids fit, but would take a GB to build.
  EXPECT_NO_THROW(validate({1.0, 1, 0.5}, {8192.0, 8192.0}));  // exactly kMaxCells
  EXPECT_NO_THROW(validate({123.3, 1, 0.5}, {1e6, 1e6}));
  EXPECT_NO_THROW(validate({64.65, 1, 0.5}, {4294967297.0}));
}

TEST(DensityGrid, ThreeDimensionsBlockOfOneLoadedCellWrapsAroundTheBox) {
  // 14 particles in cell (0, 5, 3) of a 6^3 grid (w = 1): the 27 cells of its block, which wraps
  // across the faces x = 0 and y = L, see 14 / 27 > 0.5 and are rich; every other cell is empty.
  const auto g = test::make_grid(3, 6.0, {1.0, 1, 0.5}, [](const test::Cell& c) { return c == test::Cell{0, 5, 3} ? 14 : 0; });
  ASSERT_EQ(g.size(), 216u);
  EXPECT_EQ(g.strides(), (std::vector<std::size_t>{36, 6, 1}));
  EXPECT_EQ(g.counts()[0 * 36 + 5 * 6 + 3], 14);
  EXPECT_DOUBLE_EQ(g.block_volume(), 27.0);
  int rich = 0;
  for (int x = 0; x < 6; ++x)
    for (int y = 0; y < 6; ++y)
      for (int z = 0; z < 6; ++z) {
        const std::size_t c = x * 36 + y * 6 + z;
        const bool near = test::ring_distance(x, 0, 6) <= 1 && test::ring_distance(y, 5, 6) <= 1 && std::abs(z - 3) <= 1;
        EXPECT_EQ(g.block_counts()[c], near ? 14 : 0) << x << y << z;
        EXPECT_EQ(g.psi()[c], near ? 1 : -1);
        rich += near;
      }
  EXPECT_EQ(rich, 27);
  EXPECT_DOUBLE_EQ(g.rho_loc(5 * 36 + 0 * 6 + 2), 14.0 / 27);  // the corner (-1, +1, -1) of the block
}

}  // namespace
}  // namespace gg
