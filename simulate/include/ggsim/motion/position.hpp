#pragma once
// A particle's position and velocity a time dt after its record, under a motion law (free_flight.hpp,
// gravity.hpp): the one place they are put together from the law's coordinates, for the engine, its
// look-ahead, its boundaries and its observers alike. Not folded into the box.
#include "ggsim/hot_path.hpp"
#include "ggsim/particles.hpp"

namespace ggsim {

template <int D, class Motion>
GG_ALWAYS_INLINE Vec<D> position_after(const Motion& motion, const Particle<D>& q, double dt) {
  Vec<D> x;
  for (int k = 0; k < D; ++k) x[k] = motion.coordinate(q, k, dt);
  return x;
}

template <int D, class Motion>
GG_ALWAYS_INLINE Vec<D> velocity_after(const Motion& motion, const Particle<D>& q, double dt) {
  Vec<D> v;
  for (int k = 0; k < D; ++k) v[k] = motion.velocity(q, k, dt);
  return v;
}

}  // namespace ggsim
