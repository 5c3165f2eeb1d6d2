// The cell grid (cell_grid.hpp): its visit of the cells around a point reports every particle
// whose centre is within one cell width once, and the engine's variant, which also passes on
// empty places, reports the same particles in the same order and nothing else but empty places
// (and, for the engine's search, puts a particle and the empty places out of reach on request);
// centres kept in fixed point come back from their decoded values unchanged and measure the
// minimum-image distance.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <random>
#include <vector>

#include "gg/errors.hpp"
#include "ggsim/cell_grid.hpp"
#include "ggsim/engine.hpp"

namespace {

using ggsim::CellGrid;
using ggsim::Vec;
using ggsim::Visit;

struct Seen {
  std::vector<std::uint32_t> particles;  // in the order reported
  std::size_t empty_places = 0;
  std::size_t wrong_codes = 0;  // particles reported with a code other than their own
};

// The engine's visits (kWithEmptyPlaces, for_each_near_inner) report slots, the other particle
// numbers.
template <int D, Visit V>
Seen visit_around(const CellGrid<D>& grid, const Vec<D>& x) {
  Seen seen;
  grid.template for_each_near<V>(grid.encode(x), [&](std::uint32_t reported, const typename CellGrid<D>::Code& c) {
    if (V == Visit::kWithEmptyPlaces && reported == CellGrid<D>::kEmptySlot) {
      ++seen.empty_places;
    } else {
      const std::uint32_t j = V == Visit::kWithEmptyPlaces ? CellGrid<D>::particle(reported) : reported;
      seen.particles.push_back(j);
      seen.wrong_codes += c != grid.code(j);
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
  int inner_queries = 0;
  for (int q = 0; q < 300; ++q) {
    const Vec<D> x = random_point();
    const Seen plain = visit_around<D, Visit::kParticles>(grid, x);
    const Seen padded = visit_around<D, Visit::kWithEmptyPlaces>(grid, x);
    EXPECT_EQ(plain.empty_places, 0u);
    EXPECT_EQ(plain.wrong_codes, 0u);
    EXPECT_EQ(padded.particles, plain.particles) << "the empty places must not change what is reported";
    if (grid.far_from_edges(grid.encode(x))) {  // the engine's visit away from the edges, level by level
      using Slot = typename CellGrid<D>::Slot;
      std::vector<std::uint32_t> inner;
      std::size_t first_places = 0;
      const auto seen = [&](Slot s, const auto& c) {
        if (s == CellGrid<D>::kEmptySlot) return;
        const std::uint32_t j = CellGrid<D>::particle(s);
        inner.push_back(j);
        EXPECT_EQ(c, grid.code(j));
      };
      grid.for_each_near_inner(
          grid.encode(x), [&](Slot s, const auto& c) { ++first_places, seen(s, c); },
          [&](Slot s, const auto& c) {
            EXPECT_NE(s, CellGrid<D>::kEmptySlot) << "past the fixed places only particles are passed on";
            seen(s, c);
          });
      EXPECT_EQ(first_places, CellGrid<D>::kFirstPlaces);
      std::vector<std::uint32_t> expected = plain.particles;
      std::sort(inner.begin(), inner.end());
      std::sort(expected.begin(), expected.end());
      EXPECT_EQ(inner, expected);
      ++inner_queries;
    }
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
  if (L >= 30) {
    EXPECT_GT(inner_queries, 0);
  }
  // Hidden for a search around its centre, a particle and the empty places are reported at the
  // farthest point of the box (the particle once, the others as they are); unhide restores it.
  EXPECT_DOUBLE_EQ(grid.hidden_distance2(), D * L * L / 4);
  for (std::uint32_t p = 0; p < n; p += 7) {
    const auto centre = grid.code(p);
    grid.hide_for_search(p);
    int seen_p = 0;
    grid.template for_each_near<Visit::kWithEmptyPlaces>(centre, [&](std::uint32_t s, const auto& c) {
      const std::uint32_t j = CellGrid<D>::particle(s);
      if (j == p || s == CellGrid<D>::kEmptySlot) {
        seen_p += j == p;
        EXPECT_EQ(grid.distance2(centre, c), grid.hidden_distance2());
      } else {
        EXPECT_EQ(c, grid.code(j));
      }
    });
    EXPECT_EQ(seen_p, 1);
    grid.unhide(p);
    EXPECT_EQ(grid.code(p), centre);
  }
}

// Codes: decode then encode is the identity (checkpoints save decoded centres), a point is within
// code_error() of its code, and the distance of two codes is the minimum image of the decoded
// centres' distance.
template <int D>
void check_codes(double L, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::array<double, D> edges;
  edges.fill(L);
  const gg::Box<D> box(edges);
  const CellGrid<D> grid(box, 2.0, 1);
  for (int q = 0; q < 10000; ++q) {
    Vec<D> a, b;
    for (int k = 0; k < D; ++k) a[k] = L * u(rng), b[k] = L * u(rng);
    const auto ca = grid.encode(a), cb = grid.encode(b);
    ASSERT_EQ(grid.encode(grid.decode(ca)), ca);
    const Vec<D> da = grid.decode(ca), db = grid.decode(cb);
    double err2 = 0, d2 = 0;
    for (int k = 0; k < D; ++k) {
      const double e = box.min_image(da[k] - a[k], k), d = box.min_image(da[k] - db[k], k);
      err2 += e * e;
      d2 += d * d;
    }
    ASSERT_LE(std::sqrt(err2), grid.code_error());
    ASSERT_NEAR(grid.distance2(ca, cb), d2, 1e-12 * L * L);
  }
  EXPECT_NEAR(grid.code_error(), 0.5 * std::sqrt(double(D)) * L / 4294967296.0, 1e-20 * L);
}

TEST(CellGrid, CodesRoundTripAndMeasureMinimumImages2D) { check_codes<2>(512.0, 5); }
TEST(CellGrid, CodesRoundTripAndMeasureMinimumImages1D) { check_codes<1>(1e5, 6); }

// The engine needs a new shell's centre within a tenth of a radius of where it was meant to be:
// a box so long that a code step is coarser than that is refused, not run wrongly.
TEST(CellGrid, EngineRefusesABoxTooLongForItsShells) {
  const auto engine_in = [](double L) {
    const gg::Box<1> box({L});
    ggsim::Engine<1, ggsim::Effects<>> eng(box, {{0.0}, {L / 2}}, {{1.0}, {-1.0}}, {});
    return eng.size();
  };
  EXPECT_EQ(engine_in(1e7), 2u);  // code step 2.3e-3, shell radius 0.35
  EXPECT_THROW(engine_in(1e8), gg::UsageError);
}

// Slots are byte offsets in 32 bits: a grid for more particles than they reach is refused with a
// clear error before anything is allocated (the request would need ~30 GB).
TEST(CellGrid, RefusesMoreParticlesThanItsSlotsReach) {
  const gg::Box<2> box({1e5, 1e5});
  const std::size_t too_many = ggsim::CellGrid<2>::max_particles() + 1;
  EXPECT_EQ(too_many, ggsim::kMaxParticles + 1);  // 2D reaches exactly what gg-sim allows
  EXPECT_THROW(ggsim::CellGrid<2>(box, 1.7, too_many), gg::UsageError);
  EXPECT_GE(ggsim::CellGrid<1>::max_particles(), ggsim::kMaxParticles);
}

// The engine's search without minimum images (far_from_edges) is for cells whose neighbours and
// their neighbours lie inside the box: 2 <= cell <= n - 3 along every axis, so never in a grid of
// fewer than 5 cells a side. Checked at the centre of every cell of grids 1 to 10 cells wide.
TEST(CellGrid, FarFromEdgesOnlyTwoCellsInFromEveryEdge) {
  for (int n = 1; n <= 10; ++n) {
    const double width = 1.7, L = n * width + 0.01;
    const gg::Box<2> box({L, L});
    // 1000 particles: cells holding one particle on average would be narrower than `width`, so the
    // grid does not widen them.
    const CellGrid<2> grid(box, width, 1000);
    ASSERT_NEAR(grid.min_cell_width(), L / n, 1e-12) << n << " cells a side";
    const auto inner = [n](int c) { return c >= 2 && c <= n - 3; };
    for (int cx = 0; cx < n; ++cx)
      for (int cy = 0; cy < n; ++cy) {
        const Vec<2> x{(cx + 0.5) * L / n, (cy + 0.5) * L / n};
        EXPECT_EQ(grid.far_from_edges(grid.encode(x)), inner(cx) && inner(cy))
            << "cell (" << cx << ", " << cy << ") of " << n << " a side";
      }
  }
}

TEST(CellGrid, VisitsReportEveryNearParticleOnce2D) { check_visits<2>(30.0, 200, 1); }
TEST(CellGrid, VisitsReportEveryNearParticleOnceInACrowd) { check_visits<2>(12.0, 400, 2); }
TEST(CellGrid, VisitsReportEveryNearParticleOnceInANarrowBox) { check_visits<2>(5.0, 20, 3); }
TEST(CellGrid, VisitsReportEveryNearParticleOnce1D) { check_visits<1>(40.0, 30, 4); }

}  // namespace
