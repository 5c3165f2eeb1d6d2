#include "fit/ensemble.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

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

std::vector<double> jackknife_stderr(const std::vector<Ensemble>& groups, const Estimator& estimate) {
  for (const Ensemble& g : groups)
    if (g.size() < 3)
      throw UsageError("the jackknife over runs needs at least 3 runs per ensemble (got " +
                       std::to_string(g.size()) + "); use --errors covariance");
  std::vector<Series> base;
  for (const Ensemble& g : groups) base.push_back(mean_series(g));
  std::vector<double> var(estimate(base).size(), 0.0);
  for (std::size_t gi = 0; gi < groups.size(); ++gi) {
    const Ensemble& g = groups[gi];
    const std::size_t R = g.size();
    std::vector<std::vector<double>> est;
    for (std::size_t i = 0; i < R; ++i) {
      Ensemble loo = g;
      loo.runs.erase(loo.runs.begin() + static_cast<long>(i));
      std::vector<Series> means = base;
      means[gi] = mean_series(loo);
      // The weights stay those of the whole ensemble: the leave-one-out estimates then differ only
      // by the data, and the jackknife measures the scatter of the estimator, not of its weights.
      means[gi].err = base[gi].err;
      try {
        est.push_back(estimate(means));
      } catch (const std::exception&) {
        est.emplace_back();  // failed: marks every parameter undetermined
      }
    }
    for (std::size_t k = 0; k < var.size(); ++k) {
      double m = 0;
      bool ok = true;
      for (const auto& v : est) {
        if (v.size() <= k || !std::isfinite(v[k])) ok = false;
        else m += v[k];
      }
      if (!ok) {
        var[k] = std::numeric_limits<double>::quiet_NaN();
        continue;
      }
      m /= static_cast<double>(R);
      double ss = 0;
      for (const auto& v : est) ss += (v[k] - m) * (v[k] - m);
      var[k] += ss * static_cast<double>(R - 1) / static_cast<double>(R);
    }
  }
  for (double& v : var) v = std::sqrt(v);
  return var;
}

}  // namespace gg::fit
