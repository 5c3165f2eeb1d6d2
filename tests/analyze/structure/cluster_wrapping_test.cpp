// The giant cluster (analyze/structure/cluster): which axes a cluster wraps, the largest cluster's share
// and the rest's mean mass, and each particle's cluster, on hand-built fields whose answers are known.
// Wrapping means a closed path through the cluster winding around the periodic box, not touching a face.
#include <gtest/gtest.h>

#include <cmath>

#include "cluster.hpp"
#include "density_grid_fixtures.hpp"

namespace gg {
namespace {

constexpr std::uint8_t kX = 1, kY = 2, kZ = 4;  // Cluster::wraps bits of axes 0, 1, 2

// No averaging (w = 0) and rho_c = 1.5: a cell holding 2 particles is rich, one holding 1 is gas.
const CoarseGrain kSharp{1.0, 0, 1.5};

ClusterResult clusters_of(int d, double L, Connectivity conn, const std::function<int(const test::Cell&)>& per_cell) {
  return find_clusters(test::make_grid(d, L, kSharp, per_cell), conn);
}

const Connectivity kBoth[] = {Connectivity::face, Connectivity::full};

TEST(ClusterWrapping, StripeWrapsAlongItsOwnAxisOnly) {
  // Columns 5 and 6 across all 16 rows (2 particles a cell: 64), a blob of 2 cells (4 particles) and a
  // gas row of 16 single particles in no cluster: N = 84.
  const auto field = [](const test::Cell& c) {
    if (c[1] == 5 || c[1] == 6) return 2;
    if (c[0] == 10 && (c[1] == 10 || c[1] == 11)) return 2;
    return c[1] == 13 ? 1 : 0;
  };
  for (auto conn : kBoth) {
    const auto r = clusters_of(2, 16, conn, field);
    ASSERT_EQ(r.clusters.size(), 2u);
    EXPECT_EQ(r.clusters[0].mass, 64);
    EXPECT_EQ(r.clusters[0].wraps, kX);
    EXPECT_EQ(r.clusters[1].wraps, 0);
    const auto g = giant_cluster(r.clusters, 84, 1);
    EXPECT_DOUBLE_EQ(g.share, 64.0 / 84.0);
    EXPECT_DOUBLE_EQ(g.share_of_clustered, 64.0 / 68.0);
    EXPECT_DOUBLE_EQ(g.rest_mean_mass, 4.0);
    EXPECT_EQ(g.wraps, kX);
  }
  // The same stripe along the other axis wraps along that axis.
  const auto r = clusters_of(2, 16, Connectivity::face, [](const test::Cell& c) { return c[0] == 3 ? 2 : 0; });
  ASSERT_EQ(r.clusters.size(), 1u);
  EXPECT_EQ(r.clusters[0].wraps, kY);
}

TEST(ClusterWrapping, BlobAcrossTheFacesDoesNotWrap) {
  // A 5x5 blob centred on the box corner, cut in four by the faces: one cluster, no winding.
  const auto corner = clusters_of(2, 16, Connectivity::face, [](const test::Cell& c) {
    return test::ring_distance(c[0], 0, 16) <= 2 && test::ring_distance(c[1], 0, 16) <= 2 ? 2 : 0;
  });
  ASSERT_EQ(corner.clusters.size(), 1u);
  EXPECT_EQ(corner.clusters[0].cells, 25);
  EXPECT_EQ(corner.clusters[0].wraps, 0);
  // A stripe crossing the face x = 0 that spans 15 of the 16 rows: one gap, so no loop around the box.
  for (auto conn : kBoth) {
    const auto gap = clusters_of(2, 16, conn, [](const test::Cell& c) { return c[1] == 5 && c[0] != 7 ? 2 : 0; });
    ASSERT_EQ(gap.clusters.size(), 1u);
    EXPECT_EQ(gap.clusters[0].cells, 15);
    EXPECT_EQ(gap.clusters[0].wraps, 0);
  }
}

TEST(ClusterWrapping, CrossWrapsBothAxes) {
  for (auto conn : kBoth) {
    const auto r = clusters_of(2, 16, conn, [](const test::Cell& c) { return c[0] == 3 || c[1] == 9 ? 2 : 0; });
    ASSERT_EQ(r.clusters.size(), 1u);
    EXPECT_EQ(r.clusters[0].cells, 31);
    EXPECT_EQ(r.clusters[0].wraps, kX | kY);
  }
}

TEST(ClusterWrapping, DiagonalStaircaseWrapsBothAxes) {
  // Cells (i, i) and (i, i+1): a staircase joined through faces; (15, 0) meets (0, 0) across the face
  // x = 0, closing a loop of winding (1, 1). Both connectivities see it.
  for (auto conn : kBoth) {
    const auto r = clusters_of(2, 16, conn, [](const test::Cell& c) {
      return c[1] == c[0] || c[1] == (c[0] + 1) % 16 ? 2 : 0;
    });
    ASSERT_EQ(r.clusters.size(), 1u);
    EXPECT_EQ(r.clusters[0].cells, 32);
    EXPECT_EQ(r.clusters[0].wraps, kX | kY);
  }
  // The bare diagonal (i, i): cells touching only at corners. With 8 neighbours one cluster winding
  // (1, 1); with 4, sixteen single cells, and the largest (the first, cell (0, 0)) wraps nothing.
  const auto diagonal = [](const test::Cell& c) { return c[1] == c[0] ? 2 : 0; };
  const auto full = clusters_of(2, 16, Connectivity::full, diagonal);
  ASSERT_EQ(full.clusters.size(), 1u);
  EXPECT_EQ(full.clusters[0].wraps, kX | kY);
  const auto face = clusters_of(2, 16, Connectivity::face, diagonal);
  ASSERT_EQ(face.clusters.size(), 16u);
  EXPECT_EQ(face.clusters[0].first_cell, 0u);
  for (const auto& c : face.clusters) EXPECT_EQ(c.wraps, 0);
  const auto g = giant_cluster(face.clusters, 32, 1);
  EXPECT_DOUBLE_EQ(g.share, 2.0 / 32.0);
  EXPECT_DOUBLE_EQ(g.share_of_clustered, 1.0 / 16.0);
  EXPECT_DOUBLE_EQ(g.rest_mean_mass, 2.0);
  EXPECT_EQ(g.wraps, 0);
}

TEST(ClusterWrapping, StaircaseOfSlopeTwoWindsTwiceAlongOneAxis) {
  // Cells (i, 2i), (i, 2i+1), (i, 2i+2) mod 16: a face-joined staircase that closes after going once
  // around x and twice around y. Winding (1, 2): both axes wrap.
  for (auto conn : kBoth) {
    const auto r = clusters_of(2, 16, conn, [](const test::Cell& c) {
      const int rise = ((c[1] - 2 * c[0]) % 16 + 16) % 16;
      return rise <= 2 ? 2 : 0;
    });
    ASSERT_EQ(r.clusters.size(), 1u);
    EXPECT_EQ(r.clusters[0].cells, 48);
    EXPECT_EQ(r.clusters[0].wraps, kX | kY);
  }
}

TEST(ClusterWrapping, ThreeDimensionalSlabWrapsTwoAxesNotTheThird) {
  // Layers z = 2, 3 of an 8^3 box: a slab spanning x and y, 2 cells thick.
  for (auto conn : kBoth) {
    const auto r = clusters_of(3, 8, conn, [](const test::Cell& c) { return c[2] == 2 || c[2] == 3 ? 2 : 0; });
    ASSERT_EQ(r.clusters.size(), 1u);
    EXPECT_EQ(r.clusters[0].cells, 128);
    EXPECT_EQ(r.clusters[0].wraps, kX | kY);
  }
  // A rod along z wraps z only; the body diagonal (i, i, i) wraps all three with 26 neighbours and
  // is 8 single cells with 6.
  const auto rod = clusters_of(3, 8, Connectivity::face, [](const test::Cell& c) { return c[0] == 1 && c[1] == 6 ? 2 : 0; });
  ASSERT_EQ(rod.clusters.size(), 1u);
  EXPECT_EQ(rod.clusters[0].wraps, kZ);
  const auto diagonal = [](const test::Cell& c) { return c[0] == c[1] && c[1] == c[2] ? 2 : 0; };
  const auto full = clusters_of(3, 8, Connectivity::full, diagonal);
  ASSERT_EQ(full.clusters.size(), 1u);
  EXPECT_EQ(full.clusters[0].wraps, kX | kY | kZ);
  EXPECT_EQ(clusters_of(3, 8, Connectivity::face, diagonal).clusters.size(), 8u);
}

TEST(ClusterWrapping, OneDimensionWrapsOnlyTheWholeRing) {
  const auto ring = clusters_of(1, 12, Connectivity::face, [](const test::Cell&) { return 2; });
  ASSERT_EQ(ring.clusters.size(), 1u);
  EXPECT_EQ(ring.clusters[0].wraps, kX);
  // Cells 9..11, 0..4 (across the boundary) and 6..7: two clusters, neither wrapping.
  const auto cut = clusters_of(1, 12, Connectivity::face, [](const test::Cell& c) { return c[0] == 5 || c[0] == 8 ? 0 : 2; });
  ASSERT_EQ(cut.clusters.size(), 2u);
  EXPECT_EQ(cut.clusters[0].cells, 8);
  EXPECT_EQ(cut.clusters[0].wraps, 0);
  EXPECT_EQ(cut.clusters[1].wraps, 0);
}

TEST(ClusterWrapping, OnlyTheLargestClusterCounts) {
  // A 6x6 blob (72 particles) that wraps nothing and a one-cell-wide stripe (32) that wraps x.
  const auto r = clusters_of(2, 16, Connectivity::face, [](const test::Cell& c) {
    if (c[0] >= 4 && c[0] < 10 && c[1] >= 4 && c[1] < 10) return 2;
    return c[1] == 13 ? 2 : 0;
  });
  ASSERT_EQ(r.clusters.size(), 2u);
  EXPECT_EQ(r.clusters[0].mass, 72);
  EXPECT_EQ(r.clusters[1].wraps, kX);
  const auto g = giant_cluster(r.clusters, 104, 1);
  EXPECT_EQ(g.wraps, 0);
  EXPECT_DOUBLE_EQ(g.rest_mean_mass, 32.0);
}

TEST(ClusterWrapping, GiantSummaryFollowsMinSize) {
  const std::vector<Cluster> cl = {{10, 1, 0, kY}, {5, 1, 1, 0}, {1, 1, 2, 0}};
  const auto g = giant_cluster(cl, 20, 2);  // the cluster of 1 is left out
  EXPECT_DOUBLE_EQ(g.share, 0.5);
  EXPECT_DOUBLE_EQ(g.share_of_clustered, 10.0 / 15.0);
  EXPECT_DOUBLE_EQ(g.rest_mean_mass, 5.0);
  EXPECT_EQ(g.wraps, kY);
  const auto alone = giant_cluster(cl, 20, 6);  // only the largest: no rest
  EXPECT_DOUBLE_EQ(alone.share_of_clustered, 1.0);
  EXPECT_TRUE(std::isnan(alone.rest_mean_mass));
  const auto none = giant_cluster(cl, 20, 11);  // no cluster at all
  EXPECT_EQ(none.share, 0.0);
  EXPECT_TRUE(std::isnan(none.share_of_clustered));
  EXPECT_TRUE(std::isnan(none.rest_mean_mass));
  EXPECT_EQ(none.wraps, 0);
  EXPECT_TRUE(std::isnan(giant_cluster({}, 0, 1).share));  // no particles
}

TEST(ClusterWrapping, EachParticleGetsItsCellsCluster) {
  // The stripe (cluster 0), a blob of 3 cells (cluster 1) and gas particles in no cluster (-1).
  const auto field = [](const test::Cell& c) {
    if (c[1] == 5) return 2;
    if (c[0] == 10 && c[1] >= 9 && c[1] <= 11) return 2;
    return c[1] == 13 ? 1 : 0;
  };
  DensityGrid grid({16.0, 16.0}, kSharp);
  const auto x = test::fill_cells(grid.cells_per_side(), grid.spacing(), field);
  const std::size_t n = x.size() / 2;
  grid.assign(x.data(), n);
  const auto r = find_clusters(grid, Connectivity::face);
  const auto idx = particle_clusters(grid, r, x.data(), n);
  ASSERT_EQ(idx.size(), n);
  std::int64_t per_cluster[2] = {0, 0}, gas = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const int cx = static_cast<int>(x[2 * i]), cy = static_cast<int>(x[2 * i + 1]);
    const int expected = cy == 5 ? 0 : cy == 13 ? -1 : 1;
    EXPECT_EQ(idx[i], expected) << "particle " << i << " in cell (" << cx << ", " << cy << ")";
    if (idx[i] >= 0) ++per_cluster[idx[i]];
    else ++gas;
  }
  EXPECT_EQ(per_cluster[0], 32);
  EXPECT_EQ(per_cluster[1], 6);
  EXPECT_EQ(gas, 16);
}

}  // namespace
}  // namespace gg
