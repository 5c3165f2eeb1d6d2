#pragma once
// Theory the tests of the uniform-shear-flow scene (Lees-Edwards, simulate/include/ggsim/boundary/sheared.hpp)
// compare with, in the units of docs/DESIGN.md: sigma = m = k_B = 1, T = m <V_x^2> with V the peculiar
// velocity, d = 2 (disks) or 3 (spheres). x is the flow axis, y the gradient axis: u_x = a y.
// Sources and what was checked of them: docs/PHYSICS.md "Uniform shear flow". The papers
// are cited without equation numbers: only their abstracts could be read when this was written, so each
// formula is derived or reduced to a checkable form in its comment and tested in shear_flow_theory_test.
//
//  - Elastic gas: Enskog's shear viscosity (first Sonine approximation) and the temperature of a gas
//    heated by a constant shear rate a.
//  - Dilute granular gas (restitution alpha < 1): the steady uniform shear flow of Grad's method, in
//    which alpha alone sets the reduced shear rate a* and the reduced pressure tensor.
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace shear_theory {

// Packing fraction phi of n particles of unit diameter per unit volume: pi n / 4 (disks), pi n / 6
// (spheres), i.e. the volume pi^(d/2) / (2^d Gamma(d/2 + 1)) of one particle times n.
inline double packing_fraction(int d, double n) {
  return std::pow(std::numbers::pi, d / 2.0) / (std::pow(2.0, d) * std::tgamma(d / 2.0 + 1)) * n;
}

// Contact value chi = g(sigma+) of the equilibrium pair correlation, the chi of every Enskog formula:
// Henderson, Mol. Phys. 30, 971 (1975), (1 - 7 phi/16) / (1 - phi)^2 for disks; Carnahan & Starling,
// J. Chem. Phys. 51, 635 (1969), (1 - phi/2) / (1 - phi)^3 for spheres.
inline double contact_value(int d, double phi) {
  if (d == 2) return (1 - 7 * phi / 16) / ((1 - phi) * (1 - phi));
  if (d == 3) return (1 - phi / 2) / std::pow(1 - phi, 3);
  throw std::invalid_argument("shear_theory::contact_value: d must be 2 or 3");
}

// Shear viscosity of the dilute (Boltzmann) elastic gas in the first Sonine approximation,
// eta0 = (d + 2) Gamma(d/2) / (8 pi^((d-1)/2)) sqrt(T) (the d-dimensional form used by Garzo & Dufty,
// Phys. Rev. E 59, 5895 (1999)): 5 / (16 sqrt(pi)) sqrt(T) for spheres (Chapman & Cowling, The
// Mathematical Theory of Non-Uniform Gases, first approximation), 1 / (2 sqrt(pi)) sqrt(T) for disks.
inline double dilute_viscosity(int d, double T) {
  return (d + 2) * std::tgamma(d / 2.0) / (8 * std::pow(std::numbers::pi, (d - 1) / 2.0)) * std::sqrt(T);
}

// The collision frequency that reduces the shear rate of the granular theory below: nu0 = n T / eta0,
// (16/5) sqrt(pi) n sqrt(T) for spheres, 2 sqrt(pi) n sqrt(T) for disks. a* = a / nu0.
inline double nu0(int d, double n, double T) { return n * T / dilute_viscosity(d, T); }

// Enskog's shear viscosity of elastic hard disks or spheres over eta0, first Sonine approximation, at
// packing fraction phi and contact value chi: the elastic limit (alpha = 1) of Garzo & Dufty (1999),
//   eta / eta0 = (1/chi) (1 + 2^d phi chi / (d + 2))^2 + (d / (d + 2)) kappa / eta0,
//   kappa / eta0 = 2^(2d+2) / (pi (d + 2)) phi^2 chi   (Enskog's bulk viscosity).
// In 3D, with b rho = 4 phi, this is Chapman & Cowling's 1/chi + (4/5) b rho + (4/25)(1 + 12/pi)
// (b rho)^2 chi; in 2D it is 1/chi + 2 phi + (1 + 8/pi) phi^2 chi (Gass, J. Chem. Phys. 54, 1898 (1971)).
inline double enskog_viscosity_ratio(int d, double phi, double chi) {
  const double kinetic = 1 + std::pow(2.0, d) * phi * chi / (d + 2);
  const double bulk = std::pow(2.0, 2 * d + 2) / (std::numbers::pi * (d + 2)) * phi * phi * chi;
  return kinetic * kinetic / chi + d * bulk / (d + 2);
}

// Enskog's shear viscosity of elastic disks (d = 2, Henderson's chi) or spheres (d = 3,
// Carnahan-Starling's chi) at number density n and temperature T.
inline double enskog_viscosity(int d, double n, double T) {
  const double phi = packing_fraction(d, n);
  return enskog_viscosity_ratio(d, phi, contact_value(d, phi)) * dilute_viscosity(d, T);
}

// Temperature at time t of an elastic gas at density n, temperature T0 at t = 0, sheared at the
// constant rate a. Energy balance (exact for hard particles under Lees-Edwards): (d/2) n dT/dt =
// -a P_xy; Newton's law P_xy = -eta a with Enskog's eta = eta1 sqrt(T) gives d sqrt(T)/dt =
// eta1 a^2 / (d n), so sqrt(T) grows linearly: T(t) = (sqrt(T0) + eta1 a^2 t / (d n))^2. Newton's law
// holds to O(a*^2), a* = a / nu0(T), and after the initial build-up of P_xy (a few collision times).
inline double sheared_elastic_temperature(int d, double n, double a, double T0, double t) {
  const double root = std::sqrt(T0) + enskog_viscosity(d, n, 1) * a * a * t / (d * n);
  return root * root;
}

// Dilute gas of inelastic hard disks or spheres (restitution alpha), Maxwellian estimates of the
// Boltzmann collision integral (Brey, Dufty, Kim & Santos, Phys. Rev. E 58, 4638 (1998); Garzo &
// Dufty (1999), their dilute limit, the fourth cumulant a2 set to 0), in units of nu0:
// the cooling rate zeta* = zeta / nu0 = (d + 2)(1 - alpha^2) / (4 d), i.e. Haff's zeta = (1 - alpha^2) omega / d
// with the collision frequency omega at chi = 1 (docs/PHYSICS.md "Homogeneous cooling"), ...
inline double reduced_cooling_rate(int d, double alpha) { return (d + 2) * (1 - alpha * alpha) / (4.0 * d); }

// ... and the relaxation rate of the traceless pressure tensor Pi, beta = -J[m V_x V_y] / (nu0 P_xy)
// for Grad's distribution f_M (1 + (m / 2T) Pi_ij V_i V_j / p) to first order in Pi:
// beta = (1 + alpha)(2d + 3 - 3 alpha) / (4 d) (Garzo & Dufty's nu_eta* at alpha < 1; 1 when elastic).
inline double reduced_stress_relaxation(int d, double alpha) {
  return (1 + alpha) * (2 * d + 3 - 3 * alpha) / (4.0 * d);
}

// Steady uniform shear flow of the dilute granular gas, reduced by nu0 and n T: the shear rate
// a* = a / nu0(n, T) and P*_ij = P_ij / (n T). P*_zz = P*_yy in 3D.
struct SteadyShear {
  double a;     // a*
  double P_xx;  // flow direction
  double P_yy;  // gradient direction (and vorticity direction z in 3D)
  double P_xy;  // < 0 for a > 0
};

// Grad's solution (moment equations closed by the collisional moment above, linear in Pi; the
// granular USF as in Santos, Garzo & Dufty, Phys. Rev. E 69, 061303 (2004)). The steady moment
// equations a_ik P_kj + a_jk P_ik = -nu0 [beta (P_ij - p delta_ij) + zeta* p delta_ij] with a_xy = a give
//   P*_yy = 1 - zeta*/beta,  P*_xx = 1 + (d - 1) zeta*/beta,  P*_xy = -a* P*_yy / beta,
// and their trace, viscous heating = collisional cooling (-a* P*_xy = (d/2) zeta*), fixes
//   a*^2 = (d/2) zeta* beta^2 / (beta - zeta*).
// alpha -> 1: a* -> 0, P* -> identity, -P*_xy / a* -> 1 (Newton's law with eta0).
inline SteadyShear grad_steady_shear(int d, double alpha) {
  const double zeta = reduced_cooling_rate(d, alpha), beta = reduced_stress_relaxation(d, alpha);
  SteadyShear s;
  s.P_yy = 1 - zeta / beta;
  s.P_xx = 1 + (d - 1) * zeta / beta;
  s.a = std::sqrt(0.5 * d * zeta * beta * beta / (beta - zeta));
  s.P_xy = -s.a * s.P_yy / beta;
  return s;
}

}  // namespace shear_theory
