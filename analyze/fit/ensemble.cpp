#include "fit/ensemble.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <gsl/gsl_cdf.h>

#include "gg/errors.hpp"

namespace gg::fit {
namespace {

bool same_time(double a, double b) { return std::abs(a - b) <= 1e-9 * std::max({1.0, std::abs(a), std::abs(b)}); }

void check_run(const RunData& r) {
  if (r.t.empty()) throw RuntimeError(r.name + ": no samples");
  if (r.cols == 0 || r.values.size() != r.t.size() * r.cols)
    throw RuntimeError(r.name + ": " + std::to_string(r.values.size()) + " values do not fill " +
                       std::to_string(r.t.size()) + " times x " + std::to_string(r.cols) +
                       " columns; the dataset's first axis must be its time axis");
  for (std::size_t k = 0; k < r.t.size(); ++k) {
    if (!std::isfinite(r.t[k])) throw RuntimeError(r.name + ": non-finite time at sample " + std::to_string(k));
    if (k > 0 && !(r.t[k] > r.t[k - 1]))
      throw RuntimeError(r.name + ": times are not increasing at sample " + std::to_string(k) + " (t = " +
                         fmt(r.t[k - 1]) + ", " + fmt(r.t[k]) + ")");
  }
  for (std::size_t k = 0; k < r.values.size(); ++k)
    if (!std::isfinite(r.values[k]))
      throw RuntimeError(r.name + ": non-finite value at sample " + std::to_string(k / r.cols) + " (t = " +
                         fmt(r.t[k / r.cols]) + ")");
}

// Values of run r at time tau (linear in ln t between its neighbours); false if it cannot be had.
bool value_at(const RunData& r, double tau, std::vector<double>& out) {
  auto it = std::lower_bound(r.t.begin(), r.t.end(), tau);
  const std::size_t k = static_cast<std::size_t>(it - r.t.begin());
  for (std::size_t kk : {k, k == 0 ? k : k - 1}) {
    if (kk < r.t.size() && same_time(r.t[kk], tau)) {
      out.assign(r.values.begin() + kk * r.cols, r.values.begin() + (kk + 1) * r.cols);
      return true;
    }
  }
  if (k == 0 || k >= r.t.size() || !(tau > 0) || !(r.t[k - 1] > 0)) return false;
  const double a = (std::log(tau) - std::log(r.t[k - 1])) / (std::log(r.t[k]) - std::log(r.t[k - 1]));
  out.resize(r.cols);
  for (std::size_t c = 0; c < r.cols; ++c)
    out[c] = (1 - a) * r.values[(k - 1) * r.cols + c] + a * r.values[k * r.cols + c];
  return true;
}

}  // namespace

Ensemble common_grid(const std::vector<RunData>& runs, bool interpolate) {
  if (runs.size() < 2)
    throw UsageError("an ensemble average needs at least 2 runs (got " + std::to_string(runs.size()) + ")");
  for (const RunData& r : runs) check_run(r);
  const RunData& first = runs.front();
  for (const RunData& r : runs)
    if (r.cols != first.cols)
      throw RuntimeError(r.name + " has " + std::to_string(r.cols) + " columns per time but " + first.name +
                         " has " + std::to_string(first.cols) + "; average runs of the same analysis settings");
  Ensemble e;
  e.cols = first.cols;
  if (!interpolate) {
    for (const RunData& r : runs) {
      if (r.t.size() != first.t.size())
        throw RuntimeError("runs of different length: " + first.name + " has " + std::to_string(first.t.size()) +
                           " samples, " + r.name + " has " + std::to_string(r.t.size()) +
                           "; pass --interpolate to put them on a common grid (linear in ln t)");
      for (std::size_t k = 0; k < r.t.size(); ++k)
        if (!same_time(r.t[k], first.t[k]))
          throw RuntimeError("runs on different time grids: " + first.name + " has t = " + fmt(first.t[k]) +
                             " but " + r.name + " has t = " + fmt(r.t[k]) + " at sample " + std::to_string(k) +
                             "; pass --interpolate to put them on a common grid (linear in ln t)");
    }
    e.t = first.t;
    for (const RunData& r : runs) e.runs.push_back(r.values);
    return e;
  }
  e.interpolated = true;
  e.runs.resize(runs.size());
  std::vector<double> v;
  for (double tau : first.t) {
    bool ok = true;
    std::vector<std::vector<double>> row(runs.size());
    for (std::size_t r = 0; r < runs.size() && ok; ++r) ok = value_at(runs[r], tau, row[r]);
    if (!ok) {
      ++e.dropped;
      continue;
    }
    e.t.push_back(tau);
    for (std::size_t r = 0; r < runs.size(); ++r) e.runs[r].insert(e.runs[r].end(), row[r].begin(), row[r].end());
  }
  if (e.t.empty())
    throw RuntimeError("the runs share no time range (each run must cover some common interval of t > 0)");
  return e;
}

Average average(const Ensemble& e) {
  const std::size_t R = e.size();
  if (R < 2) throw UsageError("an ensemble average needs at least 2 runs");
  const std::size_t n = e.t.size() * e.cols;
  Average a;
  a.t = e.t;
  a.cols = e.cols;
  a.runs = R;
  a.mean.assign(n, 0);
  a.err.assign(n, 0);
  for (std::size_t k = 0; k < n; ++k) {
    double m = 0;
    for (const auto& run : e.runs) m += run[k];
    m /= static_cast<double>(R);
    double ss = 0;
    for (const auto& run : e.runs) ss += (run[k] - m) * (run[k] - m);
    a.mean[k] = m;
    a.err[k] = std::sqrt(ss / static_cast<double>(R - 1) / static_cast<double>(R));
  }
  return a;
}

Series mean_series(const Ensemble& e) {
  if (e.cols != 1) throw RuntimeError("a fit needs a 1-D time series, not [T][" + std::to_string(e.cols) + "] data");
  Average a = average(e);
  return Series{a.t, a.mean, a.err};
}

Jackknife jackknife_linked(const std::vector<std::vector<Ensemble>>& groups, const Estimator& estimate) {
  for (const auto& g : groups)
    for (const Ensemble& e : g) {
      if (e.size() < 3)
        throw UsageError("the jackknife over runs needs at least 3 runs per ensemble (got " + std::to_string(e.size()) +
                         "); use --errors covariance");
      if (e.size() != g.front().size())
        throw RuntimeError("linked ensembles hold different numbers of runs (" + std::to_string(g.front().size()) + ", " +
                           std::to_string(e.size()) + "); average the same runs, in the same order, for each quantity");
    }
  std::vector<Series> base;
  for (const auto& g : groups)
    for (const Ensemble& e : g) base.push_back(mean_series(e));
  const std::size_t P = estimate(base).size();
  std::vector<double> var(P, 0.0), welch(P, 0.0);  // welch: sum_g v_g^2 / (R_g - 1)
  std::size_t first = 0;  // index in `base` of the group's first ensemble
  for (const auto& g : groups) {
    const std::size_t R = g.front().size();
    std::vector<std::vector<double>> est;
    for (std::size_t i = 0; i < R; ++i) {
      std::vector<Series> means = base;
      for (std::size_t m = 0; m < g.size(); ++m) {
        Ensemble loo = g[m];
        loo.runs.erase(loo.runs.begin() + static_cast<long>(i));
        means[first + m] = mean_series(loo);
        // The weights stay those of the whole ensemble: the leave-one-out estimates then differ only
        // by the data, and the jackknife measures the scatter of the estimator, not of its weights.
        means[first + m].err = base[first + m].err;
      }
      try {
        est.push_back(estimate(means));
      } catch (const std::exception&) {
        est.emplace_back();  // failed: marks every parameter undetermined
      }
    }
    for (std::size_t k = 0; k < P; ++k) {
      double m = 0;
      bool ok = true;
      for (const auto& v : est) {
        if (v.size() <= k || !std::isfinite(v[k])) ok = false;
        else m += v[k];
      }
      if (!ok) {
        var[k] = welch[k] = std::numeric_limits<double>::quiet_NaN();
        continue;
      }
      m /= static_cast<double>(R);
      double ss = 0;
      for (const auto& v : est) ss += (v[k] - m) * (v[k] - m);
      const double vg = ss * static_cast<double>(R - 1) / static_cast<double>(R);
      var[k] += vg;
      welch[k] += vg * vg / static_cast<double>(R - 1);
    }
    first += g.size();
  }
  Jackknife j;
  for (std::size_t k = 0; k < P; ++k) {
    j.se.push_back(std::sqrt(var[k]));
    // All groups without scatter: the estimate does not depend on the runs, and any quantile will do.
    j.dof.push_back(welch[k] > 0 ? var[k] * var[k] / welch[k] : std::numeric_limits<double>::infinity());
  }
  return j;
}

Jackknife jackknife(const std::vector<Ensemble>& groups, const Estimator& estimate) {
  std::vector<std::vector<Ensemble>> linked;
  for (const Ensemble& g : groups) linked.push_back({g});
  return jackknife_linked(linked, estimate);
}

std::vector<double> jackknife_stderr(const std::vector<Ensemble>& groups, const Estimator& estimate) {
  return jackknife(groups, estimate).se;
}

double Jackknife::halfwidth(std::size_t k, double sigmas) const { return student_quantile(sigmas, dof.at(k)) * se.at(k); }

double student_quantile(double sigmas, double dof) {
  if (!(dof > 0)) return std::numeric_limits<double>::quiet_NaN();
  if (std::isinf(dof)) return sigmas;
  return gsl_cdf_tdist_Qinv(gsl_cdf_ugaussian_Q(sigmas), dof);
}

Estimate difference(const Estimate& a, const Estimate& b) {
  const double va = a.se * a.se, vb = b.se * b.se, v = va + vb;
  const double welch = (a.dof > 0 ? va * va / a.dof : 0) + (b.dof > 0 ? vb * vb / b.dof : 0);
  return {a.value - b.value, std::sqrt(v), welch > 0 ? v * v / welch : std::numeric_limits<double>::infinity()};
}

bool within(const Estimate& e, double null, double sigmas) {
  return std::abs(e.value - null) <= student_quantile(sigmas, e.dof) * e.se;  // false for NaN
}

}  // namespace gg::fit
