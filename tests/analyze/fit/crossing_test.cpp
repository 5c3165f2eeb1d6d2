// gg-fit crossing's library (fit/crossing.hpp): crossing times on hand-made series whose answer is
// known in closed form, the slope of ln t* against ln x and its verdict, and the slope recovered from
// synthetic ensembles whose crossing time scales as x^kappa.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "calibration.hpp"
#include "fit/crossing.hpp"
#include "fit/ensemble.hpp"
#include "synthetic.hpp"

using namespace gg::fit;

namespace {

Series series(const std::vector<double>& t, const std::vector<double>& y) { return Series{t, y, {}}; }

// 8 samples per decade from t = 1, as the study's snapshots.
std::vector<double> snapshot_times(int n) { return gg::fit::testing::log_times(1, std::pow(10.0, (n - 1) / 8.0), n); }

}  // namespace

// y = a + b ln t is linear in ln t, so the interpolation is exact: t* = exp((level - a) / b), from below
// (b > 0) and from above (b < 0), also between samples and with either rule.
TEST(Crossing, LinearRampInLnTGivesTheClosedForm) {
  const auto t = snapshot_times(33);
  for (double b : {0.1, -0.07}) {
    std::vector<double> y;
    for (double ti : t) y.push_back(0.3 + b * std::log(ti));
    for (double level : {0.5, 0.6}) {
      const double lv = b > 0 ? level : 0.6 - level;  // from above: 0.1 and 0.0 (a share of 0 is fine)
      const double exact = std::exp((lv - 0.3) / b);
      EXPECT_NEAR(crossing_time(series(t, y), lv, CrossingRule::first), exact, 1e-9 * exact) << b << " " << lv;
      EXPECT_NEAR(crossing_time(series(t, y), lv, CrossingRule::stays), exact, 1e-9 * exact) << b << " " << lv;
    }
  }
}

// A 0/1 step between two samples crosses 1/2 half-way between them in ln t (the geometric mean); a
// step of 0.25 (a quarter of the runs) reaches 0.5 only at the next step.
TEST(Crossing, StepFunctionCrossesHalfWayInLnT) {
  const auto t = snapshot_times(25);
  std::vector<double> y(t.size(), 0.0), q(t.size(), 0.0);
  for (std::size_t k = 10; k < t.size(); ++k) y[k] = 1, q[k] = k < 14 ? 0.25 : 0.75;
  EXPECT_NEAR(crossing_time(series(t, y), 0.5, CrossingRule::first), std::sqrt(t[9] * t[10]), 1e-9 * t[10]);
  EXPECT_NEAR(crossing_time(series(t, y), 0.25, CrossingRule::first), t[9] * std::pow(t[10] / t[9], 0.25), 1e-9 * t[10]);
  // From 0.25 at t[13] to 0.75 at t[14]: half-way.
  EXPECT_NEAR(crossing_time(series(t, q), 0.5, CrossingRule::first), std::sqrt(t[13] * t[14]), 1e-9 * t[14]);
  // Reached at a sample: that sample's time; on the level from the start: the first time.
  EXPECT_NEAR(crossing_time(series(t, y), 1.0, CrossingRule::first), t[10], 1e-12 * t[10]);
  std::vector<double> flat(t.size(), 0.5);
  flat.back() = 0.7;
  EXPECT_EQ(crossing_time(series(t, flat), 0.5, CrossingRule::first), t[0]);
}

// A series that crosses, falls back and crosses again for good: the first crossing and the one after
// which it stays differ, each interpolated in its own interval.
TEST(Crossing, StaysSkipsACrossingThatFallsBack) {
  const std::vector<double> t{1, 2, 4, 8, 16, 32, 64, 128};
  const std::vector<double> y{0.0, 0.2, 0.6, 0.4, 0.3, 0.55, 0.7, 0.9};
  // 0.2 -> 0.6 between t = 2 and 4: a quarter of the way in ln t, 2^(1.25).
  EXPECT_NEAR(crossing_time(series(t, y), 0.5, CrossingRule::first), std::pow(2.0, 1.75), 1e-12);
  // 0.3 -> 0.55 between t = 16 and 32: 0.8 of the way, 2^4.8.
  EXPECT_NEAR(crossing_time(series(t, y), 0.5, CrossingRule::stays), std::pow(2.0, 4.8), 1e-12);
  // Falling back at the end: stays never holds.
  std::vector<double> back = y;
  back.back() = 0.45;
  EXPECT_TRUE(std::isnan(crossing_time(series(t, back), 0.5, CrossingRule::stays)));
  EXPECT_NE(no_crossing_reason(series(t, back), 0.5, CrossingRule::stays).find("does not stay"), std::string::npos);
  EXPECT_EQ(no_crossing_reason(series(t, y), 0.5, CrossingRule::stays), "");
}

TEST(Crossing, NeverReachedIsNaNWithItsReason) {
  const std::vector<double> t{1, 10, 100};
  const std::vector<double> y{0.1, 0.2, 0.3};
  EXPECT_TRUE(std::isnan(crossing_time(series(t, y), 0.5, CrossingRule::first)));
  EXPECT_TRUE(std::isnan(crossing_time(series(t, y), 0.5, CrossingRule::stays)));
  EXPECT_NE(no_crossing_reason(series(t, y), 0.5, CrossingRule::first).find("never reaches 0.5"), std::string::npos);
  EXPECT_TRUE(std::isnan(crossing_time(series({}, {}), 0.5, CrossingRule::first)));
}

// A sample at t = 0 has no ln t: the segment from it is interpolated linearly in t.
TEST(Crossing, SegmentFromTimeZeroIsLinearInT) {
  EXPECT_NEAR(crossing_time(series({0, 10, 100}, {0, 1, 1}), 0.25, CrossingRule::first), 2.5, 1e-12);
}

// Two points: the line through them, the error propagated, Welch-Satterthwaite's dof in closed form.
// --per-run on three runs of 0/1 steps on the grid t = 1, 10, 100, 1000: run r steps up between samples
// r and r + 1, so its own crossing of 1/2 is the geometric midpoint 10^(r + 1/2); the mean of ln t_r is
// ln 10^1.5 and its standard error ln 10 / sqrt(3) (the sd of 0.5, 1.5, 2.5 decades is 1 decade).
// The mean's crossing reads the median run. A run that never steps up leaves the mean censored (NaN).
TEST(Crossing, MeanOfTheRunsOwnTimesForSteps) {
  Ensemble e;
  e.t = {1, 10, 100, 1000};
  e.runs = {{0, 1, 1, 1}, {0, 0, 1, 1}, {0, 0, 0, 1}};
  const CrossingEstimate c = mean_of_crossings(e, 0.5, CrossingRule::first);
  EXPECT_NEAR(c.log_time, 1.5 * std::log(10.0), 1e-12);
  EXPECT_NEAR(c.log_time_stderr, std::log(10.0) / std::sqrt(3.0), 1e-12);
  EXPECT_EQ(c.log_time_dof, 2);
  EXPECT_EQ(c.runs_reaching, 3u);
  EXPECT_NEAR(crossing_of_mean(e, 0.5, CrossingRule::first).log_time, 1.5 * std::log(10.0), 1e-12);  // mean 1/3 -> 2/3 between 10 and 100
  e.runs.push_back({0, 0, 0, 0});
  const CrossingEstimate censored = mean_of_crossings(e, 0.5, CrossingRule::first);
  EXPECT_TRUE(std::isnan(censored.log_time));
  EXPECT_EQ(censored.runs_reaching, 3u);
}

TEST(CrossingSlope, TwoPointsInClosedFormAndThreeOnALine) {
  const double v1 = 0.01, v2 = 0.04, d1 = 7, d2 = 3, dx = std::log(4.0);
  const CrossingSlope s = crossing_slope({512, 2048}, {8, 4}, {std::log(100.0), std::log(200.0)}, {v1, v2}, {d1, d2});
  EXPECT_NEAR(s.slope, 0.5, 1e-12);
  EXPECT_NEAR(s.slope_stderr, std::sqrt(v1 + v2) / dx, 1e-12);
  EXPECT_NEAR(s.slope_dof, (v1 + v2) * (v1 + v2) / (v1 * v1 / d1 + v2 * v2 / d2), 1e-9);
  EXPECT_EQ(s.points, 2u);
  // Three exact points t* = 3 x^0.7, unequal weights: the slope is exact; a NaN point is left out.
  std::vector<double> x{512, 1024, 2048, 4096}, w{8, 8, 4, 8}, lt, var{0.01, 0.02, 0.05, 0.01}, dof{7, 7, 3, 7};
  for (double xi : x) lt.push_back(std::log(3 * std::pow(xi, 0.7)));
  lt[3] = std::nan("");
  const CrossingSlope t = crossing_slope(x, w, lt, var, dof);
  EXPECT_NEAR(t.slope, 0.7, 1e-12);
  EXPECT_EQ(t.points, 3u);
  // Weights 8, 8, 4 at u = ln x = u0 + (0, 1, 2) ln 2: u_w = u0 + 0.8 ln 2, S = (8 0.64 + 8 0.04 + 4 1.44) ln^2 2
  // = 11.2 ln^2 2, c_j = w_j (u_j - u_w) / S = (-6.4, 1.6, 4.8) / (11.2 ln 2).
  const double c0 = -6.4 / 11.2 / std::log(2.0), c1 = 1.6 / 11.2 / std::log(2.0), c2 = 4.8 / 11.2 / std::log(2.0);
  const double v = c0 * c0 * var[0] + c1 * c1 * var[1] + c2 * c2 * var[2];
  EXPECT_NEAR(t.slope_stderr, std::sqrt(v), 1e-12);
  EXPECT_NEAR(t.slope_dof, v * v / (std::pow(c0 * c0 * var[0], 2) / 7 + std::pow(c1 * c1 * var[1], 2) / 7 + std::pow(c2 * c2 * var[2], 2) / 3), 1e-9);
  EXPECT_TRUE(std::isnan(crossing_slope({512, 1024}, {8, 8}, {1, std::nan("")}, {0.1, 0.1}, {7, 7}).slope));
}

TEST(CrossingSlope, Verdicts) {
  // dof infinite: the normal's 2 sigma.
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(slope_verdict({0.5, 0.1, inf, 3}, 2, 0.1), "grows with x");
  EXPECT_EQ(slope_verdict({-0.5, 0.1, inf, 3}, 2, 0.1), "falls with x");
  EXPECT_EQ(slope_verdict({0.01, 0.04, inf, 3}, 2, 0.1), "independent of x");
  EXPECT_EQ(slope_verdict({0.05, 0.04, inf, 3}, 2, 0.1), "undecided");
  // 3 dof widen 0.15 +- 2 x 0.07 (excludes 0) to +- 3.31 x 0.07 (does not).
  EXPECT_EQ(slope_verdict({0.15, 0.07, inf, 3}, 2, 0.1), "grows with x");
  EXPECT_EQ(slope_verdict({0.15, 0.07, 3, 3}, 2, 0.1), "undecided");
  EXPECT_EQ(slope_verdict({std::nan(""), 0.1, 3, 0}, 2, 0.1), "undecided");
}

// Synthetic ensembles (calibration.hpp): 8, 8 and 4 runs at x = 512, 1024, 2048 whose crossing time
// scales as x^kappa. The slope comes back within a few of its standard errors (the mean of 40 trials'
// slopes within 0.05 of kappa), its 2-sigma interval holds kappa in most trials, and kappa = 0.5 is seen
// to grow.
TEST(CrossingSlope, RecoversKappaFromSyntheticEnsembles) {
  for (double kappa : {0.0, 0.5}) {
    double sum = 0;
    int covered = 0, grows = 0;
    for (unsigned long seed = 1; seed <= 40; ++seed) {
      const calibration::CrossingTrial c = calibration::crossing_trial(seed, kappa);
      ASSERT_TRUE(std::isfinite(c.slope.slope)) << seed;
      sum += c.slope.slope, covered += c.covered, grows += c.verdict == "grows with x";
    }
    EXPECT_NEAR(sum / 40, kappa, 0.05) << kappa;
    EXPECT_GE(covered, 35) << kappa;
    if (kappa > 0) {
      EXPECT_GE(grows, 30);
    }
  }
}
