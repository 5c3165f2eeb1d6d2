#pragma once
// Time-shift comparison of two growth curves with no assumed functional form: is y_B(t) = y_A(t / c)
// for one constant c? The reference y_A is interpolated linearly in ln y - ln t, so crossovers and
// drifting local exponents are compared as they are, not through a fitted power law. Two readings:
//  - the factor c that best maps B onto A (least squares of ln y_B(t_i) - ln y_A(t_i / c)
//    over B's samples whose y lies in the range both cover), with chi^2 per point of the collapsed
//    data as the quality of the collapse;
//  - the lag t_B(y) / t_A(y) at log-spaced levels of y, and its drift d ln lag / d ln y, which is 0
//    when c is a constant, and its curvature.
// The verdicts rest on the lag, with errors from the jackknife over both ensembles' runs (which carries
// the correlations between the times of a run) and Student-t quantiles for their few degrees of
// freedom: the curves collapse when neither the drift nor the curvature of ln lag departs from 0, the
// factor is a constant when the drift does not. (A chi^2 of the collapsed points against per-point
// variances rejects true collapses: each variance from R runs has R - 1 degrees of freedom, and the
// noise of a run is correlated in time; docs/PHYSICS.md "Calibration of the verdicts".)
// Both cover only the part of each curve inside its window (e.g. past the onset of growth and before
// finite size), and only the range of y both windows reach.
#include <cstddef>
#include <vector>

#include "fit/ensemble.hpp"
#include "fit/series.hpp"

namespace gg::fit {

// What a comparison is fixed by before any fit: the range of y both curves cover inside their
// windows, the samples of the other curve compared (those in that range, by time), the range of
// ln c searched, and the levels of the lag. Fixed from the full ensembles, so that the leave-one-out
// estimates of a jackknife compare the same things.
struct ShiftSetup {
  Window ref_window, other_window;
  double y_lo = 0, y_hi = 0;
  Window compared;                     // times of the other curve's compared samples
  double log_factor_lo = 0, log_factor_hi = 0;  // ln c searched: the lags' range, +-1
  std::vector<double> levels;          // log-spaced in [y_lo, y_hi]
};

// RuntimeError (naming both ranges and the fix) when the windows' y ranges do not overlap by more
// than a factor 1 + kMinOverlap, a window holds fewer than 3 samples with t, y > 0, fewer than 3 of
// the other's lie in the common range, or the curves do not both reach two of the levels.
inline constexpr double kMinOverlap = 0.05;
ShiftSetup shift_setup(const Series& ref, const Window& ref_window, const Series& other, const Window& other_window,
                       std::size_t levels);

struct ShiftFit {
  double log_factor = 0;            // ln c
  double chi2_per_point = 0;        // chi^2 / (points - 1) at the best c, by both curves' errors if weighted
  std::size_t points = 0;           // samples of B compared
  bool weighted = false;            // chi2_per_point by both curves' error bars (c itself is fitted unweighted)
  std::vector<double> log_lag;      // ln(t_B(y_k) / t_A(y_k)) at the setup's levels (NaN: not reached by both)
  double drift = 0;                 // slope of ln lag against ln y over the levels reached (NaN if < 2)
  double curvature = 0;             // lag_curvature over the setup's levels
};

// The fit for one setup (y_B(t) = y_A(t / c): the global minimum of chi^2 over the setup's range of
// ln c on a fine grid, refined by golden section; y_A continued linearly in ln y - ln t beyond its
// window's ends, where a trial c maps B's first or last samples).
ShiftFit fit_shift(const Series& ref, const Series& other, const ShiftSetup& setup);

// The quadratic coefficient of ln lag against u = ln y mapped onto [-1, 1] between the first and last
// of `levels`, over the levels whose lag is finite (NaN if fewer than 3).
double lag_curvature(const std::vector<double>& levels, const std::vector<double>& log_lag);

// [ln c, ln lag_0 .. ln lag_{K-1}, drift, curvature]: what a jackknife resamples.
std::vector<double> shift_parameters(const ShiftFit& f);

// The verdicts on one fit, given the jackknife of its shift_parameters and the level (a normal's
// +-sigmas, two-sided, alpha = 2 Q(sigmas)):
//  - collapses: the drift and the curvature each lie within their Student-t interval at alpha / 2
//    (Bonferroni: the joint test rejects a true collapse at most at rate alpha);
//  - constant: 1 if the drift lies within its interval at alpha, 0 if not, -1 if undetermined;
//  - the half width of the interval of ln c at alpha.
struct ShiftVerdict {
  bool collapses = false;
  int constant = -1;
  double log_factor_halfwidth = 0;
};
ShiftVerdict shift_verdict(const ShiftFit& f, const Jackknife& j, double sigmas);

// The time at which a curve first reaches y (linear in ln y - ln t between the samples around the
// crossing), within window w; NaN if it never does there.
double first_time_at(const Series& s, const Window& w, double y);

}  // namespace gg::fit
