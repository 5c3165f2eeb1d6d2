#pragma once
// The collision of two smooth particles, with what the scene's effects add to it
// (effects/effect_set.hpp): they may make it elastic, add an impulse, or take its virial.
#include <cmath>
#include <cstdint>

#include "ggsim/effects/effect_parameters.hpp"
#include "ggsim/particles.hpp"

namespace ggsim {

// The scene's collision parameters: its restitution, and each effect's own, which the effect
// reads when the engine is built (effects/effect_parameters.hpp).
struct RuleParameters {
  double e = 1;  // coefficient of restitution
  EffectParameters effects;
};

// Applies paper eqs. (6)-(7) to particles i, j already advanced to the collision time t:
//   v_i' = v_i - (1+e)/2 [n.(v_i - v_j)] n,  v_j' = v_j + (1+e)/2 [n.(v_i - v_j)] n,
// with n the unit vector from j to i, after the effects have had their say on e. Returns
// r_ij . Delta p_i, the virial of this collision, which the effects also see (add_virial, and
// Delta p_i itself add_collision_stress).
// With sizes (effects/particle_sizes.hpp) the masses m_i, m_j weigh the impulse (docs/PHYSICS.md
// "Mixtures"):
//   v_i' = v_i - (1+e) m_j/(m_i+m_j) [n.v_ij] n,  v_j' = v_j + (1+e) m_i/(m_i+m_j) [n.v_ij] n;
// for equal masses m_j/(m_i+m_j) is exactly 1/2, and the products below round as the plain
// rule's do (a factor 1/2 is exact), so equal masses give the plain rule's bits.
template <int D, class Set>
double collide(Particle<D>& a, Particle<D>& b, std::uint32_t ia, std::uint32_t ib, const Vec<D>& r_ab, double t,
               double e, Set& effects) {
  const double dist = std::sqrt(dot<D>(r_ab, r_ab));
  Vec<D> n;
  for (int k = 0; k < D; ++k) n[k] = r_ab[k] / dist;
  double vn = 0;
  for (int k = 0; k < D; ++k) vn += n[k] * (a.v[k] - b.v[k]);
  effects.restitution(e, vn, ia, ib, t);
  double virial;  // r_ij . Delta p_i
  if constexpr (Set::kSizes) {
    const double ma = effects.mass(ia), mb = effects.mass(ib);
    const double wa = mb / (ma + mb), wb = ma / (ma + mb);
    const double dva = wa * (1 + e) * vn, dvb = wb * (1 + e) * vn;  // speed changes along -n and n
    for (int k = 0; k < D; ++k) {
      a.v[k] -= dva * n[k];
      b.v[k] += dvb * n[k];
    }
    virial = -ma * dva * dist;  // -(1+e) mu (n.v_ij) |r_ij|, mu = m_i m_j/(m_i+m_j)
    effects.add_collision_stress(r_ab, -ma * dva / dist);
  } else {
    const double impulse = 0.5 * (1 + e) * vn;  // |Delta p| along -n for i (mass 1)
    for (int k = 0; k < D; ++k) {
      const double dv = impulse * n[k];
      a.v[k] -= dv;
      b.v[k] += dv;
    }
    virial = -impulse * dist;  // -(1+e)/2 (n.v_ij) |r_ij|
    effects.add_collision_stress(r_ab, -impulse / dist);
  }
  effects.after_impulse(a.v, b.v, ia, ib, n);
  ++a.collisions;
  ++b.collisions;
  effects.add_virial(virial);
  return virial;
}

}  // namespace ggsim
