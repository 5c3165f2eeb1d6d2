// The cell grid's visit of the cells around a point (cell_grid.hpp): every particle whose centre
// is within one cell width is reported once, and the engine's variant, which also passes on
// empty places, reports the same particles in the same order and nothing else but empty places.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <random>
#include <vector>

#include "ggsim/cell_grid.hpp"

namespace {

using ggsim::CellGrid;
using ggsim::Vec;
using ggsim::Visit;

template <int D>
struct Seen {
  std::vector<std::uint32_t> particles;  // in the order reported
  std::size_t empty_places = 0;
  std::size_t bad_empty_places = 0;  // reported as empty but with a finite centre coordinate
};

template <int D, Visit V>
Seen<D> visit_around(const CellGrid<D>& grid, const Vec<D>& x) {
  Seen<D> seen;
  grid.template for_each_near<V>(x, [&](std::uint32_t j, const Vec<D>& c) {
    if (j == CellGrid<D>::kEmptyPlace) {
      ++seen.empty_places;
      for (double ck : c) seen.bad_empty_places += !std::isinf(ck);
    } else {
      seen.particles.push_back(j);
    }
  });
  return seen;
}

// Random centres in a periodic box (cells of width >= 2), moved around a little so the lists are
// not in insertion order, then queried at random points, edges included.
template <int D>
void check_visits(double L, std::size_t n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::array<double, D> edges;
  edges.fill(L);
  const gg::Box<D> box(edges);
  CellGrid<D> grid(box, 2.0, n);
  std::vector<Vec<D>> centre(n);
  const auto random_point = [&] {
    Vec<D> x;
    for (int k = 0; k < D; ++k) x[k] = L * u(rng);
    return x;
  };
  for (std::uint32_t p = 0; p < n; ++p) grid.insert(p, centre[p] = random_point());
  for (std::uint32_t p = 0; p < n; p += 3) grid.move(p, centre[p] = random_point());
  const double w = grid.min_cell_width();
  for (int q = 0; q < 300; ++q) {
    const Vec<D> x = random_point();
    const Seen<D> plain = visit_around<D, Visit::kParticles>(grid, x);
    const Seen<D> padded = visit_around<D, Visit::kWithEmptyPlaces>(grid, x);
    EXPECT_EQ(plain.empty_places, 0u);
    EXPECT_EQ(padded.particles, plain.particles) << "the empty places must not change what is reported";
    EXPECT_EQ(padded.bad_empty_places, 0u);
    std::map<std::uint32_t, int> count;
    for (std::uint32_t j : plain.particles) ++count[j];
    for (const auto& [j, c] : count) EXPECT_EQ(c, 1) << "particle " << j << " reported " << c << " times";
    for (std::uint32_t p = 0; p < n; ++p) {
      double d2 = 0;
      for (int k = 0; k < D; ++k) {
        const double d = box.min_image(centre[p][k] - x[k], k);
        d2 += d * d;
      }
      if (d2 < w * w) {
        EXPECT_EQ(count.count(p), 1u) << "particle " << p << " within a cell width was not reported";
      }
    }
  }
}

TEST(CellGrid, VisitsReportEveryNearParticleOnce2D) { check_visits<2>(30.0, 200, 1); }
TEST(CellGrid, VisitsReportEveryNearParticleOnceInACrowd) { check_visits<2>(12.0, 400, 2); }
TEST(CellGrid, VisitsReportEveryNearParticleOnceInANarrowBox) { check_visits<2>(5.0, 20, 3); }
TEST(CellGrid, VisitsReportEveryNearParticleOnce1D) { check_visits<1>(40.0, 30, 4); }

}  // namespace
