#include "fit/power_law.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "fit/least_squares.hpp"
#include "gg/errors.hpp"

namespace gg::fit {
namespace {

// ln y = c0 + c1 ln t over the samples `idx`.
LsqResult log_log(const Series& s, const std::vector<std::size_t>& idx, const std::vector<double>& sigma) {
  std::vector<double> X, ly, sl;
  X.reserve(2 * idx.size());
  for (std::size_t k = 0; k < idx.size(); ++k) {
    const std::size_t i = idx[k];
    X.push_back(1.0);
    X.push_back(std::log(s.t[i]));
    ly.push_back(std::log(s.y[i]));
    if (!sigma.empty()) sl.push_back(sigma[k] / s.y[i]);  // delta method: sigma(ln y) = sigma(y) / y
  }
  return linear_lsq(X, 2, ly, sl);
}

}  // namespace

PowerLawFit fit_power_law(const Series& s, const Window& w) {
  const std::string what = "power-law fit";
  check_series(s, what);
  auto idx = select_window(s, w, 3, what);
  require_positive(s, idx, what);
  PowerLawFit f;
  auto sigma = weights_sigma(s, idx, f.raised_errors);
  LsqResult r = log_log(s, idx, sigma);
  f.exponent = r.coef[1];
  f.exponent_stderr = r.stderr_of(1);
  f.amplitude = std::exp(r.coef[0]);
  f.log_amplitude_stderr = r.stderr_of(0);
  f.amplitude_stderr = f.amplitude * f.log_amplitude_stderr;
  f.record(r, s, idx, !sigma.empty());
  return f;
}

PowerLawFit fit_power_law_offset(const Series& s, const Window& w) {
  const std::string what = "power-law fit with offset";
  check_series(s, what);
  auto idx = select_window(s, w, 4, what);
  for (std::size_t i : idx)
    if (!(s.t[i] > 0))
      throw RuntimeError(what + ": t = " + fmt(s.t[i]) + " <= 0 in the window; start the window after t = 0");
  PowerLawFit f;
  auto sigma = weights_sigma(s, idx, f.raised_errors);
  std::vector<double> x, y;
  for (std::size_t i : idx) {
    x.push_back(s.t[i]);
    y.push_back(s.y[i]);
  }
  // ln y = ln(c0 + c1 t^c2), in ln y for the same reason as the plain fit: relative fluctuations
  // have one size over decades of y. With ensemble error bars, sigma(ln y) = sigma(y) / y.
  std::vector<double> lny, sl;
  for (std::size_t k = 0; k < y.size(); ++k) {
    if (!(y[k] > 0))
      throw RuntimeError(what + ": non-positive value y = " + fmt(y[k]) + " at t = " + fmt(x[k]) +
                         "; the fit takes ln y: choose a window where the data are positive");
    lny.push_back(std::log(y[k]));
    if (!sigma.empty()) sl.push_back(sigma[k] / y[k]);
  }
  const ModelFn model = [](double t, const double* c, double* g) {
    const double p = std::pow(t, c[2]);
    const double m = c[0] + c[1] * p;
    g[0] = 1.0 / m;
    g[1] = p / m;
    g[2] = c[1] * p * std::log(t) / m;
    return std::log(std::abs(m));
  };
  const double ymin = *std::min_element(y.begin(), y.end());
  LsqResult best;
  bool found = false;
  std::string last_error;
  // Start from plateau guesses y0 = q * min(y): a log-log fit of y - y0 gives A and z to start from.
  for (double q : {0.0, 0.5, 0.8, 0.9, 0.95, 0.99}) {
    if (q > 0 && ymin <= 0) continue;
    const double y0 = q * ymin;
    Series rest;
    for (std::size_t k = 0; k < x.size(); ++k) {
      rest.t.push_back(x[k]);
      rest.y.push_back(y[k] - y0);
    }
    try {
      std::vector<std::size_t> all(x.size());
      for (std::size_t k = 0; k < all.size(); ++k) all[k] = k;
      require_positive(rest, all, what);
      LsqResult g = log_log(rest, all, {});
      LsqResult r = nonlinear_lsq(model, 3, x, lny, sl, {y0, std::exp(g.coef[0]), g.coef[1]});
      if (!found || r.chi2 < best.chi2) {
        best = r;
        found = true;
      }
    } catch (const std::exception& e) {
      last_error = e.what();
    }
  }
  if (!found) throw RuntimeError(what + ": no start converged (" + last_error + ")");
  f.offset = best.coef[0];
  f.offset_stderr = best.stderr_of(0);
  f.amplitude = best.coef[1];
  f.amplitude_stderr = best.stderr_of(1);
  f.log_amplitude_stderr = f.amplitude != 0 ? f.amplitude_stderr / std::abs(f.amplitude) : 0;
  f.exponent = best.coef[2];
  f.exponent_stderr = best.stderr_of(2);
  f.record(best, s, idx, !sigma.empty());
  f.with_offset = true;
  return f;
}

LocalExponent local_exponent(const Series& s, double decades) {
  const std::string what = "local exponent";
  check_series(s, what);
  if (!(decades > 0) || !std::isfinite(decades))
    throw UsageError(what + ": --window must be a positive number of decades (got " + fmt(decades) + ")");
  std::vector<std::size_t> pos;
  for (std::size_t i = 0; i < s.size(); ++i)
    if (s.t[i] > 0) pos.push_back(i);
  LocalExponent out;
  if (pos.empty()) throw RuntimeError(what + ": no samples with t > 0");
  const double lo = std::log10(s.t[pos.front()]), hi = std::log10(s.t[pos.back()]);
  const double half = decades / 2;
  const double eps = 1e-12;
  for (std::size_t i : pos) {
    const double c = std::log10(s.t[i]);
    if (c - half < lo - eps || c + half > hi + eps) continue;  // window would stick out of the data
    std::vector<std::size_t> idx;
    for (std::size_t j : pos)
      if (std::abs(std::log10(s.t[j]) - c) <= half + eps) idx.push_back(j);
    if (idx.size() < 3) continue;
    require_positive(s, idx, what);
    std::size_t raised = 0;
    auto sigma = weights_sigma(s, idx, raised);
    LsqResult r = log_log(s, idx, sigma);
    out.t.push_back(s.t[i]);
    out.exponent.push_back(r.coef[1]);
    out.err.push_back(r.stderr_of(1));
  }
  if (out.t.empty())
    throw RuntimeError(what + ": no time has a full window of " + fmt(decades) +
                       " decades with >= 3 samples inside the data (span " + fmt(hi - lo) +
                       " decades); use a smaller --window");
  return out;
}

}  // namespace gg::fit
