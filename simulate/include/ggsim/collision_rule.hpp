#pragma once
// The collision rule with the effects a scene may ask for, composed at compile time: a scene
// without a cutoff, t_c or pressure runs code without a branch for them (each effect a policy,
// as the pair evaluators of HOOMD-blue are: an unused effect costs nothing).
#include <vector>

#include "ggsim/hot_path.hpp"
#include "ggsim/particles.hpp"

namespace ggsim {

// Which effects are compiled in. Each flag is a template argument of the engine.
template <bool Cutoff, bool Tc, bool Virial, bool Images = false, bool Aggregate = false, bool Driven = false,
          bool Mixture = false>
struct Effects {
  static constexpr bool kCutoff = Cutoff;  // elastic if |n.v_ij| < delta (McNamara; Ben-Naim et al.)
  static constexpr bool kTc = Tc;          // elastic if a partner collided < t_c ago (Luding & McNamara 1998)
  static constexpr bool kVirial = Virial;  // accumulate sum r_ij . Delta p_i for the pressure
  static constexpr bool kImages = Images;  // count boundary crossings (gg-sim --unwrapped, image_counts.hpp)
  // Colliding particles merge (the ballistic aggregation model, aggregation.hpp) instead of
  // bouncing: radii and masses per particle, and the number of particles shrinks.
  static constexpr bool kAggregate = Aggregate;
  // Random kicks at times of their own between events (the white-noise drive, drive.hpp).
  static constexpr bool kDriven = Driven;
  // A radius and a mass per particle that collisions keep (a mixture or a polydisperse gas,
  // mixture.hpp): contact at R_i + R_j, impulses by the masses.
  static constexpr bool kMixture = Mixture;
};

// The ballistic aggregation model: no restitution, no cutoff, no pressure, no images.
using Aggregation = Effects<false, false, false, false, true>;

struct RuleParameters {
  double e = 1;      // coefficient of restitution
  double delta = 0;  // velocity cutoff
  double tc = 0;     // TC-model time
};

// Applies paper eqs. (6)-(7) to particles i, j already advanced to the collision time t:
//   v_i' = v_i - (1+e)/2 [n.(v_i - v_j)] n,  v_j' = v_j + (1+e)/2 [n.(v_i - v_j)] n,
// with n the unit vector from j to i. Returns r_ij . Delta p_i (the virial of this collision).
// With Fx::kMixture the masses m_i, m_j weigh the impulse (docs/PHYSICS.md "Mixtures"):
//   v_i' = v_i - (1+e) m_j/(m_i+m_j) [n.v_ij] n,  v_j' = v_j + (1+e) m_i/(m_i+m_j) [n.v_ij] n;
// for equal masses m_j/(m_i+m_j) is exactly 1/2, and the products below round as the plain
// rule's do (a factor 1/2 is exact), so equal masses give the plain rule's bits.
template <int D, class Fx>
struct CollisionRule {
  RuleParameters p;
  std::vector<double> last_collision;  // per particle, only with the TC model

  // Asks memory for what apply() will read of particle i and nothing else (the engine's
  // look-ahead calls it for the events a few buckets ahead): only the TC model reads data of its
  // own, the last collision times at random places, so the other rules compile to nothing.
  GG_ALWAYS_INLINE void prefetch(std::uint32_t i) const {
    if constexpr (Fx::kTc) __builtin_prefetch(&last_collision[i]);
    else (void)i;
  }

  double apply(Particle<D>& a, Particle<D>& b, std::uint32_t ia, std::uint32_t ib, const Vec<D>& r_ab,
               double t, double ma = 1, double mb = 1) {
    const double dist = std::sqrt(dot<D>(r_ab, r_ab));
    Vec<D> n;
    for (int k = 0; k < D; ++k) n[k] = r_ab[k] / dist;
    double vn = 0;
    for (int k = 0; k < D; ++k) vn += n[k] * (a.v[k] - b.v[k]);
    double e = p.e;
    if constexpr (Fx::kCutoff) {
      if (std::abs(vn) < p.delta) e = 1;
    }
    if constexpr (Fx::kTc) {
      if (t - last_collision[ia] < p.tc || t - last_collision[ib] < p.tc) e = 1;
      last_collision[ia] = last_collision[ib] = t;
    } else {
      (void)ia, (void)ib, (void)t;
    }
    if constexpr (Fx::kMixture) {
      const double wa = mb / (ma + mb), wb = ma / (ma + mb);
      const double dva = wa * (1 + e) * vn, dvb = wb * (1 + e) * vn;  // speed changes along -n and n
      for (int k = 0; k < D; ++k) {
        a.v[k] -= dva * n[k];
        b.v[k] += dvb * n[k];
      }
      ++a.collisions;
      ++b.collisions;
      // r_ij . Delta p_i = -(1+e) mu (n.v_ij) |r_ij|, mu = m_i m_j/(m_i+m_j)
      if constexpr (Fx::kVirial) return -ma * dva * dist;
      return 0;
    } else {
      (void)ma, (void)mb;
      const double impulse = 0.5 * (1 + e) * vn;  // |Delta p| along -n for i (mass 1)
      for (int k = 0; k < D; ++k) {
        const double dv = impulse * n[k];
        a.v[k] -= dv;
        b.v[k] += dv;
      }
      ++a.collisions;
      ++b.collisions;
      if constexpr (Fx::kVirial) return -impulse * dist;  // r_ij . Delta p_i = -(1+e)/2 (n.v_ij) |r_ij|
      return 0;
    }
  }
};

}  // namespace ggsim
