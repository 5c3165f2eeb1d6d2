#include "fit/late_growth.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "fit/power_law.hpp"
#include "gg/errors.hpp"

namespace gg::fit {

LateExponent late_exponent(const Series& s, double t_end, double decades) {
  if (!(decades > 0) || !(t_end > 0))
    throw UsageError("late-exponent: --end and --decades must be positive");
  LateExponent f;
  const double r = std::pow(10.0, decades);
  f.late_window = {t_end / r, t_end};
  f.before_window = {t_end / (r * r), t_end / r};
  const PowerLawFit late = fit_power_law(s, f.late_window), before = fit_power_law(s, f.before_window);
  f.late = late.exponent, f.before = before.exponent, f.change = late.exponent - before.exponent;
  f.late_points = late.points, f.before_points = before.points;
  return f;
}

std::vector<double> late_exponent_parameters(const LateExponent& f) { return {f.late, f.before, f.change}; }

EqualTimeRatio equal_time_ratio(const Series& ref, const Series& other, const Window& w) {
  std::vector<double> x, v;  // other's ln t, ln y
  for (std::size_t i = 0; i < other.size(); ++i)
    if (other.t[i] > 0 && other.y[i] > 0) x.push_back(std::log(other.t[i])), v.push_back(std::log(other.y[i]));
  EqualTimeRatio r;
  double sum = 0;
  for (std::size_t i = 0; i < ref.size(); ++i) {
    if (!w.contains(ref.t[i]) || ref.t[i] <= 0 || ref.y[i] <= 0 || x.size() < 2) continue;
    const double lt = std::log(ref.t[i]);
    if (lt < x.front() || lt > x.back()) continue;
    const std::size_t j = std::min<std::size_t>(std::upper_bound(x.begin(), x.end(), lt) - x.begin(), x.size() - 1);
    const double f = (lt - x[j - 1]) / (x[j] - x[j - 1]);
    sum += v[j - 1] + f * (v[j] - v[j - 1]) - std::log(ref.y[i]);
    ++r.points;
  }
  if (r.points == 0)
    throw RuntimeError("ratio: no sample of the reference in " + fmt_window(w) +
                       " lies inside the other curve's times; choose a window both cover");
  r.log_ratio = sum / static_cast<double>(r.points);
  return r;
}

}  // namespace gg::fit
