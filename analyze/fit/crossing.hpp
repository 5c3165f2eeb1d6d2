#pragma once
// When a quantity first reaches a level, and how that time scales with a control parameter: the
// giant-cluster time t_g (the largest cluster's share of the clustered particles first reaching 1/2)
// and the first wrapping time (the fraction of runs whose largest cluster wraps the box reaching 1/2),
// read off ensemble means, with the slope of ln t* against ln L that says whether they grow with the
// box (docs/PHYSICS.md "Finite size").
#include <cstddef>
#include <string>
#include <vector>

#include "fit/ensemble.hpp"
#include "fit/extrapolate.hpp"
#include "fit/series.hpp"

namespace gg::fit {

// The side of `level` a series starts on fixes the direction: starting below (its first sample not
// equal to the level is below it), "reached" means y >= level; starting above, y <= level.
// first: the first time y is reached, interpolated linearly in y against ln t between the two samples
//   around it (linear in y, not ln y: a share or a fraction of runs can be 0; linear in t when the
//   earlier sample is at t <= 0). The first sample's time if it is reached there already.
// stays: the first time after which every sample is reached (the same interpolation from the last
//   sample that is not); NaN unless the last sample is reached.
// NaN when the level is never reached (or y holds no sample, or the level is not finite).
enum class CrossingRule { first, stays };
double crossing_time(const Series& y, double level, CrossingRule rule);

// Why crossing_time is NaN, in words ("" when it is not).
std::string no_crossing_reason(const Series& y, double level, CrossingRule rule);

// ln t* of an ensemble with its standard error and degrees of freedom, and how many runs' own series
// reach the level.
struct CrossingEstimate {
  double log_time = 0, log_time_stderr = 0, log_time_dof = 0;
  std::size_t runs_reaching = 0;
};
// Of the ensemble mean: ln of crossing_time(mean), with the delete-one jackknife over runs (runs - 1
// dof). Right where each run's series is smooth near the level; where a run's series is a 0/1 step (its
// largest cluster wraps from t_r on) the mean's crossing is the runs' median, whose delete-one jackknife
// is not consistent (Efron & Tibshirani ch. 11): its 2-sigma interval missed the truth in 13.5% of
// synthetic trials (docs/PHYSICS.md "Calibration of the verdicts").
CrossingEstimate crossing_of_mean(const Ensemble& e, double level, CrossingRule rule);
// Of the runs: the mean of ln t*_r over the runs' own crossing times, with the standard error of a mean
// (sd / sqrt(R), R - 1 dof). For 0/1 steps: a mean of independent times, so its Student-t interval holds
// its level. NaN (censored) unless every run reaches the level.
CrossingEstimate mean_of_crossings(const Ensemble& e, double level, CrossingRule rule);

// ln t* = a + slope ln x by least squares weighted by `weight` (the runs behind each point: the variance
// of a mean of R runs is s^2 / R when the runs scatter alike at every x) over the points whose ln t* and
// variance are finite (var > 0). The weights are fixed, not the jackknife's variances: weights from 3-7
// degrees of freedom follow their own noise, and with them the 2-sigma test of slope = 0 rejected 7-14%
// of true claims where fixed weights reject 4-9% (docs/PHYSICS.md "Calibration of the verdicts"). The
// slope is then a fixed linear combination sum_j c_j ln t*_j of independent estimates, so its variance is
// sum_j c_j^2 var_j, with Welch-Satterthwaite's degrees of freedom from each point's (Welch 1947). NaN
// with fewer than two usable points or with all their x equal.
struct CrossingSlope {
  double slope = 0, slope_stderr = 0, slope_dof = 0;
  std::size_t points = 0;
};
CrossingSlope crossing_slope(const std::vector<double>& x, const std::vector<double>& weight,
                             const std::vector<double>& log_time, const std::vector<double>& log_time_var,
                             const std::vector<double>& log_time_dof);

// The slope's verdict on the interval slope +- q stderr (q: Student's quantile of slope_dof at the
// coverage of a normal's +-sigmas): "grows with x" if it lies above 0, "falls with x" if below,
// "independent of x" if it lies within +-tolerance, else "undecided" (also for a NaN slope).
std::string slope_verdict(const CrossingSlope& s, double sigmas, double tolerance);

}  // namespace gg::fit
