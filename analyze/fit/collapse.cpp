#include "fit/collapse.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "fit/least_squares.hpp"
#include "gg/errors.hpp"

namespace gg::fit {
namespace {

void decide(CollapseFit& f) {
  f.all_agree = true;
  f.agree.assign(f.amplitude.size(), 1);
  for (std::size_t j = 1; j < f.amplitude.size(); ++j) {
    const double d = f.log_amplitude[j] - f.log_amplitude[0];
    f.agree[j] = std::abs(d) <= student_quantile(f.sigmas, f.log_ratio_dof[j]) * f.log_ratio_stderr[j] ? 1 : 0;
    if (!f.agree[j]) f.all_agree = false;
  }
}

}  // namespace

CollapseFit fit_collapse(const std::vector<Series>& s, const std::vector<Window>& w, double sigmas) {
  const std::size_t k = s.size();
  if (k < 2) throw UsageError("collapse: needs at least 2 ensembles (got " + std::to_string(k) + ")");
  if (w.size() != k)
    throw UsageError("collapse: " + std::to_string(w.size()) + " windows for " + std::to_string(k) +
                     " ensembles; give --window T1 T2 once (for all) or once per input");
  if (!(sigmas > 0)) throw UsageError("collapse: --sigmas must be > 0");
  const bool weighted = s.front().weighted();
  for (const Series& x : s)
    if (x.weighted() != weighted)
      throw RuntimeError("collapse: some inputs have error bars (a stderr sibling) and some do not; "
                         "fit ensemble averages throughout (gg-fit average) or plain series throughout");
  CollapseFit f;
  f.sigmas = sigmas;
  f.weighted = weighted;
  const std::size_t p = 1 + k;  // [z, lnA_0, ..., lnA_{k-1}]
  std::vector<double> X, ly, sl;
  std::size_t raised_all = 0;
  for (std::size_t j = 0; j < k; ++j) {
    const std::string what = "collapse, ensemble " + std::to_string(j);
    check_series(s[j], what);
    auto idx = select_window(s[j], w[j], 3, what);
    require_positive(s[j], idx, what);
    std::size_t raised = 0;
    auto sigma = weights_sigma(s[j], idx, raised);
    raised_all += raised;
    if (weighted && sigma.empty())
      throw RuntimeError(what + ": every standard error in the window is zero; cannot weight");
    for (std::size_t m = 0; m < idx.size(); ++m) {
      const std::size_t i = idx[m];
      for (std::size_t c = 0; c < p; ++c) X.push_back(c == 0 ? std::log(s[j].t[i]) : (c == j + 1 ? 1.0 : 0.0));
      ly.push_back(std::log(s[j].y[i]));
      if (weighted) sl.push_back(sigma[m] / s[j].y[i]);
    }
    f.points.push_back(idx.size());
  }
  LsqResult r = linear_lsq(X, p, ly, sl);
  f.exponent = r.coef[0];
  f.exponent_stderr = r.stderr_of(0);
  f.chi2_dof = r.chi2_dof();
  for (std::size_t j = 0; j < k; ++j) {
    f.log_amplitude.push_back(r.coef[1 + j]);
    f.log_amplitude_stderr.push_back(r.stderr_of(1 + j));
    f.amplitude.push_back(std::exp(r.coef[1 + j]));
    f.amplitude_stderr.push_back(f.amplitude[j] * f.log_amplitude_stderr[j]);
    // var(ln A_j - ln A_0) = C_jj + C_00 - 2 C_0j
    const double v = j == 0 ? 0.0 : r.cov[(1 + j) * p + 1 + j] + r.cov[p + 1] - 2 * r.cov[(1 + j) * p + 1];
    f.log_ratio_stderr.push_back(std::sqrt(std::max(0.0, v)));
    f.ratio.push_back(std::exp(r.coef[1 + j] - r.coef[1]));
    f.ratio_stderr.push_back(f.ratio[j] * f.log_ratio_stderr[j]);
    f.log_ratio_dof.push_back(std::numeric_limits<double>::infinity());
  }
  decide(f);
  return f;
}

std::vector<double> collapse_parameters(const CollapseFit& f) {
  std::vector<double> p{f.exponent};
  for (double a : f.log_amplitude) p.push_back(a);
  for (std::size_t j = 1; j < f.log_amplitude.size(); ++j) p.push_back(f.log_amplitude[j] - f.log_amplitude[0]);
  return p;
}

void set_collapse_errors(CollapseFit& f, const Jackknife& jk) {
  const std::vector<double>& se = jk.se;
  const std::size_t k = f.amplitude.size();
  f.exponent_stderr = se[0];
  for (std::size_t j = 0; j < k; ++j) {
    f.log_amplitude_stderr[j] = se[1 + j];
    f.amplitude_stderr[j] = f.amplitude[j] * se[1 + j];
    if (j > 0) {
      f.log_ratio_stderr[j] = se[k + j];
      f.ratio_stderr[j] = f.ratio[j] * se[k + j];
      f.log_ratio_dof[j] = jk.dof[k + j];
    }
  }
  decide(f);
}

}  // namespace gg::fit
