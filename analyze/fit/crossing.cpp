#include "fit/crossing.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "fit/ensemble.hpp"

namespace gg::fit {

namespace {

constexpr double kNotReached = std::numeric_limits<double>::quiet_NaN();

// Whether sample k is reached; `below`: the series starts below the level.
bool is_reached(const Series& y, std::size_t k, double level, bool below) {
  return below ? y.y[k] >= level : y.y[k] <= level;
}

// The index of the first sample not equal to the level (y.size() if none).
std::size_t first_off_level(const Series& y, double level) {
  std::size_t k = 0;
  while (k < y.size() && y.y[k] == level) ++k;
  return k;
}

// Where the line through samples k and k + 1 (k not reached, k + 1 reached) meets the level.
double level_time_between(const Series& y, std::size_t k, double level) {
  const double f = (level - y.y[k]) / (y.y[k + 1] - y.y[k]);
  const double t0 = y.t[k], t1 = y.t[k + 1];
  if (!(t0 > 0)) return t0 + f * (t1 - t0);
  return std::exp(std::log(t0) + f * std::log(t1 / t0));
}

}  // namespace

double crossing_time(const Series& y, double level, CrossingRule rule) {
  if (y.size() == 0 || !std::isfinite(level)) return kNotReached;
  const std::size_t off = first_off_level(y, level);
  if (off == y.size()) return y.t.front();  // on the level throughout
  const bool below = y.y[off] < level;
  if (rule == CrossingRule::first) {
    if (off > 0) return y.t.front();  // on the level from the start
    for (std::size_t k = off; k < y.size(); ++k)
      if (is_reached(y, k, level, below)) return level_time_between(y, k - 1, level);
    return kNotReached;
  }
  if (!is_reached(y, y.size() - 1, level, below)) return kNotReached;
  std::size_t last = y.size() - 1;  // the last sample not reached exists: `off` is one
  while (is_reached(y, last, level, below)) --last;
  return level_time_between(y, last, level);
}

std::string no_crossing_reason(const Series& y, double level, CrossingRule rule) {
  if (std::isfinite(crossing_time(y, level, rule))) return "";
  if (y.size() == 0) return "the series is empty";
  if (!std::isfinite(level)) return "the level is not finite";
  const auto [lo, hi] = std::minmax_element(y.y.begin(), y.y.end());
  const std::string span = "spans [" + fmt(*lo) + ", " + fmt(*hi) + "], last " + fmt(y.y.back());
  if (rule == CrossingRule::stays && *lo <= level && *hi >= level)
    return "the mean reaches " + fmt(level) + " but does not stay there to its last sample (it " + span + ")";
  return "the mean never reaches " + fmt(level) + " (it " + span + ")";
}

CrossingEstimate crossing_of_mean(const Ensemble& e, double level, CrossingRule rule) {
  const auto est = [&](const std::vector<Series>& m) { return std::vector<double>{std::log(crossing_time(m[0], level, rule))}; };
  CrossingEstimate c{est({mean_series(e)})[0], kNotReached, kNotReached, 0};
  for (const auto& r : e.runs) c.runs_reaching += std::isfinite(crossing_time(Series{e.t, r, {}}, level, rule));
  if (std::isfinite(c.log_time)) {
    const Jackknife jk = jackknife({e}, est);
    c.log_time_stderr = jk.se[0], c.log_time_dof = jk.dof[0];
  }
  return c;
}

CrossingEstimate mean_of_crossings(const Ensemble& e, double level, CrossingRule rule) {
  std::vector<double> lt;
  for (const auto& r : e.runs) {
    const double t = crossing_time(Series{e.t, r, {}}, level, rule);
    if (std::isfinite(t) && t > 0) lt.push_back(std::log(t));
  }
  CrossingEstimate c{kNotReached, kNotReached, kNotReached, lt.size()};
  const double R = static_cast<double>(lt.size());
  if (lt.size() != e.size() || lt.size() < 2) return c;
  double mean = 0, ss = 0;
  for (double v : lt) mean += v / R;
  for (double v : lt) ss += (v - mean) * (v - mean);
  c.log_time = mean, c.log_time_stderr = std::sqrt(ss / (R - 1) / R), c.log_time_dof = R - 1;
  return c;
}

CrossingSlope crossing_slope(const std::vector<double>& x, const std::vector<double>& weight,
                             const std::vector<double>& log_time, const std::vector<double>& log_time_var,
                             const std::vector<double>& log_time_dof) {
  std::vector<std::size_t> use;
  for (std::size_t j = 0; j < x.size(); ++j)
    if (std::isfinite(log_time[j]) && std::isfinite(log_time_var[j]) && log_time_var[j] > 0 && x[j] > 0 && weight[j] > 0)
      use.push_back(j);
  CrossingSlope s{kNotReached, kNotReached, kNotReached, use.size()};
  if (use.size() < 2) return s;
  // Weighted mean of u = ln x; the slope is sum_j c_j ln t*_j, c_j = w_j (u_j - u_w) / S.
  double W = 0, U = 0;
  for (std::size_t j : use) W += weight[j], U += weight[j] * std::log(x[j]);
  U /= W;
  double S = 0;
  for (std::size_t j : use) S += weight[j] * (std::log(x[j]) - U) * (std::log(x[j]) - U);
  if (!(S > 0)) return s;
  double slope = 0, var = 0, welch = 0;
  for (std::size_t j : use) {
    const double c = weight[j] * (std::log(x[j]) - U) / S, v = c * c * log_time_var[j];
    slope += c * log_time[j];
    var += v;
    welch += log_time_dof[j] > 0 ? v * v / log_time_dof[j] : 0;
  }
  s.slope = slope;
  s.slope_stderr = std::sqrt(var);
  s.slope_dof = welch > 0 ? var * var / welch : std::numeric_limits<double>::infinity();
  return s;
}

std::string slope_verdict(const CrossingSlope& s, double sigmas, double tolerance) {
  const double half = student_quantile(sigmas, s.slope_dof) * s.slope_stderr;
  if (!std::isfinite(s.slope) || !std::isfinite(half)) return "undecided";
  const double lo = s.slope - half, hi = s.slope + half;
  if (lo > 0) return "grows with x";
  if (hi < 0) return "falls with x";
  if (lo >= -tolerance && hi <= tolerance) return "independent of x";
  return "undecided";
}

}  // namespace gg::fit
