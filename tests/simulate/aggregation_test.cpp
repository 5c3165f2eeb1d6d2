// The ballistic aggregation model (contact/aggregate.hpp, engine.hpp with Fx::kAggregate): what every
// merge must keep exactly, checked on the engine directly.
//  - total mass (N0, exactly) and total momentum (to round-off) over whole runs in 1D, 2D, 3D;
//  - no two particles overlap at any of many observation times (a cascade left undone would leave
//    a receding overlapping pair that never merges, seen at the next observation);
//  - a merge that makes the new particle overlap a third one takes the third in at once, at the
//    centre of mass of all three (cascade merging, as Trizac & Hansen, PRL 74, 4114 (1995));
//  - radii from the summed volume: R^d = sum of R^d.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "engine_harness.hpp"

namespace {

using Aggregation = ggsim::Effects<ggsim::AggregateEffect>;
using ggsim::Engine;
using ggsim::Vec;

// At log-spaced times: the totals and the closest approach of any two particles left, in units of
// their contact distance (all pairs: the runs are small).
template <int D>
struct Totals {
  std::vector<double> times;
  std::size_t k = 0;
  double min_gap = 1e300;  // min over observations of |r_ij| / (R_i + R_j)
  std::vector<double> mass;
  std::vector<Vec<D>> momentum;
  std::vector<std::size_t> left;
  double next_time() const { return k < times.size() ? times[k] : ggsim::kNever; }
  template <class E>
  void observe(E& eng, double t) {
    ++k;
    std::vector<Vec<D>> r, v;
    std::vector<double> m, rad;
    eng.for_each_particle(t, [&](std::uint32_t, const Vec<D>& x, const Vec<D>& u) { r.push_back(x), v.push_back(u); });
    eng.for_each_size([&](std::uint32_t, double mi, double ri) { m.push_back(mi), rad.push_back(ri); });
    ASSERT_EQ(r.size(), m.size());
    ASSERT_EQ(r.size(), eng.contact().alive());
    double M = 0;
    Vec<D> P{};
    for (std::size_t i = 0; i < r.size(); ++i) {
      M += m[i];
      for (int d = 0; d < D; ++d) P[d] += m[i] * v[i][d];
      for (std::size_t j = 0; j < i; ++j) {
        double s = 0;
        for (int d = 0; d < D; ++d) {
          const double x = eng.box().min_image(r[i][d] - r[j][d], d);
          s += x * x;
        }
        min_gap = std::min(min_gap, std::sqrt(s) / (rad[i] + rad[j]));
      }
    }
    mass.push_back(M), momentum.push_back(P), left.push_back(r.size());
  }
  template <class E> bool poll(const E&) { return false; }
};

template <int D>
void check_conservation(double L, double rho, std::uint64_t seed) {
  const auto s = ggtest::random_start<D>(L, rho, seed);
  const std::size_t n0 = s.r.size();
  Engine<D, Aggregation> eng(s.box, s.r, s.v, {});
  Totals<D> obs;
  for (int k = 0; k <= 300; ++k) obs.times.push_back(0.1 * std::pow(10.0, k / 75.0));  // 0.1 .. 1e3
  eng.run(obs.times.back(), ~0ull, obs);
  ASSERT_GE(obs.left.size(), 2u);
  EXPECT_LT(obs.left.back(), n0 / 4) << "too few merges to test anything";
  Vec<D> P0{};
  for (const auto& v : s.v)
    for (int d = 0; d < D; ++d) P0[d] += v[d];
  for (std::size_t k = 0; k < obs.mass.size(); ++k) {
    EXPECT_EQ(obs.mass[k], static_cast<double>(n0)) << "mass at t = " << obs.times[k];
    for (int d = 0; d < D; ++d)
      EXPECT_NEAR(obs.momentum[k][d], P0[d], 1e-12 * static_cast<double>(n0)) << "momentum at t = " << obs.times[k];
  }
  // Touching pairs sit at contact to round-off (kOverlapTolerance); an undone cascade overlaps by
  // a finite fraction.
  EXPECT_GE(obs.min_gap, 1 - 1e-9);
}

TEST(Aggregation, ConservesMassAndMomentumAndLeavesNoOverlap1D) { check_conservation<1>(4000, 0.3, 3); }
TEST(Aggregation, ConservesMassAndMomentumAndLeavesNoOverlap2D) { check_conservation<2>(40, 0.4, 4); }
TEST(Aggregation, ConservesMassAndMomentumAndLeavesNoOverlap3D) { check_conservation<3>(14, 0.3, 5); }

// A and B meet head on at t = 0.25 at (10.75, 10); their aggregate (radius sqrt(1/2)) reaches
// C, at rest 1.1 above, before either touched C (they pass it at 1.21 > 1): C is taken in at once.
TEST(Aggregation, CascadeTakesInWhatTheMergedParticleOverlaps) {
  const gg::Box<2> box({20.0, 20.0});
  const std::vector<Vec<2>> r{{10, 10}, {11.5, 10}, {10.75, 11.1}};
  const std::vector<Vec<2>> v{{1, 0.5}, {-1, 0.5}, {0, 0}};
  Engine<2, Aggregation> eng(box, r, v, {});
  ggtest::Silent none;
  EXPECT_EQ(eng.run(10, ~0ull, none), ggsim::StopReason::kOneLeft);
  EXPECT_EQ(eng.now(), 0.25);
  EXPECT_EQ(eng.contact().alive(), 1u);
  eng.for_each_size([&](std::uint32_t, double m, double radius) {
    EXPECT_EQ(m, 3);
    EXPECT_NEAR(radius, 0.5 * std::sqrt(3.0), 1e-15);  // the area of three disks
  });
  eng.for_each_particle(eng.now(), [&](std::uint32_t, const Vec<2>& x, const Vec<2>& u) {
    EXPECT_NEAR(x[0], 10.75, 1e-12);
    EXPECT_NEAR(x[1], (2 * 10.125 + 11.1) / 3, 1e-12);  // A and B moved up by 0.125
    EXPECT_NEAR(u[0], 0, 1e-15);
    EXPECT_NEAR(u[1], 1.0 / 3, 1e-15);  // momentum 2 x 0.5 over mass 3
  });
}

// Lengths add in 1D, volumes in 3D.
TEST(Aggregation, RadiusFromTheSummedVolume) {
  EXPECT_EQ(ggsim::merged_radius<1>(0.5, 1.5), 2.0);
  EXPECT_NEAR(ggsim::merged_radius<3>(0.5, 0.5), 0.5 * std::cbrt(2.0), 1e-15);
}

// Two rods meet in a box four diameters long: their aggregate (2 diameters) leaves no room for a
// shell (every edge must exceed two of the largest diameters, Engine::usable_skin), and the run
// stops there, cleanly.
TEST(Aggregation, AParticleThatOutgrowsTheBoxEndsTheRun) {
  const gg::Box<1> box({4.0});
  Engine<1, Aggregation> eng(box, {{0.5}, {2.0}, {3.2}}, {{1}, {-1}, {0}}, {});
  ggtest::Silent none;
  EXPECT_EQ(eng.run(10, ~0ull, none), ggsim::StopReason::kOutgrewBox);
  EXPECT_EQ(eng.contact().alive(), 2u);
}

}  // namespace
