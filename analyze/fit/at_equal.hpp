#pragma once
// One quantity read at equal values of another, across ensembles: y of each ensemble at the time its
// own x(t) first crosses each level (e.g. m at the time the energy E(t) falls to E*), and the ratio of
// the other ensembles' y to the reference's there. This is the paper's closing question (does m
// depend on e only through E?), asked of ensembles whose x decays at different rates, so that an
// equal-time comparison compares unequal energies.
#include <cstddef>
#include <vector>

#include "fit/series.hpp"

namespace gg::fit {

// The time at which x first crosses `level` (from either side), linear in ln x - ln t between the
// samples around the crossing; NaN if it never does, or if x or t is not positive there.
double time_at_level(const Series& x, double level);

// y at time t, linear in ln y - ln t between its neighbouring samples; NaN outside its samples.
double value_at_time(const Series& y, double t);

struct AtEqual {
  std::vector<double> log_y_ref, log_y_other;  // ln y at each level (NaN: not reached)
  std::vector<double> log_ratio;               // ln(y_other / y_ref) at each level
  double mean_log_ratio = 0;                   // over the levels (NaN unless both reach every one)
  std::size_t reached = 0;                     // levels both reach
};

// The comparison at `levels` of x.
AtEqual at_equal(const Series& x_ref, const Series& y_ref, const Series& x_other, const Series& y_other,
                 const std::vector<double>& levels);

// [mean ln ratio, ln ratio at each level]: what a jackknife resamples.
std::vector<double> at_equal_parameters(const AtEqual& a);

}  // namespace gg::fit
