#pragma once
// Plain data the fits work on: a time series with optional error bars, and a time window.
// No HDF5 here (only common/ includes it, so the fits build and test without it): the gg-fit tool
// reads files and hands these structs over.
#include <cstddef>
#include <string>
#include <vector>

#include "gg/fmt.hpp"

namespace gg::fit {

// y(t) with optional standard errors `err` (empty = unweighted; else same length as t).
struct Series {
  std::vector<double> t, y, err;
  bool weighted() const { return !err.empty(); }
  std::size_t size() const { return t.size(); }
};

// Closed interval t1 <= t <= t2.
struct Window {
  double t1 = 0, t2 = 0;
  bool contains(double t) const { return t >= t1 && t <= t2; }
};

// Checks that t, y (and err, if present) have equal lengths and finite values
// (RuntimeError naming `what` otherwise).
void check_series(const Series& s, const std::string& what);

// Indices of the samples inside `w`. Throws UsageError if the window is empty by construction
// (t1 >= t2, non-finite), RuntimeError if it holds no samples or fewer than `min_points`
// (the message names the data's span and the fix).
std::vector<std::size_t> select_window(const Series& s, const Window& w, std::size_t min_points,
                                       const std::string& what);

// A log-log fit takes ln t and ln y: a window reaching t <= 0 is a UsageError (the window is the
// caller's choice), a selected y <= 0 a RuntimeError (the data's).
void require_positive(const Series& s, const std::vector<std::size_t>& idx, const std::string& what);

// Error bars used as weights, from the ensemble's standard errors of the selected samples.
// Each standard error from R runs is itself uncertain (R - 1 degrees of freedom); weighting by them
// as they are lets the samples whose spread happened to come out small dominate the fit and makes
// its error bars too small (for R = 4 the variance of the slope came out 2.4x the quoted one in
// simulated trials). So the relative variance (err/y)^2 is first averaged over the kSmooth
// neighbours on each side, which pools their degrees of freedom while following a slow trend in
// time. Samples whose smoothed error is zero (all runs equal, e.g. E at t = 0) get the smallest
// non-zero one; `raised` counts them. Returns sigma of each selected sample, or empty when `s` is
// unweighted or every error is zero.
inline constexpr std::size_t kSmooth = 3;
std::vector<double> weights_sigma(const Series& s, const std::vector<std::size_t>& idx, std::size_t& raised);

// "[1, 10]": a fit window as it reads in messages.
std::string fmt_window(const Window& w);

}  // namespace gg::fit
