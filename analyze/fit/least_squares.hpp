#pragma once
// Weighted least squares through GSL, with one policy for honest error bars (see scale below).
#include <cstddef>
#include <functional>
#include <vector>

#include "fit/series.hpp"

namespace gg::fit {

struct LsqResult {
  std::vector<double> coef;  // [p]
  std::vector<double> cov;   // [p][p] row-major, already scaled by `scale`
  double chi2 = 0;           // sum of squared (weighted) residuals
  std::size_t dof = 0;       // n - p
  double scale = 1;          // factor applied to the raw covariance
  double chi2_dof() const { return chi2 / static_cast<double>(dof); }
  double stderr_of(std::size_t k) const;
};

// What a fit of one series over a window reports besides its parameters (PowerLawFit, HaffFit).
struct FitQuality {
  double chi2_dof = 0;
  std::size_t points = 0;          // samples used
  double t_first = 0, t_last = 0;  // first and last sample used
  bool weighted = false;           // by the ensemble's error bars
  std::size_t raised_errors = 0;   // samples whose zero stderr was raised (see weights_sigma)
  // chi2/dof of `r`, the fit of the samples `idx` (ascending) of `s`, weighted or not.
  void record(const LsqResult& r, const Series& s, const std::vector<std::size_t>& idx, bool with_weights);
};

// Error-bar policy shared by every fit:
//  - weighted (sigma from the ensemble's standard error): the raw covariance (J^T W J)^-1 is right
//    when the sigmas are right and the model fits; if chi2/dof > 1 the model or the sigmas are off and
//    the scatter of the residuals is the better measure, so it is inflated by chi2/dof. It is never
//    shrunk when chi2/dof < 1: successive samples of the same runs are correlated, which makes
//    chi2/dof small without making the parameters any better known.
//  - unweighted: nothing says how large the noise is, so it is estimated from the residuals,
//    i.e. the covariance is (J^T J)^-1 times chi2/dof (ordinary least squares; the t-statistic of a
//    parameter then follows Student's t with n - p degrees of freedom).
double covariance_scale(bool weighted, double chi2, std::size_t dof);

// Linear model y ~ X c. X is [n][p] row-major; sigma empty = unweighted. Needs n > p.
LsqResult linear_lsq(const std::vector<double>& X, std::size_t p, const std::vector<double>& y,
                     const std::vector<double>& sigma);

// Nonlinear model y ~ f(x; c). `f` returns the model value and writes the p partial
// derivatives d f / d c_k into `grad`. Trust-region Levenberg-Marquardt (gsl_multifit_nlinear).
// Throws RuntimeError if the iteration does not converge or leaves non-finite parameters.
using ModelFn = std::function<double(double x, const double* c, double* grad)>;
LsqResult nonlinear_lsq(const ModelFn& f, std::size_t p, const std::vector<double>& x,
                        const std::vector<double>& y, const std::vector<double>& sigma,
                        const std::vector<double>& start);

}  // namespace gg::fit
