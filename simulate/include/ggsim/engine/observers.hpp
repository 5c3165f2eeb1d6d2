#pragma once
// Part of the engine (engine.hpp, which includes it after its class): what observers read of the
// particles at a time of their choice (the recorder, the tests): the kinetic energy and the velocity
// tensor less the mean flow, the squared speeds, and every particle's position, velocity and image.
// Reading changes no state, so observations never perturb the trajectory.
// Not to be included on its own.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "ggsim/particles.hpp"

namespace ggsim {

// Kinetic energy per particle (mass 1) at time t, of the velocities less the mean flow in a
// sheared box (t >= every particle's last update; now if
// not given), summed afresh: no drift from incremental updates. For aggregates, per start
// particle (per unit mass): sum m v^2 / 2 over the particles left, / N0; for a mixture,
// sum m v^2 / 2 / N.
template <int D, class Fx>
inline double Engine<D, Fx>::kinetic_energy(double t) const {
  double s = 0;
  for (std::size_t i = 0; i < p_.size(); ++i) {
    const Vec<D> v = peculiar_velocity(p_[i], t);
    s += effects_.mass(static_cast<std::uint32_t>(i)) * dot<D>(v, v);
  }
  return 0.5 * s / static_cast<double>(size());
}

// The sum over the particles of m V_a V_b at time t, V as in kinetic_energy(), row-major d x d.
template <int D, class Fx>
inline std::vector<double> Engine<D, Fx>::velocity_tensor(double t) const {
  std::vector<double> s(D * D, 0.0);
  for (std::size_t i = 0; i < p_.size(); ++i) {
    const Vec<D> v = peculiar_velocity(p_[i], t);
    const double m = effects_.mass(static_cast<std::uint32_t>(i));
    for (int a = 0; a < D; ++a)
      for (int b = 0; b < D; ++b) s[a * D + b] += m * v[a] * v[b];
  }
  return s;
}

// |v|^2 at time t of each particle, in the engine's numbering.
template <int D, class Fx>
inline std::vector<double> Engine<D, Fx>::squared_speeds(double t) const {
  std::vector<double> s(p_.size());
  for (std::size_t i = 0; i < p_.size(); ++i) {
    const Vec<D> v = velocity(p_[i], t);
    for (double x : v) s[i] += x * x;
  }
  return s;
}

// Calls f(number in the start, position at time t folded into the box, velocity) for every
// particle, in the engine's memory order (t >= every particle's last update). Reading does not
// change the state, so observations never perturb the trajectory.
// For aggregates, the particles left (each under the number in the start of one of its parts).
template <int D, class Fx>
template <class F>
inline void Engine<D, Fx>::for_each_particle(double t, F&& f) const {
  for (std::uint32_t i = 0; i < p_.size(); ++i) {
    if (!present(i)) continue;
    const Particle<D>& q = p_[i];
    Vec<D> x = position_after(q, t - q.t), v = velocity(q, t);
    box_.fold(x, v, t);
    for (int k = 0; k < D; ++k) x[k] = box_.wrap(x[k], k);
    f(grid_.label(i), x, v);
  }
}

// Calls f(number in the start, periodic image at time t) for every particle, as
// for_each_particle visits them: with its position there it says where the particle has gone
// since the start (position + image x L; a sheared box adds its slide, boundary/sheared.hpp). Only an
// engine whose effects count images (effects/image_counts.hpp) counts them; else every image is 0.
template <int D, class Fx>
template <class F>
inline void Engine<D, Fx>::for_each_image(double t, F&& f) const {
  for (std::uint32_t i = 0; i < p_.size(); ++i) {
    const Particle<D>& q = p_[i];
    Image<D> a = effects_.image(i);
    Vec<D> x = position_after(q, t - q.t), v = velocity(q, t);  // the fold moves v too; only the count is wanted here
    box_.fold(x, v, t, &a);
    for (int k = 0; k < D; ++k) {
      std::int64_t folds;
      box_.wrap(x[k], k, folds);
      a[k] += static_cast<std::int32_t>(folds);
    }
    f(grid_.label(i), a);
  }
}

}  // namespace ggsim
