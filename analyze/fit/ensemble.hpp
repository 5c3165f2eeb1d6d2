#pragma once
// Ensembles of runs: a common time grid, the mean and standard error at each time (frame by
// frame for 2-D data such as C(r,t) [T][R] or P(l_d) [T][B]), and the delete-one jackknife over
// runs that gives error bars including the correlations between the times of one run.
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "fit/series.hpp"

namespace gg::fit {

// One run: values [T][cols] (row-major) sampled at times t [T].
struct RunData {
  std::vector<double> t;
  std::size_t cols = 1;
  std::vector<double> values;
  std::string name;  // for messages, e.g. "run3.h5:/cluster/mean_mass"
};

// Runs on one time grid.
struct Ensemble {
  std::vector<double> t;
  std::size_t cols = 1;
  std::vector<std::vector<double>> runs;  // [R][T*cols]
  bool interpolated = false;
  std::size_t dropped = 0;  // samples of the first run's grid outside the range all runs cover
  std::size_t size() const { return runs.size(); }
};

// Puts the runs on one grid. Without `interpolate` the runs must share their time grid exactly
// (same length, same times up to 1e-9 relative): otherwise RuntimeError telling to pass --interpolate.
// With it, the grid is the first run's times inside the range every run covers, and each run is
// interpolated linearly in ln t (a sample at exactly the grid time is taken as is, so t = 0 works
// when every run has it). Needs >= 2 runs and equal `cols`.
Ensemble common_grid(const std::vector<RunData>& runs, bool interpolate);

struct Average {
  std::vector<double> t;
  std::size_t cols = 1;
  std::vector<double> mean, err;  // [T*cols]; err = standard error of the mean, s / sqrt(R)
  std::size_t runs = 0;
};

// Mean and standard error of the mean at each time and column over the runs of `e`.
Average average(const Ensemble& e);

// The ensemble mean of a 1-column ensemble as a weighted Series (err = standard error).
Series mean_series(const Ensemble& e);

// Grouped delete-one jackknife. `groups` are independent ensembles (one for a single fit; one per
// e for a collapse); `estimate` maps their mean series to a parameter vector. For every run i of
// every group g the estimate is recomputed with that run left out of g; the variance is
// sum_g (R_g - 1)/R_g sum_i (p_{g,-i} - mean_i p_{g,-i})^2 (Efron & Tibshirani ch. 11; groups are
// independent, so their contributions add). The leave-one-out series keep the full ensemble's
// error bars as weights. Each group needs >= 3 runs so that a leave-one-out
// mean still has a standard error. NaN where a leave-one-out estimate failed.
// The variance from R runs is itself uncertain: each group's part has R_g - 1 degrees of freedom,
// and their sum has the Welch-Satterthwaite number (sum_g v_g)^2 / sum_g v_g^2 / (R_g - 1) (Welch
// 1947), with which an interval takes Student's t quantile rather than the normal's.
struct Jackknife {
  std::vector<double> se, dof;  // per parameter
  // The half width of the interval of parameter k at the coverage of a normal's +-sigmas.
  double halfwidth(std::size_t k, double sigmas) const;
};
using Estimator = std::function<std::vector<double>(const std::vector<Series>&)>;
Jackknife jackknife(const std::vector<Ensemble>& groups, const Estimator& estimate);
// The same with ensembles linked within a group: the ensembles of one group are readings of the same
// runs (e.g. E(t) and m(t) of each run), so a run is left out of all of them at once. `estimate`
// gets the means of every ensemble of every group, in order.
Jackknife jackknife_linked(const std::vector<std::vector<Ensemble>>& groups, const Estimator& estimate);
// The standard errors alone.
std::vector<double> jackknife_stderr(const std::vector<Ensemble>& groups, const Estimator& estimate);

// The two-sided Student-t quantile with `dof` degrees of freedom whose coverage is that of a normal's
// +-sigmas (2 -> 95.45%); the normal's `sigmas` itself for infinite dof, NaN for dof <= 0 or NaN.
double student_quantile(double sigmas, double dof);

// An estimate with its standard error and the degrees of freedom of that error.
struct Estimate {
  double value = 0, se = 0, dof = 0;
};
// a - b of independent estimates, its error in quadrature and Welch-Satterthwaite's dof.
Estimate difference(const Estimate& a, const Estimate& b);
// Whether `e` lies within its Student-t interval (coverage of a normal's +-sigmas) of `null`; false
// when undetermined (value or error not finite).
bool within(const Estimate& e, double null, double sigmas);

}  // namespace gg::fit
