#pragma once
// Flight under gravity, a motion law (free_flight.hpp) whose g its effect gives (the walls',
// effects/walls.hpp).
#include <cmath>

#include "ggsim/hot_path.hpp"
#include "ggsim/particles.hpp"
#include "ggsim/prediction.hpp"

namespace ggsim {

// Flight under a constant acceleration -g along the last axis (gravity, docs/PHYSICS.md "Walls and
// gravity"): z(t_i + dt) = z + v_z dt - g dt^2 / 2, v_z(t_i + dt) = v_z - g dt; the other axes fly
// freely. g = 0 is free flight bit for bit (the added terms are exact zeros).
struct UniformGravity {
  explicit UniformGravity(double gravity) : g(gravity) {}

  template <int D>
  GG_ALWAYS_INLINE double coordinate(const Particle<D>& q, int k, double dt) const {
    const double fall = k == D - 1 ? 0.5 * g * dt * dt : 0.0;
    return q.r[k] + q.v[k] * dt - fall;
  }
  template <int D>
  GG_ALWAYS_INLINE double velocity(const Particle<D>& q, int k, double dt) const {
    return k == D - 1 ? q.v[k] - g * dt : q.v[k];
  }
  bool bends() const { return g != 0; }
  // A lower bound on the time to leave the sphere: the particle has moved at most |v| t + g t^2 / 2
  // from where it was, so it is inside until that reaches the distance to the sphere's edge. (An
  // early exit costs an event and no exactness: the engine then gives the particle a new shell.)
  template <int D>
  double time_to_leave_sphere(const Vec<D>& r, const Vec<D>& v, double radius) const {
    if (g == 0) return time_to_leave<D>(r, v, radius);
    const double room = radius - std::sqrt(dot<D>(r, r));
    if (room <= 0) return 0;
    const double speed = std::sqrt(dot<D>(v, v));
    // The positive root of g t^2 / 2 + speed t - room = 0, written without cancellation.
    return 2 * room / (speed + std::sqrt(speed * speed + 2 * g * room));
  }

  double g;
};

}  // namespace ggsim
