#include "fit/onset.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "fit/power_law.hpp"
#include "gg/errors.hpp"

namespace gg::fit {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Index of the first k with above[k..k+P-1] all true (truncated at the end); npos if none.
std::size_t first_run(const std::vector<bool>& above, std::size_t P) {
  for (std::size_t k = 0; k < above.size(); ++k) {
    bool ok = true;
    for (std::size_t j = k; j < std::min(above.size(), k + P) && ok; ++j) ok = above[j];
    if (ok) return k;
  }
  return static_cast<std::size_t>(-1);
}

// Where f (f[k-1] <= 0 < f[k] or the reverse) crosses zero between t[k-1] and t[k]:
// linear in ln t when both times are positive, else linear in t.
double crossing(const std::vector<double>& t, const std::vector<double>& f, std::size_t k) {
  if (k == 0) return t[0];
  const double a = f[k - 1] / (f[k - 1] - f[k]);
  if (!(a >= 0 && a <= 1)) return t[k];
  if (t[k - 1] > 0) return std::exp(std::log(t[k - 1]) + a * (std::log(t[k]) - std::log(t[k - 1])));
  return t[k - 1] + a * (t[k] - t[k - 1]);
}

void check_criterion(const OnsetCriterion& c) {
  if (c.plateau_samples < 1) throw UsageError("onset: --plateau-samples must be >= 1");
  if (c.persist < 1) throw UsageError("onset: --persist must be >= 1");
  if (!(c.plateau_tol > 0)) throw UsageError("onset: --tol must be > 0");
  if (!(c.exponent_tol > 0)) throw UsageError("onset: --exponent-tol must be > 0");
}

}  // namespace

std::string describe_plateau(const OnsetCriterion& c) {
  return "plateau onset: first time m(t) exceeds plateau*(1+" + fmt(c.plateau_tol) + ") and stays above for " +
         std::to_string(c.persist) + " consecutive samples, plateau = median of the first " +
         std::to_string(c.plateau_samples) + " samples; crossing interpolated linearly in ln t";
}

std::string describe_asymptote(const OnsetCriterion& c, double asymptote) {
  return "asymptote onset: first time the local exponent d ln m/d ln t (fit over " + fmt(c.decades) +
         " decades) is within " + fmt(c.exponent_tol) + " of " + fmt(asymptote) + " for " +
         std::to_string(c.persist) + " consecutive samples; crossing interpolated linearly in ln t";
}

PlateauOnset plateau_onset(const Series& s, const OnsetCriterion& c) {
  check_criterion(c);
  check_series(s, "onset");
  if (s.size() <= c.plateau_samples)
    throw RuntimeError("onset: " + std::to_string(s.size()) + " samples, but the plateau alone takes the first " +
                       std::to_string(c.plateau_samples) + "; lower --plateau-samples or give a longer series");
  std::vector<double> head(s.y.begin(), s.y.begin() + static_cast<long>(c.plateau_samples));
  std::sort(head.begin(), head.end());
  const std::size_t K = head.size();
  PlateauOnset r;
  r.plateau = K % 2 ? head[K / 2] : 0.5 * (head[K / 2 - 1] + head[K / 2]);
  if (!(r.plateau > 0)) throw RuntimeError("onset: the plateau value " + fmt(r.plateau) + " is not positive");
  const double thr = r.plateau * (1 + c.plateau_tol);
  std::vector<double> f(s.size());
  std::vector<bool> above(s.size());
  for (std::size_t k = 0; k < s.size(); ++k) {
    f[k] = s.y[k] - thr;
    above[k] = f[k] > 0;
  }
  const std::size_t k = first_run(above, c.persist);
  r.time = k == static_cast<std::size_t>(-1) ? kNaN : crossing(s.t, f, k);
  return r;
}

double asymptote_onset(const Series& s, double asymptote, const OnsetCriterion& c) {
  check_criterion(c);
  if (!std::isfinite(asymptote)) throw UsageError("onset: the asymptotic exponent is not finite");
  LocalExponent z = local_exponent(s, c.decades);
  std::vector<double> f(z.t.size());
  std::vector<bool> inside(z.t.size());
  for (std::size_t k = 0; k < z.t.size(); ++k) {
    f[k] = c.exponent_tol - std::abs(z.exponent[k] - asymptote);  // > 0 inside the band
    inside[k] = f[k] >= 0;
  }
  const std::size_t k = first_run(inside, c.persist);
  return k == static_cast<std::size_t>(-1) ? kNaN : crossing(z.t, f, k);
}

}  // namespace gg::fit
