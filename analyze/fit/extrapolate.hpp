#pragma once
// Finite-size extrapolation and the equality verdict of the finite-size study (Fig. 8,
// docs/PHYSICS.md "Finite size"): a quantity measured in boxes of edge L, y(L) = y_inf + b / L,
// fitted by weighted least squares in x = 1/L; and the rule that says whether a measured ratio
// supports, rejects or leaves undecided the paper's claim that it equals 1.
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace gg::fit {

struct SizeExtrapolation {
  double limit = 0, limit_stderr = 0;  // y_inf, the value at 1/L = 0
  double slope = 0, slope_stderr = 0;  // b
  double chi2_dof = 0;                 // NaN when the line passes through every point (two sizes)
  std::size_t points = 0;
};

// y(L) = y_inf + b / L over the sizes whose value and error are finite, weighted by 1/err^2
// (err > 0 required). Two sizes: the line through both, errors propagated from theirs. More: the
// covariance scaled by max(1, chi2/dof), the policy of every gg-fit fit (least_squares.hpp).
// Throws RuntimeError with fewer than two usable sizes or an L <= 0.
SizeExtrapolation extrapolate_in_inverse_size(const std::vector<double>& L, const std::vector<double>& y,
                                              const std::vector<double>& err);

// Whether a measured value supports "value == expected" (an equivalence test):
//   rejected  : expected lies outside value +- q * stderr;
//   supported : the whole interval value +- q * stderr lies within expected * (1 +- tolerance),
//               i.e. the data exclude any deviation larger than the tolerance;
//   undecided : neither (consistent with expected, but too uncertain to exclude a deviation of that
//               size), or the value or its error is not finite.
// q is Student's t quantile with `dof` degrees of freedom (those of a jackknife's error) at the
// coverage of a normal's +-sigmas; the normal's own for infinite dof.
enum class Verdict { supported, rejected, undecided };
Verdict equality_verdict(double value, double stderr, double expected, double sigmas, double tolerance,
                         double dof = std::numeric_limits<double>::infinity());
// The same for a ratio r = exp(log_ratio) against 1, on the interval of ln r (stderr `se`, `dof`):
// rejected if it excludes 0, supported if it lies within +-ln(1 + tolerance).
Verdict ratio_verdict(double log_ratio, double se, double dof, double sigmas, double tolerance);
// Several claims at once: rejected if any is, supported if all are, else undecided.
Verdict combined_verdict(const std::vector<Verdict>& v);
std::string verdict_name(Verdict v);

}  // namespace gg::fit
