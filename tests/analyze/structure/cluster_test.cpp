// gg-cluster's analysis (analyze/structure/cluster): hand-known cluster counts and masses.
#include <gtest/gtest.h>

#include <cmath>

#include "cluster.hpp"
#include "density_grid_fixtures.hpp"

namespace gg {
namespace {

// 6x6 patch of cells with 2 particles each, lower corner (x0, y0) (periodic), L = 32, w = 1.
// Hand count of psi = +1 cells: the patch (36) plus the 4 middle cells along each side (their block
// holds 3 patch cells: 6/9 > 0.5); the 2 end cells of each side see 2 patch cells (4/9) and the
// diagonal corners 1 (2/9): poor. 36 + 16 = 52 cells.
DensityGrid patch(int x0, int y0) {
  return test::make_grid(2, 32.0, {}, [=](const test::Cell& c) {
    const int dx = ((c[0] - x0) % 32 + 32) % 32, dy = ((c[1] - y0) % 32 + 32) % 32;
    return dx < 6 && dy < 6 ? 2 : 0;
  });
}

TEST(Cluster, DensePatchIsOneClusterHoldingItsParticles) {
  const auto g = patch(10, 12);
  for (auto conn : {Connectivity::face, Connectivity::full}) {
    const auto r = find_clusters(g, conn);
    ASSERT_EQ(r.clusters.size(), 1u);
    EXPECT_EQ(r.clusters[0].mass, 72);
    EXPECT_EQ(r.clusters[0].cells, 52);
    EXPECT_EQ(r.label[12 * 32 + 14], 0);  // inside the patch
    EXPECT_EQ(r.label[0], -1);            // empty corner of the box
    const auto s = summarize(r.clusters, 1);
    EXPECT_EQ(s.count, 1);
    EXPECT_EQ(s.largest, 72);
    EXPECT_DOUBLE_EQ(s.mean_mass, 72.0);
    EXPECT_DOUBLE_EQ(s.weight_mass, 72.0);
  }
}

TEST(Cluster, PatchAcrossThePeriodicCornerGivesTheSameAnswer) {
  // Cells 29..34 mod 32 along both axes: the patch is cut in four by the boundaries.
  const auto g = patch(29, 29);
  const auto r = find_clusters(g, Connectivity::face);
  ASSERT_EQ(r.clusters.size(), 1u);
  EXPECT_EQ(r.clusters[0].mass, 72);
  EXPECT_EQ(r.clusters[0].cells, 52);
  EXPECT_EQ(r.label[0], 0);              // cell (0,0) is inside it
  EXPECT_EQ(r.label[31 * 32 + 31], 0);   // and so is (31,31)
  EXPECT_EQ(r.clusters[0].first_cell, 0u);
}

// Two 4x4 patches (1 particle per cell, no averaging) touching only at a corner.
DensityGrid corner_patches(int ax, int bx) {
  return test::make_grid(2, 32.0, {1.0, 0, 0.5}, [=](const test::Cell& c) {
    auto in = [&](int x0) {
      const int dx = ((c[0] - x0) % 32 + 32) % 32, dy = ((c[1] - x0) % 32 + 32) % 32;
      return dx < 4 && dy < 4;
    };
    return in(ax) || in(bx) ? 1 : 0;
  });
}

TEST(Cluster, DiagonalNeighboursMergeUnder8ButNot4Connectivity) {
  for (const auto& [a, b] : {std::pair{4, 8}, std::pair{0, 28}}) {  // second: touching across the corner
    const auto g = corner_patches(a, b);
    const auto face = find_clusters(g, Connectivity::face);
    ASSERT_EQ(face.clusters.size(), 2u) << a << "," << b;
    EXPECT_EQ(face.clusters[0].mass, 16);
    EXPECT_EQ(face.clusters[1].mass, 16);
    const auto full = find_clusters(g, Connectivity::full);
    ASSERT_EQ(full.clusters.size(), 1u) << a << "," << b;
    EXPECT_EQ(full.clusters[0].mass, 32);
  }
}

TEST(Cluster, ThreeDimensionsCornerCubesMergeOnlyUnderFullConnectivity) {
  // Two 3x3x3 cubes (1 particle per cell, w = 0) in L = 12 touching at one corner: (2,2,2)-(3,3,3).
  // Face connectivity (6 neighbours): 2 clusters of 27; full (26 neighbours): one of 54.
  const auto g = test::make_grid(3, 12.0, {1.0, 0, 0.5}, [](const test::Cell& c) {
    const bool a = c[0] < 3 && c[1] < 3 && c[2] < 3;
    const bool b = c[0] >= 3 && c[0] < 6 && c[1] >= 3 && c[1] < 6 && c[2] >= 3 && c[2] < 6;
    return a || b ? 1 : 0;
  });
  const auto face = find_clusters(g, Connectivity::face);
  ASSERT_EQ(face.clusters.size(), 2u);
  EXPECT_EQ(face.clusters[0].mass, 27);
  const auto full = find_clusters(g, Connectivity::full);
  ASSERT_EQ(full.clusters.size(), 1u);
  EXPECT_EQ(full.clusters[0].mass, 54);
}

TEST(Cluster, OrderIsHeaviestFirstThenSmallestCell) {
  // w = 0, 1 particle per rich cell: masses 3 (cells 20..22), 5 (cells 10..14), 3 (cells 2..4).
  const auto g = test::make_grid(1, 30.0, {1.0, 0, 0.5}, [](const test::Cell& c) {
    const int i = c[0];
    return (i >= 2 && i <= 4) || (i >= 10 && i <= 14) || (i >= 20 && i <= 22) ? 1 : 0;
  });
  const auto r = find_clusters(g, Connectivity::face);
  ASSERT_EQ(r.clusters.size(), 3u);
  EXPECT_EQ(r.clusters[0].mass, 5);
  EXPECT_EQ(r.clusters[0].first_cell, 10u);
  EXPECT_EQ(r.clusters[1].first_cell, 2u);   // tie on mass 3: smaller cell first
  EXPECT_EQ(r.clusters[2].first_cell, 20u);
  EXPECT_EQ(r.label[21], 2);
}

TEST(Cluster, OneDimensionWrapsAroundAndBothConnectivitiesAgree) {
  // 1 particle per cell in cells 19, 0, 1 (joined through the boundary) and 5; w = 0.
  const auto g = test::make_grid(1, 20.0, {1.0, 0, 0.5}, [](const test::Cell& c) {
    return c[0] == 19 || c[0] == 0 || c[0] == 1 || c[0] == 5 ? 1 : 0;
  });
  for (auto conn : {Connectivity::face, Connectivity::full}) {
    const auto r = find_clusters(g, conn);
    ASSERT_EQ(r.clusters.size(), 2u);
    EXPECT_EQ(r.clusters[0].mass, 3);
    EXPECT_EQ(r.clusters[0].first_cell, 0u);
    EXPECT_EQ(r.clusters[1].mass, 1);
    EXPECT_EQ(r.label[19], 0);
  }
}

TEST(Cluster, HomogeneousRandomBelowRhoCHasOnlyTinyClusters) {
  // rho = 0.37 < rho_c = 0.5, uniform random, L = 256: rich cells are fluctuations, far below
  // percolation; the largest cluster holds well under 1% of the particles.
  const auto g = test::random_grid_2d(256, 0.37, 2024);
  const auto s = summarize(find_clusters(g, Connectivity::face).clusters, 1);
  EXPECT_LT(s.largest, static_cast<std::int64_t>(0.01 * g.n_particles()));
  EXPECT_LT(s.mean_mass, 20.0);
  EXPECT_GT(s.count, 100);  // many small ones, not one
}

TEST(Cluster, SummaryAppliesMinSizeToEveryNumber) {
  const std::vector<Cluster> cl = {{10, 1, 0}, {5, 1, 1}, {1, 1, 2}};
  const auto s = summarize(cl, 2);
  EXPECT_EQ(s.count, 2);
  EXPECT_EQ(s.largest, 10);
  EXPECT_DOUBLE_EQ(s.mean_mass, 7.5);
  EXPECT_DOUBLE_EQ(s.weight_mass, 125.0 / 15.0);
  const auto none = summarize(cl, 11);
  EXPECT_EQ(none.count, 0);
  EXPECT_EQ(none.largest, 0);
  EXPECT_TRUE(std::isnan(none.mean_mass));
  EXPECT_TRUE(std::isnan(none.weight_mass));
}

TEST(Cluster, MassHistogramInLog2Bins) {
  const auto edges = mass_bin_edges(7);
  EXPECT_EQ(edges, (std::vector<double>{1, 2, 4, 8}));
  const std::vector<Cluster> cl = {{7, 1, 0}, {4, 1, 1}, {3, 1, 2}, {2, 1, 3}, {1, 1, 4}, {0, 1, 5}};
  EXPECT_EQ(mass_histogram(cl, 1, edges), (std::vector<double>{1, 2, 2}));
  EXPECT_EQ(mass_histogram(cl, 3, edges), (std::vector<double>{0, 1, 2}));
}

TEST(Cluster, ThreeDimensionsBallAcrossThePeriodicCornerIsOneCluster) {
  // Cells within 3 cells of the box corner (0,0,0), periodically (L = 16, w = 0, 2 particles each):
  // the ball is cut in 8 pieces by the box faces and must come back as one cluster under both
  // connectivities, of 2 particles per cell.
  const auto in_ball = [](const test::Cell& c) {
    int r2 = 0;
    for (int k = 0; k < 3; ++k) {
      const int d = test::ring_distance(c[k], 0, 16);
      r2 += d * d;
    }
    return r2 <= 9;
  };
  std::int64_t ball_cells = 0;
  for (int x = -3; x <= 3; ++x)
    for (int y = -3; y <= 3; ++y)
      for (int z = -3; z <= 3; ++z) ball_cells += x * x + y * y + z * z <= 9;
  ASSERT_EQ(ball_cells, 123);  // the lattice points of a radius-3 ball
  const auto g = test::make_grid(3, 16.0, {1.0, 0, 0.5}, [&](const test::Cell& c) { return in_ball(c) ? 2 : 0; });
  for (auto conn : {Connectivity::face, Connectivity::full}) {
    const auto r = find_clusters(g, conn);
    ASSERT_EQ(r.clusters.size(), 1u);
    EXPECT_EQ(r.clusters[0].cells, ball_cells);
    EXPECT_EQ(r.clusters[0].mass, 2 * ball_cells);
    EXPECT_EQ(r.label[15 * 256 + 15 * 16 + 15], 0);  // the piece in the far corner
    EXPECT_EQ(r.label[8 * 256 + 8 * 16 + 8], -1);    // the middle of the box
  }
}

TEST(Cluster, ThreeDimensionsCellsSharingOnlyAnEdgeJoinUnderFullConnectivity) {
  // Single rich cells (w = 0) at (1,1,1), (2,2,1) (sharing an edge) and (5,5,5) alone: 6
  // neighbours give 3 clusters, 26 give 2.
  const auto g = test::make_grid(3, 8.0, {1.0, 0, 0.5}, [](const test::Cell& c) {
    const bool a = c == test::Cell{1, 1, 1}, b = c == test::Cell{2, 2, 1}, lone = c == test::Cell{5, 5, 5};
    return a || b || lone ? 1 : 0;
  });
  EXPECT_EQ(find_clusters(g, Connectivity::face).clusters.size(), 3u);
  const auto full = find_clusters(g, Connectivity::full);
  ASSERT_EQ(full.clusters.size(), 2u);
  EXPECT_EQ(full.clusters[0].mass, 2);
  EXPECT_EQ(full.clusters[1].mass, 1);
}

}  // namespace
}  // namespace gg
