#include "fit/series.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "gg/errors.hpp"

namespace gg::fit {

std::string fmt_window(const Window& w) { return "[" + fmt(w.t1) + ", " + fmt(w.t2) + "]"; }

void check_series(const Series& s, const std::string& what) {
  if (s.y.size() != s.t.size())
    throw RuntimeError(what + ": " + std::to_string(s.y.size()) + " values but " + std::to_string(s.t.size()) +
                       " times; the dataset and its time axis must have the same length");
  if (!s.err.empty() && s.err.size() != s.t.size())
    throw RuntimeError(what + ": " + std::to_string(s.err.size()) + " error bars for " +
                       std::to_string(s.t.size()) + " values; the stderr sibling must match the dataset");
  for (std::size_t i = 0; i < s.t.size(); ++i) {
    if (!std::isfinite(s.t[i]) || !std::isfinite(s.y[i]) || (!s.err.empty() && !std::isfinite(s.err[i])))
      throw RuntimeError(what + ": non-finite value at sample " + std::to_string(i) + " (t = " + fmt(s.t[i]) +
                         "); fix or cut the input before fitting");
    if (!s.err.empty() && s.err[i] < 0)
      throw RuntimeError(what + ": negative standard error at t = " + fmt(s.t[i]));
  }
}

std::vector<std::size_t> select_window(const Series& s, const Window& w, std::size_t min_points,
                                       const std::string& what) {
  if (!std::isfinite(w.t1) || !std::isfinite(w.t2) || !(w.t1 < w.t2))
    throw UsageError(what + ": empty window " + fmt_window(w) + "; give --window T1 T2 with T1 < T2");
  std::vector<std::size_t> idx;
  for (std::size_t i = 0; i < s.t.size(); ++i)
    if (w.contains(s.t[i])) idx.push_back(i);
  std::string span = s.t.empty() ? std::string("no samples at all")
                                 : "the data span t = [" + fmt(*std::min_element(s.t.begin(), s.t.end())) + ", " +
                                       fmt(*std::max_element(s.t.begin(), s.t.end())) + "]";
  if (idx.empty())
    throw RuntimeError(what + ": no samples in the window " + fmt_window(w) + " (" + span +
                       "); choose a window inside the data");
  if (idx.size() < min_points)
    throw RuntimeError(what + ": only " + std::to_string(idx.size()) + " sample(s) in the window " +
                       fmt_window(w) + ", need at least " + std::to_string(min_points) + " (" + span +
                       "); widen the window");
  return idx;
}

void require_positive(const Series& s, const std::vector<std::size_t>& idx, const std::string& what) {
  for (std::size_t i : idx) {
    if (!(s.t[i] > 0))
      throw UsageError(what + ": t = " + fmt(s.t[i]) +
                       " <= 0 in the window; a log-log fit takes ln t: start the window after t = 0");
    if (!(s.y[i] > 0))
      throw RuntimeError(what + ": non-positive value y = " + fmt(s.y[i]) + " at t = " + fmt(s.t[i]) +
                         "; a log-log fit takes ln y: choose a window where the data are positive");
  }
}

std::vector<double> weights_sigma(const Series& s, const std::vector<std::size_t>& idx, std::size_t& raised) {
  raised = 0;
  if (!s.weighted()) return {};
  const std::size_t n = idx.size();
  std::vector<double> rel2(n);
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t i = idx[k];
    rel2[k] = s.y[i] != 0 ? (s.err[i] / s.y[i]) * (s.err[i] / s.y[i]) : 0.0;
  }
  // Running mean of the relative variance over +- kSmooth neighbours (see the header).
  std::vector<double> smooth(n, 0.0);
  double min_pos = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t a = k >= kSmooth ? k - kSmooth : 0, b = std::min(n - 1, k + kSmooth);
    double sum = 0;
    for (std::size_t j = a; j <= b; ++j) sum += rel2[j];
    smooth[k] = sum / static_cast<double>(b - a + 1);
    if (smooth[k] > 0) min_pos = std::min(min_pos, smooth[k]);
  }
  if (!std::isfinite(min_pos)) return {};  // every error is zero: nothing to weight by
  std::vector<double> sigma(n);
  for (std::size_t k = 0; k < n; ++k) {
    if (!(smooth[k] > 0)) {
      smooth[k] = min_pos;
      ++raised;
    }
    const double y = std::abs(s.y[idx[k]]);
    sigma[k] = std::sqrt(smooth[k]) * (y > 0 ? y : 1.0);
  }
  return sigma;
}

}  // namespace gg::fit
