// Tests of the late-growth readings of gg-fit on synthetic curves with known answers: the time-shift
// factor of a crossover curve (not a power law) and the honesty of its jackknife interval, the drift of
// the lag, the late exponent and the ratio at equal times.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "fit/at_equal.hpp"
#include "fit/ensemble.hpp"
#include "fit/late_growth.hpp"
#include "fit/shift.hpp"
#include "gg/errors.hpp"
#include "synthetic.hpp"

using namespace gg::fit;
using namespace gg::fit::testing;

namespace {

// A crossover from y ~ t^0.9 to y ~ t^0.4 around t = 100, as m(t) of a cooling gas crosses over: no
// single power law.
double crossover(double t) { return std::pow(t, 0.9) / std::sqrt(1 + t / 100); }

// R runs of crossover(s t / c) a, each with its own time stretch s and amplitude a (run-to-run
// scatter, correlated over the times of a run) and a little independent noise per sample. Both
// scatters are multiplicative, so the ensemble mean of B = the ensemble mean of A at t / c exactly.
Ensemble crossover_ensemble(Rng& rng, const std::vector<double>& t, double c, int R) {
  std::vector<RunData> runs;
  for (int r = 0; r < R; ++r) {
    const double s = std::exp(0.05 * rng.normal()), a = 1 + 0.05 * rng.normal();
    RunData run{t, 1, {}, "run" + std::to_string(r)};
    for (double x : t) run.values.push_back(a * crossover(s * x / c) * (1 + 0.01 * rng.normal()));
    runs.push_back(run);
  }
  return common_grid(runs, false);
}

Series exact(const std::vector<double>& t, double (*f)(double)) {
  Series s;
  s.t = t;
  for (double x : t) s.y.push_back(f(x));
  return s;
}

double shifted_by_7(double t) { return crossover(t / 7); }
// A lag that grows with y: B = A at (t / 7)^1.15, so t_B(y) / t_A(y) is not a constant.
double stretched(double t) { return crossover(std::pow(t / 7, 1.15)); }

}  // namespace

TEST(Shift, ExactShiftedCrossoverGivesItsFactorAndAConstantLag) {
  const auto t = log_times(1, 1e5, 60);
  const Series a = exact(t, crossover), b = exact(t, shifted_by_7);
  const ShiftSetup s = shift_setup(a, {10, 3000}, b, {30, 3e4}, 6);
  const ShiftFit f = fit_shift(a, b, s);
  EXPECT_NEAR(std::exp(f.log_factor), 7.0, 7.0 * 1e-3);
  ASSERT_EQ(f.log_lag.size(), 6u);
  // The lag is read by linear interpolation between samples 0.09 decades apart: exact to ~1e-3.
  for (double lag : f.log_lag) EXPECT_NEAR(lag, std::log(7.0), 2e-3);
  EXPECT_NEAR(f.drift, 0.0, 2e-3);
  EXPECT_NEAR(f.curvature, 0.0, 2e-3);
  EXPECT_LT(f.chi2_per_point, 1e-5);  // unweighted: the residual variance of ln y
}

TEST(Shift, StretchedCurveHasADriftingLag) {
  const auto t = log_times(1, 1e5, 60);
  const Series a = exact(t, crossover), b = exact(t, stretched);
  const ShiftFit f = fit_shift(a, b, shift_setup(a, {10, 3000}, b, {30, 3e4}, 6));
  // ln t_B = ln 7 + ln t_A / 1.15 at equal y: the lag falls as y grows.
  EXPECT_LT(f.drift, -0.05);
  EXPECT_GT(f.log_lag.front() - f.log_lag.back(), 0.2);
}

TEST(Shift, CurvatureIsTheQuadraticCoefficientOfTheLagOnTheLevels) {
  // ln lag = 1 + 0.3 u - 0.2 u^2, u = ln y mapped onto [-1, 1] over the levels: the curvature is -0.2
  // whichever levels are reached, as long as three are.
  const std::vector<double> levels{2, 4, 8, 16, 32};
  std::vector<double> lag;
  for (double y : levels) {
    const double u = 2 * std::log(y / 2) / std::log(16.0) - 1;
    lag.push_back(1 + 0.3 * u - 0.2 * u * u);
  }
  EXPECT_NEAR(lag_curvature(levels, lag), -0.2, 1e-12);
  lag[4] = std::nan("");
  EXPECT_NEAR(lag_curvature(levels, lag), -0.2, 1e-12);
  lag[0] = std::nan("");
  EXPECT_NEAR(lag_curvature(levels, lag), -0.2, 1e-12);
  lag[2] = std::nan("");
  EXPECT_TRUE(std::isnan(lag_curvature(levels, lag)));
}

TEST(Shift, JackknifeIntervalOfTheFactorCoversTheTruthOverNoisyTrials) {
  const auto t = log_times(1, 1e5, 50);
  Coverage factor, drift, curvature;
  for (unsigned long seed = 1; seed <= 200; ++seed) {
    Rng rng(7000 + seed);
    const Ensemble ea = crossover_ensemble(rng, t, 1, 8), eb = crossover_ensemble(rng, t, 7, 8);
    const Series a = mean_series(ea), b = mean_series(eb);
    const ShiftSetup s = shift_setup(a, {10, 3000}, b, {30, 3e4}, 6);
    const ShiftFit f = fit_shift(a, b, s);
    const auto se = jackknife_stderr({ea, eb}, [&](const std::vector<Series>& m) {
      return shift_parameters(fit_shift(m[0], m[1], s));
    });
    factor.add(f.log_factor, se[0], std::log(7.0));
    drift.add(f.drift, se[se.size() - 2], 0.0);
    curvature.add(f.curvature, se.back(), 0.0);
  }
  expect_honest(factor, "ln c of a shifted crossover");
  expect_honest(drift, "drift of the lag of a pure shift");
  expect_honest(curvature, "curvature of the lag of a pure shift");
}

TEST(Shift, CurvesWithoutACommonRangeAreRefusedNotFitted) {
  const auto t = log_times(1, 1e5, 60);
  const Series a = exact(t, crossover), b = exact(t, shifted_by_7);
  // A reaches at most crossover(10); B starts above it in its window.
  EXPECT_THROW(shift_setup(a, {1, 10}, b, {3e3, 1e5}, 6), gg::RuntimeError);
  EXPECT_THROW(shift_setup(a, {10, 3000}, b, {30, 3e4}, 1), gg::UsageError);
  EXPECT_THROW(shift_setup(a, {10, 11}, b, {30, 3e4}, 6), gg::RuntimeError);  // too few samples
}

TEST(LateExponent, PowerLawHasSettledAndCrossoverHasNot) {
  const auto t = log_times(1, 1e5, 60);
  Series p;
  p.t = t;
  for (double x : t) p.y.push_back(2 * std::pow(x, 0.55));
  const LateExponent fp = late_exponent(p, 1e5, 0.5);
  EXPECT_NEAR(fp.late, 0.55, 1e-9);
  EXPECT_NEAR(fp.change, 0.0, 1e-9);
  // The crossover's local exponent 0.9 - 0.5 (t/100) / (1 + t/100): near t ~ 3e3 about 0.42 and still falling.
  const LateExponent fc = late_exponent(exact(t, crossover), 1e4, 0.5);
  EXPECT_NEAR(fc.late, 0.9 - 0.5 * 31.6 / 32.6, 0.02);
  EXPECT_LT(fc.change, -0.01);
  EXPECT_DOUBLE_EQ(fc.late_window.t1, 1e4 / std::sqrt(10.0));
}

TEST(EqualTimeRatio, ScaledCurveGivesItsFactor) {
  const auto t = log_times(1, 1e4, 40);
  Series a = exact(t, crossover), b = a;
  for (double& y : b.y) y *= 0.37;
  // b sampled on other times: interpolated in ln y - ln t at a's times.
  Series c = exact(log_times(1.3, 1e4, 33), crossover);
  for (double& y : c.y) y *= 0.37;
  EXPECT_NEAR(std::exp(equal_time_ratio(a, b, {100, 1000}).log_ratio), 0.37, 1e-12);
  EXPECT_NEAR(std::exp(equal_time_ratio(a, c, {100, 1000}).log_ratio), 0.37, 0.37 * 2e-3);
  EXPECT_THROW(equal_time_ratio(a, b, {2e4, 3e4}), gg::RuntimeError);
}

TEST(AtEqual, ReadsYWhereXCrossesEachLevel) {
  // x = 1 / (1 + t)^2 falls, y = t^0.5 grows; B is A slowed by 3 in time (x_B(t) = x_A(t / 3)) with y
  // doubled: at every level of x, t_B = 3 t_A and y_B / y_A = 2 sqrt(3), to the interpolation's accuracy.
  const auto t = log_times(1, 1e4, 81);
  Series xa, ya, xb, yb;
  xa.t = ya.t = xb.t = yb.t = t;
  for (double s : t) {
    xa.y.push_back(std::pow(1 + s, -2.0)), ya.y.push_back(std::sqrt(s));
    xb.y.push_back(std::pow(1 + s / 3, -2.0)), yb.y.push_back(2 * std::sqrt(s));
  }
  EXPECT_NEAR(time_at_level(xa, std::pow(101.0, -2.0)), 100, 0.1);
  EXPECT_TRUE(std::isnan(time_at_level(xa, 1e-12)));  // never reached
  EXPECT_NEAR(value_at_time(ya, 50), std::sqrt(50.0), 1e-12);  // exact for a power law (linear in ln - ln)
  EXPECT_TRUE(std::isnan(value_at_time(ya, 2e4)));
  const std::vector<double> levels{1e-3, 1e-5};
  const AtEqual e = at_equal(xa, ya, xb, yb, levels);
  ASSERT_EQ(e.log_ratio.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_NEAR(time_at_level(xb, levels[k]), 3 * time_at_level(xa, levels[k]), 0.01 * time_at_level(xb, levels[k]));
    EXPECT_NEAR(e.log_ratio[k], std::log(2 * std::sqrt(3.0)), 2e-3);
  }
  EXPECT_NEAR(e.mean_log_ratio, (e.log_ratio[0] + e.log_ratio[1]) / 2, 1e-15);
  EXPECT_TRUE(std::isnan(at_equal(xa, ya, xb, yb, {1e-3, 1e-12}).mean_log_ratio));  // one level unreached
}
