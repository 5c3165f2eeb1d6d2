#pragma once
// Power laws y = A t^z: a straight line in ln y vs ln t (weighted least squares), the same with a
// plateau offset y = y0 + A t^z (nonlinear least squares), and the local exponent d ln y / d ln t.
#include <cstddef>
#include <vector>

#include "fit/least_squares.hpp"
#include "fit/series.hpp"

namespace gg::fit {

struct PowerLawFit : FitQuality {
  double exponent = 0, exponent_stderr = 0;
  double amplitude = 0, amplitude_stderr = 0;  // A in y = A t^z (value at t = 1)
  double log_amplitude_stderr = 0;             // stderr of ln A
  double offset = 0, offset_stderr = 0;        // y0 (offset model only)
  bool with_offset = false;
};

// Fit of ln y = ln A + z ln t over the samples in `w` (needs >= 3, all t, y > 0). Weighted by
// sigma_lny = err / y when `s` has error bars. Errors: see covariance_scale (least_squares.hpp).
PowerLawFit fit_power_law(const Series& s, const Window& w);

// Fit of y = y0 + A t^z (needs >= 4 samples, t > 0), started from several plateau guesses; the one
// with the smallest chi2 wins.
PowerLawFit fit_power_law_offset(const Series& s, const Window& w);

struct LocalExponent {
  std::vector<double> t, exponent, err;  // err: standard error of the exponent
};

// Local exponent z(t_i) = d ln y / d ln t from a fit of ln y on ln t over the samples within
// +- decades/2 of t_i (in log10 t). Only times whose whole window lies inside the data (t > 0)
// and holds >= 3 samples are reported, so no value comes from a one-sided window.
LocalExponent local_exponent(const Series& s, double decades);

}  // namespace gg::fit
