#include "fit/shift.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include <gsl/gsl_cdf.h>

#include "gg/errors.hpp"

namespace gg::fit {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The samples of s inside w with t, y > 0, as ln t, ln y and the standard error of ln y (0 unweighted).
struct LogCurve {
  std::vector<double> x, y, sy;
  double y_min = 0, y_max = 0;  // of y itself
};

LogCurve log_curve(const Series& s, const Window& w, const std::string& what) {
  LogCurve c;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (!w.contains(s.t[i]) || s.t[i] <= 0 || s.y[i] <= 0) continue;
    c.x.push_back(std::log(s.t[i]));
    c.y.push_back(std::log(s.y[i]));
    c.sy.push_back(s.weighted() ? s.err[i] / s.y[i] : 0.0);
  }
  if (c.x.size() < 3)
    throw RuntimeError("shift: " + what + " has " + std::to_string(c.x.size()) + " samples with t, y > 0 in " +
                       fmt_window(w) + "; widen its window (3 are needed)");
  const auto [lo, hi] = std::minmax_element(c.y.begin(), c.y.end());
  c.y_min = std::exp(*lo), c.y_max = std::exp(*hi);
  return c;
}

// Linear interpolation of (x, v) at x0 (x ascending, >= 2 points), continued beyond the ends along
// the first and last segments.
double interpolate(const std::vector<double>& x, const std::vector<double>& v, double x0) {
  const auto it = std::upper_bound(x.begin(), x.end(), x0);
  const std::size_t j = std::clamp<std::size_t>(static_cast<std::size_t>(it - x.begin()), 1, x.size() - 1);
  const double f = (x0 - x[j - 1]) / (x[j] - x[j - 1]);
  return v[j - 1] + f * (v[j] - v[j - 1]);
}

// The lags ln(t_B(y) / t_A(y)) at the levels, NaN where either curve does not reach one.
std::vector<double> log_lags(const Series& ref, const Window& ref_window, const Series& other, const Window& other_window,
                             const std::vector<double>& levels) {
  std::vector<double> lag;
  for (double level : levels)
    lag.push_back(std::log(first_time_at(other, other_window, level) / first_time_at(ref, ref_window, level)));
  return lag;
}

}  // namespace

double first_time_at(const Series& s, const Window& w, double y) {
  const double ly = std::log(y);
  double px = kNaN, py = kNaN;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (!w.contains(s.t[i]) || s.t[i] <= 0 || s.y[i] <= 0) continue;
    const double x = std::log(s.t[i]), v = std::log(s.y[i]);
    if (v >= ly) {
      if (std::isnan(px)) return v == ly ? s.t[i] : kNaN;  // above y from the window's start: never crossed there
      return std::exp(px + (ly - py) / (v - py) * (x - px));
    }
    px = x, py = v;
  }
  return kNaN;
}

// The projection on the polynomial of degree 2 orthogonal to 1 and u over the levels reached.
double lag_curvature(const std::vector<double>& levels, const std::vector<double>& log_lag) {
  const double x0 = std::log(levels.front()), x1 = std::log(levels.back());
  std::vector<double> u, v;
  for (std::size_t k = 0; k < levels.size(); ++k)
    if (std::isfinite(log_lag[k])) u.push_back(2 * (std::log(levels[k]) - x0) / (x1 - x0) - 1), v.push_back(log_lag[k]);
  const double n = static_cast<double>(u.size());
  if (u.size() < 3) return kNaN;
  double mu = 0, mu2 = 0;
  for (double x : u) mu += x / n, mu2 += x * x / n;
  // p2 = u^2 - mu2 - b (u - mu), b the slope of u^2 on u.
  double suu = 0, su2u = 0;
  for (double x : u) suu += (x - mu) * (x - mu), su2u += (x * x - mu2) * (x - mu);
  const double b = su2u / suu;
  double num = 0, den = 0;
  for (std::size_t k = 0; k < u.size(); ++k) {
    const double p2 = u[k] * u[k] - mu2 - b * (u[k] - mu);
    num += p2 * v[k], den += p2 * p2;
  }
  return den > 0 ? num / den : kNaN;
}

ShiftSetup shift_setup(const Series& ref, const Window& ref_window, const Series& other, const Window& other_window,
                       std::size_t levels) {
  if (levels < 2) throw UsageError("shift: --levels must be >= 2 (the drift of the lag needs two levels)");
  const LogCurve a = log_curve(ref, ref_window, "the reference"), b = log_curve(other, other_window, "the other ensemble");
  ShiftSetup s;
  s.ref_window = ref_window, s.other_window = other_window;
  s.y_lo = std::max(a.y_min, b.y_min), s.y_hi = std::min(a.y_max, b.y_max);
  if (!(s.y_hi > s.y_lo * (1 + kMinOverlap)))
    throw RuntimeError("shift: the curves cover no common range of y inside their windows (reference: [" + fmt(a.y_min) +
                       ", " + fmt(a.y_max) + "] over t in " + fmt_window(ref_window) + "; other: [" + fmt(b.y_min) + ", " +
                       fmt(b.y_max) + "] over t in " + fmt_window(other_window) +
                       "); run the slower ensemble longer or start the faster one's window earlier");
  // Levels strictly inside the range (the ends are where one curve only just reaches).
  for (std::size_t k = 0; k < levels; ++k)
    s.levels.push_back(s.y_lo * std::pow(s.y_hi / s.y_lo, (static_cast<double>(k) + 0.5) / static_cast<double>(levels)));
  // The other curve's samples in the common range: the first and last of them by time.
  double t_lo = std::numeric_limits<double>::infinity(), t_hi = 0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < b.x.size(); ++i)
    if (b.y[i] >= std::log(s.y_lo) && b.y[i] <= std::log(s.y_hi))
      t_lo = std::min(t_lo, std::exp(b.x[i])), t_hi = std::max(t_hi, std::exp(b.x[i])), ++n;
  if (n < 3)
    throw RuntimeError("shift: " + std::to_string(n) + " samples of the other ensemble lie in the common range [" +
                       fmt(s.y_lo) + ", " + fmt(s.y_hi) + "]; 3 are needed (sample it more densely or widen the windows)");
  s.compared = {t_lo * (1 - 1e-12), t_hi * (1 + 1e-12)};
  // ln c is searched within 1 of the range of the lags (a factor e beyond either end).
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (double lag : log_lags(ref, ref_window, other, other_window, s.levels))
    if (std::isfinite(lag)) lo = std::min(lo, lag), hi = std::max(hi, lag);
  if (!(hi >= lo))
    throw RuntimeError("shift: the curves do not both reach any level of y in [" + fmt(s.y_lo) + ", " + fmt(s.y_hi) +
                       "] inside their windows (is one of them decreasing there?)");
  s.log_factor_lo = lo - 1, s.log_factor_hi = hi + 1;
  return s;
}

ShiftFit fit_shift(const Series& ref, const Series& other, const ShiftSetup& setup) {
  const LogCurve a = log_curve(ref, setup.ref_window, "the reference");
  const LogCurve b = log_curve(other, setup.other_window, "the other ensemble");
  // B's compared samples: a fixed set (the setup's times), so chi^2 is a function of c alone.
  std::vector<std::size_t> used;
  for (std::size_t i = 0; i < b.x.size(); ++i)
    if (setup.compared.contains(std::exp(b.x[i]))) used.push_back(i);
  if (used.size() < 3)
    throw RuntimeError("shift: " + std::to_string(used.size()) + " samples of the other ensemble in " +
                       fmt_window(setup.compared) + "; 3 are needed");
  const double lc_lo = setup.log_factor_lo, lc_hi = setup.log_factor_hi;
  const bool weighted = ref.weighted() && other.weighted();
  // The sum of squared residuals of ln y, each divided by `var` (1: unweighted).
  const auto sum_sq = [&](double lc, bool by_errors) {
    double s = 0;
    for (std::size_t i : used) {
      const double xa = b.x[i] - lc, r = b.y[i] - interpolate(a.x, a.y, xa);
      const double var = by_errors ? b.sy[i] * b.sy[i] + std::pow(interpolate(a.x, a.sy, xa), 2) : 1.0;
      s += r * r / (var > 0 ? var : 1.0);
    }
    return s;
  };
  // c minimises the unweighted sum: weights from the variances of a few runs follow the data's own
  // fluctuations, and a fit by them scatters more than the jackknife (which keeps them fixed) sees
  // (4 runs a side: the interval of c held the truth in 89% of trials instead of 95%).
  const auto chi2 = [&](double lc) { return sum_sq(lc, false); };
  // The global minimum on a fine grid, then golden section between its neighbours (chi^2 is piecewise
  // smooth: the interpolation has kinks at A's samples).
  constexpr int kGrid = 400;
  int best = 0;
  double best_chi2 = std::numeric_limits<double>::infinity();
  const double step = (lc_hi - lc_lo) / kGrid;
  for (int k = 0; k <= kGrid; ++k) {
    const double v = chi2(lc_lo + k * step);
    if (v < best_chi2) best_chi2 = v, best = k;
  }
  double lo = lc_lo + std::max(best - 1, 0) * step, hi = lc_lo + std::min(best + 1, kGrid) * step;
  const double g = (std::sqrt(5.0) - 1) / 2;
  double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo), f1 = chi2(x1), f2 = chi2(x2);
  for (int it = 0; it < 60 && hi - lo > 1e-12; ++it) {
    if (f1 < f2) hi = x2, x2 = x1, f2 = f1, x1 = hi - g * (hi - lo), f1 = chi2(x1);
    else lo = x1, x1 = x2, f1 = f2, x2 = lo + g * (hi - lo), f2 = chi2(x2);
  }
  ShiftFit f;
  f.log_factor = 0.5 * (lo + hi);
  f.points = used.size();
  f.chi2_per_point = sum_sq(f.log_factor, weighted) / static_cast<double>(used.size() - 1);
  f.weighted = weighted;
  // The lag at each level, and its drift against ln y (ordinary least squares over the levels both
  // curves reach; a curve of fewer runs, as in a jackknife, may fall short of the highest).
  f.log_lag = log_lags(ref, setup.ref_window, other, setup.other_window, setup.levels);
  double sx = 0, sy = 0, sxx = 0, sxy = 0, n = 0;
  for (std::size_t k = 0; k < f.log_lag.size(); ++k) {
    const double lag = f.log_lag[k], x = std::log(setup.levels[k]);
    if (!std::isfinite(lag)) continue;
    sx += x, sy += lag, sxx += x * x, sxy += x * lag, n += 1;
  }
  f.drift = n >= 2 ? (n * sxy - sx * sy) / (n * sxx - sx * sx) : kNaN;
  f.curvature = lag_curvature(setup.levels, f.log_lag);
  return f;
}

std::vector<double> shift_parameters(const ShiftFit& f) {
  std::vector<double> p{f.log_factor};
  p.insert(p.end(), f.log_lag.begin(), f.log_lag.end());
  p.push_back(f.drift);
  p.push_back(f.curvature);
  return p;
}

ShiftVerdict shift_verdict(const ShiftFit& f, const Jackknife& j, double sigmas) {
  const std::size_t d = j.se.size() - 2, q = j.se.size() - 1;  // drift, curvature
  const auto within = [&](double v, std::size_t k, double s) { return std::abs(v) <= j.halfwidth(k, s); };
  // The normal's sigmas whose two-sided level is half that of `sigmas`.
  const double half_level = gsl_cdf_ugaussian_Qinv(gsl_cdf_ugaussian_Q(sigmas) / 2);
  ShiftVerdict v;
  v.collapses = within(f.drift, d, half_level) && within(f.curvature, q, half_level);
  v.constant = !std::isfinite(f.drift) || !std::isfinite(j.halfwidth(d, sigmas)) ? -1 : within(f.drift, d, sigmas) ? 1 : 0;
  v.log_factor_halfwidth = j.halfwidth(0, sigmas);
  return v;
}

}  // namespace gg::fit
