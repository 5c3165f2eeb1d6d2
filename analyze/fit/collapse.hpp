#pragma once
// Several ensembles (e.g. one per e) fitted with one common exponent and one amplitude each,
// ln y_j = ln A_j + z ln t over each ensemble's own window; amplitude ratios A_j / A_0 with errors
// and whether they agree (the paper's claim: the late-time amplitude of m(t) does not depend on e).
#include <cstddef>
#include <vector>

#include "fit/ensemble.hpp"
#include "fit/series.hpp"

namespace gg::fit {

struct CollapseFit {
  double exponent = 0, exponent_stderr = 0, chi2_dof = 0;
  std::vector<double> amplitude, amplitude_stderr, log_amplitude, log_amplitude_stderr;  // [k]
  std::vector<double> ratio, ratio_stderr, log_ratio_stderr;  // A_j / A_0; [0] = 1 +- 0
  // Degrees of freedom of log_ratio_stderr: infinite for the fit's covariance, the jackknife's otherwise.
  std::vector<double> log_ratio_dof;
  // 1 if |ln A_j - ln A_0| <= q stderr(ln A_j - ln A_0), q Student's t quantile of log_ratio_dof at the
  // coverage of a normal's +-sigmas.
  std::vector<int> agree;
  bool all_agree = true;
  double sigmas = 2;
  std::vector<std::size_t> points;
  bool weighted = false;
};

// All series weighted or none (a common fit cannot mix them). Each window needs >= 3 samples with
// t, y > 0. Errors: covariance_scale (least_squares.hpp); ratio errors include the covariance of the
// two amplitudes (both share the fitted exponent).
CollapseFit fit_collapse(const std::vector<Series>& s, const std::vector<Window>& w, double sigmas = 2);

// [z, ln A_0 .. ln A_{k-1}, ln(A_1/A_0) .. ln(A_{k-1}/A_0)]: what a jackknife resamples.
std::vector<double> collapse_parameters(const CollapseFit& f);

// Replaces the error bars by the jackknife's over runs (of collapse_parameters) with their degrees of
// freedom, and re-decides the agreement.
void set_collapse_errors(CollapseFit& f, const Jackknife& j);

}  // namespace gg::fit
