#pragma once
// The kinetic theory of a dilute gas whose restitution depends on the impact speed, eps(g), and the
// engine's gases to compare with it (docs/PHYSICS.md "Viscoelastic particles"; Schwager & Poschel,
// PRE 57, 650 (1998)). Mass 1, diameter 1, T = <v_x^2>: a pair meets at normal speed g with rate
// ~ g exp(-g^2 / 4T) and loses (1 - eps^2) g^2 / 4, so
//   dT/dt = -(omega0(T) / d) T <1 - eps(g)^2>,  weight g^3 exp(-g^2 / 4T) on g > 0,
// with the Enskog collision frequency omega0 = 2 sqrt(pi) n chi sqrt(T) (2D, chi of Henderson) or
// 4 sqrt(pi) n chi sqrt(T) (3D, chi of Carnahan-Starling). With constant eps this is Haff's law.
#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "engine_harness.hpp"

namespace ggtest {

// Number density of packing fraction phi.
template <int D>
double density_of(double phi) {
  return D == 2 ? 4 * phi / std::numbers::pi : 6 * phi / std::numbers::pi;
}

// <1 - eps(g)^2> over the impact speeds of a Maxwellian at T (midpoint rule to 12 sqrt(T)).
template <class Eps>
double mean_loss(double T, const Eps& eps) {
  double num = 0, den = 0;
  const double gmax = 12 * std::sqrt(T), dg = gmax / 4000;
  for (int k = 1; k <= 4000; ++k) {
    const double g = (k - 0.5) * dg, w = g * g * g * std::exp(-g * g / (4 * T));
    const double e = eps(g);
    num += w * (1 - e * e), den += w;
  }
  return num / den;
}

// T(t) of the theory at `times` (RK4, 400 steps between times), from T = 1, at packing fraction phi.
template <int D, class Eps>
std::vector<double> theory_temperatures(double phi, const Eps& eps, const std::vector<double>& times) {
  const double chi = D == 2 ? (1 - 7 * phi / 16) / ((1 - phi) * (1 - phi)) : (1 - phi / 2) / std::pow(1 - phi, 3);
  const double omega_per_sqrt_t = (D == 2 ? 2 : 4) * std::sqrt(std::numbers::pi) * density_of<D>(phi) * chi;
  const auto rate = [&](double T) { return -(omega_per_sqrt_t * std::sqrt(T) / D) * T * mean_loss(T, eps); };
  std::vector<double> out;
  double T = 1, t = 0;
  for (double t_end : times) {
    const int steps = 400;
    const double h = (t_end - t) / steps;
    for (int k = 0; k < steps; ++k) {
      const double a = rate(T), b = rate(T + h / 2 * a), c = rate(T + h / 2 * b), d = rate(T + h * c);
      T += h / 6 * (a + 2 * b + 2 * c + d);
    }
    t = t_end;
    out.push_back(T);
  }
  return out;
}

// The mean T at `times` of `runs` independent gases of N particles at packing fraction phi, each
// from elastic equilibrium (seeds 31, 32, ...), run by the engine variant Fx with parameters par.
template <int D, class Fx>
std::vector<double> measured_temperatures(double N, int runs, double phi, const ggsim::EngineParameters& par,
                                          const std::vector<double>& times) {
  const double n = density_of<D>(phi);
  const double L = std::pow(N / n, 1.0 / D);
  std::vector<double> mean(times.size(), 0);
  for (int run = 0; run < runs; ++run) {
    auto s = equilibrium<D>(L, n, 31 + static_cast<std::uint64_t>(run));
    ggsim::Engine<D, Fx> eng(s.box, s.r, s.v, par);
    EnergyAt obs;
    obs.times = times;
    EXPECT_EQ(eng.run(times.back(), ~0ull, obs), ggsim::StopReason::kTimeReached);
    for (std::size_t j = 0; j < times.size(); ++j) mean[j] += obs.energy[j] * 2 / D / runs;  // T = 2E/d
  }
  return mean;
}

// The local exponent d ln T / d ln t between the last two times.
inline double late_exponent(const std::vector<double>& T, const std::vector<double>& times) {
  const std::size_t a = times.size() - 2, b = times.size() - 1;
  return std::log(T[b] / T[a]) / std::log(times[b] / times[a]);
}

}  // namespace ggtest
