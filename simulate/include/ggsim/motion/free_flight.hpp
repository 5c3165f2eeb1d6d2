#pragma once
// The motion law: how a particle moves between its events (docs/DESIGN.md "Boundary and motion
// law"). The engine, its look-ahead and its observers ask the law where a particle is and how fast
// it moves a time dt after its record, and how long it stays within a sphere (its shell); no other
// place writes the flight formula. The law a scene runs is its variant's (EngineVariant::Motion), fixed
// at compile time, so free flight costs what the formula costs:
//   FreeFlight      here, every scene's but the walls';
//   UniformGravity  a force common to all particles (gravity.hpp), which keeps every pair's
//                   relative motion a free flight, so collision prediction stays as it is; it moves
//                   velocities as well as positions and bends the exits from a shell.
#include "ggsim/hot_path.hpp"
#include "ggsim/particles.hpp"
#include "ggsim/prediction.hpp"

namespace ggsim {

// Ballistic flight: r(t_i + dt) = r + v dt, v unchanged.
struct FreeFlight {
  template <class Parameters>
  explicit FreeFlight(const Parameters&) {}
  FreeFlight() = default;

  // Coordinate k of q a time dt after its record (not folded into the box).
  template <int D>
  GG_ALWAYS_INLINE static double coordinate(const Particle<D>& q, int k, double dt) {
    return q.r[k] + q.v[k] * dt;
  }
  // Velocity component k of q a time dt after its record.
  template <int D>
  GG_ALWAYS_INLINE static double velocity(const Particle<D>& q, int k, double) {
    return q.v[k];
  }
  // Whether paths curve: a shell is then centred on its particle, not ahead of it (engine.hpp).
  static constexpr bool bends() { return false; }
  // How long a particle at offset r from a sphere's centre, moving with v, stays within `radius`.
  template <int D>
  static double time_to_leave_sphere(const Vec<D>& r, const Vec<D>& v, double radius) {
    return time_to_leave<D>(r, v, radius);
  }
};

}  // namespace ggsim
