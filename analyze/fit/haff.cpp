#include "fit/haff.hpp"

#include <cmath>
#include <vector>

#include "fit/least_squares.hpp"
#include "gg/errors.hpp"

namespace gg::fit {

double henderson_g(double phi) { return (1 - 7 * phi / 16) / ((1 - phi) * (1 - phi)); }

double luding_g(double phi) { return henderson_g(phi) - std::pow(phi, 3) / (128 * std::pow(1 - phi, 4)); }

double tonks_g(double rho) { return 1 / (1 - rho); }

double carnahan_starling_g(double eta) { return (1 - eta / 2) / ((1 - eta) * (1 - eta) * (1 - eta)); }

HaffPrediction enskog_haff(int dim, double rho, double e, double T0, Contact contact) {
  if (dim < 1 || dim > 3) throw UsageError("haff: dim must be 1, 2 or 3 (got " + std::to_string(dim) + ")");
  if (!(e >= 0 && e < 1))
    throw UsageError("haff: the coefficient of restitution must lie in [0, 1) for cooling (got e = " + fmt(e) + ")");
  if (!(T0 > 0)) throw UsageError("haff: T0 must be > 0 (got " + fmt(T0) + ")");
  HaffPrediction p;
  p.dim = dim;
  p.rho = rho;
  p.e = e;
  p.T0 = T0;
  p.E0 = 0.5 * dim * T0;
  const double pi = std::acos(-1.0);
  if (dim == 2) {
    p.phi = pi * rho / 4;
    if (!(p.phi > 0 && p.phi < 0.9069))
      throw UsageError("haff: rho = " + fmt(rho) + " gives packing fraction " + fmt(p.phi) +
                       " outside (0, 0.9069) (hexagonal close packing)");
    if (contact == Contact::luding) {
      p.g = luding_g(p.phi);
      p.g_name = "Luding: (1 - 7 phi/16)/(1 - phi)^2 - phi^3/(128 (1 - phi)^4)";
    } else {
      p.g = henderson_g(p.phi);
      p.g_name = "Henderson: (1 - 7 phi/16)/(1 - phi)^2";
    }
    p.omega0 = 2 * std::sqrt(pi) * rho * p.g * std::sqrt(T0);
  } else if (dim == 3) {
    p.phi = pi * rho / 6;
    if (!(p.phi > 0 && p.phi < 0.7405))
      throw UsageError("haff: rho = " + fmt(rho) + " gives packing fraction " + fmt(p.phi) +
                       " outside (0, 0.7405) (face-centred cubic close packing)");
    p.g = carnahan_starling_g(p.phi);
    p.g_name = "Carnahan-Starling: (1 - eta/2)/(1 - eta)^3";
    p.omega0 = 4 * std::sqrt(pi) * rho * p.g * std::sqrt(T0);
  } else {
    p.phi = rho;
    if (!(rho > 0 && rho < 1)) throw UsageError("haff: 1D density must lie in (0, 1) (got rho = " + fmt(rho) + ")");
    p.g = tonks_g(rho);
    p.g_name = "Tonks (1D hard rods): 1/(1 - rho)";
    p.omega0 = 2 / std::sqrt(pi) * rho * p.g * std::sqrt(T0);
  }
  p.t0 = 2.0 * dim / ((1 - e * e) * p.omega0);
  return p;
}

HaffFit fit_haff(const Series& s, const Window& w) {
  const std::string what = "haff fit";
  check_series(s, what);
  auto idx = select_window(s, w, 3, what);
  std::vector<double> x, y;
  for (std::size_t i : idx) {
    if (!(s.y[i] > 0))
      throw RuntimeError(what + ": non-positive energy " + fmt(s.y[i]) + " at t = " + fmt(s.t[i]));
    x.push_back(s.t[i]);
    y.push_back(s.y[i]);
  }
  HaffFit f;
  auto sigma = weights_sigma(s, idx, f.raised_errors);
  // Fitted in ln E: the fluctuations of E (a mean over N particles, or over runs) are relative,
  // so residuals in ln E have one size over the whole decay and an unweighted fit's error bars hold.
  // With ensemble error bars, sigma(ln E) = sigma(E) / E.
  std::vector<double> lny, sl;
  for (std::size_t k = 0; k < y.size(); ++k) {
    lny.push_back(std::log(y[k]));
    if (!sigma.empty()) sl.push_back(sigma[k] / y[k]);
  }
  // Start: E0 from the earliest sample, t0 from the decay to the last one (exact for Haff data).
  const double E0 = y.front();
  double t0 = x.back() - x.front();
  const double ratio = std::sqrt(E0 / y.back());
  if (ratio > 1 + 1e-12) t0 = (x.back() - x.front()) / (ratio - 1);
  // ln E = c0 - 2 ln(1 + t/c1), c0 = ln E0
  const ModelFn model = [](double t, const double* c, double* g) {
    const double u = 1 + t / c[1];
    g[0] = 1;
    g[1] = 2 * t / (c[1] * c[1] * u);
    return c[0] - 2 * std::log(u);
  };
  LsqResult r = nonlinear_lsq(model, 2, x, lny, sl, {std::log(E0), t0});
  r.coef[0] = std::exp(r.coef[0]);
  r.cov[0] *= r.coef[0] * r.coef[0];  // stderr(E0) = E0 stderr(ln E0)
  f.E0 = r.coef[0];
  f.E0_stderr = r.stderr_of(0);
  f.t0 = r.coef[1];
  f.t0_stderr = r.stderr_of(1);
  f.record(r, s, idx, !sigma.empty());
  return f;
}

}  // namespace gg::fit
