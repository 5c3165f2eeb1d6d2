#include "fit/at_equal.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace gg::fit {

namespace {
constexpr double kNoValue = std::numeric_limits<double>::quiet_NaN();
}

double time_at_level(const Series& x, double level) {
  if (!(level > 0)) return kNoValue;
  const double lv = std::log(level);
  for (std::size_t i = 0; i + 1 < x.size(); ++i) {
    if (!(x.t[i] > 0 && x.y[i] > 0 && x.y[i + 1] > 0)) continue;
    const double a = std::log(x.y[i]) - lv, b = std::log(x.y[i + 1]) - lv;
    if (a == 0) return x.t[i];
    if (a * b > 0) continue;
    const double ta = std::log(x.t[i]), tb = std::log(x.t[i + 1]);
    return std::exp(ta + a / (a - b) * (tb - ta));
  }
  return x.size() > 0 && x.y.back() == level ? x.t.back() : kNoValue;
}

double value_at_time(const Series& y, double t) {
  if (!(t > 0) || y.size() == 0 || t < y.t.front() || t > y.t.back()) return kNoValue;
  const auto it = std::lower_bound(y.t.begin(), y.t.end(), t);
  const std::size_t j = static_cast<std::size_t>(it - y.t.begin());
  if (y.t[j] == t) return y.y[j];
  const double t0 = y.t[j - 1], t1 = y.t[j], y0 = y.y[j - 1], y1 = y.y[j];
  if (!(t0 > 0 && y0 > 0 && y1 > 0)) return kNoValue;
  const double f = std::log(t / t0) / std::log(t1 / t0);
  return std::exp(std::log(y0) + f * std::log(y1 / y0));
}

AtEqual at_equal(const Series& x_ref, const Series& y_ref, const Series& x_other, const Series& y_other,
                 const std::vector<double>& levels) {
  AtEqual a;
  double sum = 0;
  for (double level : levels) {
    const double yr = std::log(value_at_time(y_ref, time_at_level(x_ref, level)));
    const double yo = std::log(value_at_time(y_other, time_at_level(x_other, level)));
    a.log_y_ref.push_back(yr), a.log_y_other.push_back(yo), a.log_ratio.push_back(yo - yr);
    if (std::isfinite(yo - yr)) sum += yo - yr, ++a.reached;
  }
  a.mean_log_ratio = a.reached == levels.size() && a.reached > 0 ? sum / static_cast<double>(a.reached) : kNoValue;
  return a;
}

std::vector<double> at_equal_parameters(const AtEqual& a) {
  std::vector<double> p{a.mean_log_ratio};
  p.insert(p.end(), a.log_ratio.begin(), a.log_ratio.end());
  return p;
}

}  // namespace gg::fit
