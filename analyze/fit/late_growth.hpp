#pragma once
// The late end of a growth curve, read without a common exponent across curves:
//  - its late exponent, fitted over the last `decades` before t_end, and whether it has settled:
//    the exponent over the `decades` before that, and the change between the two;
//  - the ratio of two curves at equal times, exp(mean over the reference's samples in a window of
//    ln(y_B(t) / y_A(t))), B interpolated linearly in ln y - ln t at A's times.
#include <cstddef>
#include <vector>

#include "fit/series.hpp"

namespace gg::fit {

struct LateExponent {
  double late = 0, before = 0;  // exponents over the last window and the one before it
  double change = 0;            // late - before
  Window late_window, before_window;
  std::size_t late_points = 0, before_points = 0;
};

// Power-law fits (fit_power_law) over [t_end 10^-d, t_end] and [t_end 10^-2d, t_end 10^-d].
LateExponent late_exponent(const Series& s, double t_end, double decades);

// [late, before, change]: what a jackknife resamples.
std::vector<double> late_exponent_parameters(const LateExponent& f);

struct EqualTimeRatio {
  double log_ratio = 0;  // mean of ln(y_B / y_A) over the compared times
  std::size_t points = 0;
};

// Over the samples of `ref` in w that lie inside other's sampled times (>= 1 needed).
EqualTimeRatio equal_time_ratio(const Series& ref, const Series& other, const Window& w);

}  // namespace gg::fit
