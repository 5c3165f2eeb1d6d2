#pragma once
// Haff's law E(t) = E0 / (1 + t/t0)^2 fitted to early times, and the Enskog prediction of t0
// (docs/PHYSICS.md "Homogeneous cooling").
#include <cstddef>
#include <string>

#include "fit/least_squares.hpp"
#include "fit/series.hpp"

namespace gg::fit {

// Pair correlation at contact.
enum class Contact { henderson, luding };
double henderson_g(double phi);  // 2D: (1 - 7 phi/16) / (1 - phi)^2 (Henderson 1975)
double luding_g(double phi);     // 2D: Henderson - phi^3 / (128 (1 - phi)^4) (Luding 2001)
double tonks_g(double rho);      // 1D hard rods: 1 / (1 - rho) (Tonks gas, exact)
double carnahan_starling_g(double eta);  // 3D: (1 - eta/2) / (1 - eta)^3 (Carnahan & Starling 1969)

struct HaffPrediction {
  int dim = 2;
  double rho = 0, e = 0, T0 = 1;
  double phi = 0;     // 3D: pi rho / 6; 2D: pi rho / 4; 1D: rho
  double g = 0;       // contact value used
  std::string g_name; // which formula
  double omega0 = 0;  // Enskog collision frequency per particle at T0
  double t0 = 0;      // 2 d / ((1 - e^2) omega0): 4/((1-e^2) omega0) in 2D, 6/((1-e^2) omega0) in 3D
  double E0 = 0;      // d/2 T0
};

// Enskog: omega0 = 4 sqrt(pi) rho g sqrt(T0) (3D), 2 sqrt(pi) rho g sqrt(T0) (2D), (2/sqrt(pi)) rho g
// sqrt(T0) (1D), all the d-dimensional 2 pi^((d-1)/2)/Gamma(d/2) rho g sqrt(T0); zeta0 = (1 - e^2)
// omega0 / d and t0 = 2 / zeta0. In 3D that is 1/t0 = (2/3)(1 - e^2) g rho sqrt(pi T0), Haff's law as
// Brilliantov & Poeschel, Kinetic Theory of Granular Gases (Oxford, 2004), write it (without the
// Sonine correction). Throws UsageError for dim not 1-3, rho out of range, e outside [0, 1), T0 <= 0.
HaffPrediction enskog_haff(int dim, double rho, double e, double T0, Contact contact = Contact::henderson);

struct HaffFit : FitQuality {
  double E0 = 0, E0_stderr = 0, t0 = 0, t0_stderr = 0;
};

// Nonlinear least squares of E(t) = E0 / (1 + t/t0)^2 over the samples in `w` (>= 3, E > 0).
HaffFit fit_haff(const Series& s, const Window& w);

}  // namespace gg::fit
