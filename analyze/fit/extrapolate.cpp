#include "fit/extrapolate.hpp"

#include <algorithm>
#include <cmath>

#include "fit/ensemble.hpp"
#include "fit/least_squares.hpp"
#include "fit/series.hpp"
#include "gg/errors.hpp"

namespace gg::fit {

SizeExtrapolation extrapolate_in_inverse_size(const std::vector<double>& L, const std::vector<double>& y,
                                              const std::vector<double>& err) {
  if (L.size() != y.size() || L.size() != err.size())
    throw RuntimeError("extrapolation: " + std::to_string(L.size()) + " sizes for " + std::to_string(y.size()) +
                       " values and " + std::to_string(err.size()) + " errors");
  std::vector<double> x, v, s;
  for (std::size_t i = 0; i < L.size(); ++i) {
    if (!(L[i] > 0) || !std::isfinite(L[i])) throw RuntimeError("extrapolation: box size L = " + fmt(L[i]) + " is not > 0");
    if (!std::isfinite(y[i]) || !std::isfinite(err[i]) || !(err[i] > 0)) continue;
    x.push_back(1 / L[i]);
    v.push_back(y[i]);
    s.push_back(err[i]);
  }
  const std::size_t n = x.size();
  if (n < 2)
    throw RuntimeError("extrapolation in 1/L needs values with error bars at two or more box sizes (got " +
                       std::to_string(n) + ")");
  SizeExtrapolation r;
  r.points = n;
  if (n == 2) {
    // The line through both points; each parameter is linear in y0, y1 with independent errors.
    const double dx = x[1] - x[0];
    if (dx == 0) throw RuntimeError("extrapolation: the two box sizes are equal");
    r.slope = (v[1] - v[0]) / dx;
    r.limit = v[0] - r.slope * x[0];
    r.slope_stderr = std::hypot(s[0], s[1]) / std::abs(dx);
    r.limit_stderr = std::hypot(x[1] * s[0], x[0] * s[1]) / std::abs(dx);
    r.chi2_dof = std::nan("");
    return r;
  }
  std::vector<double> X;
  for (double xi : x) {
    X.push_back(1);
    X.push_back(xi);
  }
  const LsqResult f = linear_lsq(X, 2, v, s);
  r.limit = f.coef[0];
  r.slope = f.coef[1];
  r.limit_stderr = f.stderr_of(0);
  r.slope_stderr = f.stderr_of(1);
  r.chi2_dof = f.chi2_dof();
  return r;
}

Verdict equality_verdict(double value, double stderr, double expected, double sigmas, double tolerance, double dof) {
  const double half = student_quantile(sigmas, dof) * stderr;
  if (!std::isfinite(value) || !std::isfinite(half) || stderr < 0) return Verdict::undecided;
  const double lo = value - half, hi = value + half;
  if (expected < lo || expected > hi) return Verdict::rejected;
  const double band = std::abs(expected) * tolerance;
  if (lo >= expected - band && hi <= expected + band) return Verdict::supported;
  return Verdict::undecided;
}

Verdict ratio_verdict(double log_ratio, double se, double dof, double sigmas, double tolerance) {
  const double half = student_quantile(sigmas, dof) * se;
  if (!std::isfinite(log_ratio) || !std::isfinite(half) || se < 0) return Verdict::undecided;
  const double lo = log_ratio - half, hi = log_ratio + half, band = std::log1p(tolerance);
  if (lo > 0 || hi < 0) return Verdict::rejected;
  return lo >= -band && hi <= band ? Verdict::supported : Verdict::undecided;
}

Verdict combined_verdict(const std::vector<Verdict>& v) {
  if (v.empty()) return Verdict::undecided;
  if (std::find(v.begin(), v.end(), Verdict::rejected) != v.end()) return Verdict::rejected;
  if (std::all_of(v.begin(), v.end(), [](Verdict x) { return x == Verdict::supported; })) return Verdict::supported;
  return Verdict::undecided;
}

std::string verdict_name(Verdict v) {
  switch (v) {
    case Verdict::supported: return "supported";
    case Verdict::rejected: return "rejected";
    case Verdict::undecided: break;
  }
  return "undecided";
}

}  // namespace gg::fit
