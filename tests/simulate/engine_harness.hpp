#pragma once
// Shared helpers of the engine tests: building a state, observers that record or check.
#include <cmath>
#include <vector>

#include "ggsim/engine.hpp"
#include "ggsim/initial_state.hpp"

namespace ggtest {

using ggsim::Vec;

template <int D>
struct Start {
  gg::Box<D> box;
  std::vector<Vec<D>> r, v;
};

// Random homogeneous start at density rho in a cubic box of edge L, T = T0.
template <int D>
Start<D> random_start(double L, double rho, std::uint64_t seed, double T0 = 1) {
  Start<D> s;
  std::array<double, D> edges;
  edges.fill(L);
  s.box = gg::Box<D>(edges);
  ggsim::Random rng(seed);
  const auto n = static_cast<std::size_t>(std::llround(rho * std::pow(L, D)));
  s.r = ggsim::random_positions<D>(s.box, n, rng);
  s.v = ggsim::maxwellian_velocities<D>(n, T0, rng);
  return s;
}

// Observer that records nothing.
struct Silent {
  double next_time() const { return ggsim::kNever; }
  template <class E> void observe(E&, double) {}
  template <class E> bool poll(const E&) { return false; }
};

// Observer that samples the kinetic energy at given times.
struct EnergyAt {
  std::vector<double> times, energy;
  std::size_t k = 0;
  double next_time() const { return k < times.size() ? times[k] : ggsim::kNever; }
  template <class E> void observe(E& eng, double) { energy.push_back(eng.kinetic_energy()), ++k; }
  template <class E> bool poll(const E&) { return false; }
};

// Smallest pair distance at time t over all pairs (O(N^2): for small systems only).
template <class E>
double min_distance(const E& eng, double t) {
  double best = 1e300;
  for (std::size_t i = 0; i < eng.size(); ++i) {
    const auto a = eng.position_at(i, t);
    for (std::size_t j = i + 1; j < eng.size(); ++j) {
      const auto b = eng.position_at(j, t);
      double d2 = 0;
      for (std::size_t k = 0; k < a.size(); ++k) {
        const double d = eng.box().min_image(a[k] - b[k], static_cast<int>(k));
        d2 += d * d;
      }
      best = std::min(best, d2);
    }
  }
  return std::sqrt(best);
}

template <class E>
std::vector<double> total_momentum(const E& eng, double* abs_sum) {
  std::vector<double> p(eng.particle(0).v.size(), 0.0);
  *abs_sum = 0;
  for (std::size_t i = 0; i < eng.size(); ++i)
    for (std::size_t k = 0; k < p.size(); ++k) p[k] += eng.particle(i).v[k], *abs_sum += std::abs(eng.particle(i).v[k]);
  return p;
}

}  // namespace ggtest
