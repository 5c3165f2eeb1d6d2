#pragma once
// The collision rule with the effects a scene may ask for, composed at compile time: a scene
// without a cutoff, t_c or pressure runs code without a branch for them (each effect a policy,
// as the pair evaluators of HOOMD-blue are: an unused effect costs nothing).
#include <type_traits>
#include <vector>

#include "ggsim/hot_path.hpp"
#include "ggsim/particles.hpp"

namespace ggsim {

// Which effects are compiled in. Each flag is a template argument of the engine.
template <bool Cutoff, bool Tc, bool Virial, bool Images = false, bool Aggregate = false, bool Driven = false,
          bool Rough = false, bool Mixture = false>
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
  // Rough particles: a tangential restitution beta and an angular velocity per particle
  // (docs/PHYSICS.md "Rough particles"); beta = -1 is the smooth rule bit for bit.
  static constexpr bool kRough = Rough;
  // A radius and a mass per particle that collisions keep (a mixture or a polydisperse gas,
  // mixture.hpp): contact at R_i + R_j, impulses by the masses.
  static constexpr bool kMixture = Mixture;
};

// The angular velocity of a particle: a 3-vector in 3D, its z component in 2D (rods in 1D have no
// tangential direction, so a rough collision there is a smooth one and the value stays 0).
template <int D>
using Spin = std::conditional_t<D == 3, Vec<3>, double>;
template <int D>
inline constexpr int kSpinComponents = D == 3 ? 3 : 1;

// The ballistic aggregation model: no restitution, no cutoff, no pressure, no images.
using Aggregation = Effects<false, false, false, false, true>;

struct RuleParameters {
  double e = 1;      // coefficient of restitution
  double delta = 0;  // velocity cutoff
  double tc = 0;     // TC-model time
  double beta = -1;  // tangential restitution of rough particles (-1: smooth)
  double inertia = 0.5;  // q of the moment of inertia I = q m sigma^2 / 4 (rough particles)
};

// The moment of inertia of a rough particle (m = sigma = 1).
inline double moment_of_inertia(double q) { return 0.25 * q; }

// Applies paper eqs. (6)-(7) to particles i, j already advanced to the collision time t:
//   v_i' = v_i - (1+e)/2 [n.(v_i - v_j)] n,  v_j' = v_j + (1+e)/2 [n.(v_i - v_j)] n,
// with n the unit vector from j to i. Returns r_ij . Delta p_i (the virial of this collision).
// Rough particles (Fx::kRough; Walton 1993, Huthmann & Zippelius 1997, docs/PHYSICS.md "Rough
// particles") add a tangential impulse: with g the relative velocity of the contact points and
// g_t its part perpendicular to n, eta' = q (1 + beta) / (1 + q),
//   v_i' = v_i + J_t, v_j' = v_j - J_t, J_t = -eta'/2 g_t,  w_i' = w_i + dw, w_j' = w_j + dw,
//   dw = (1 + beta) / ((1 + q) sigma) n x g_t,
// so that g_t' = -beta g_t; the normal impulse is the smooth one. (For particles of one mass and
// diameter: gg-sim refuses rough particles in a mixture.)
// With Fx::kMixture the masses m_i, m_j weigh the impulse (docs/PHYSICS.md "Mixtures"):
//   v_i' = v_i - (1+e) m_j/(m_i+m_j) [n.v_ij] n,  v_j' = v_j + (1+e) m_i/(m_i+m_j) [n.v_ij] n;
// for equal masses m_j/(m_i+m_j) is exactly 1/2, and the products below round as the plain
// rule's do (a factor 1/2 is exact), so equal masses give the plain rule's bits.
template <int D, class Fx>
struct CollisionRule {
  RuleParameters p;
  std::vector<double> last_collision;  // per particle, only with the TC model
  std::vector<Spin<D>> spin;           // angular velocity per particle, only for rough particles

  // Asks memory for what apply() will read of particle i and nothing else (the engine's
  // look-ahead calls it for the events a few buckets ahead): only the TC model and rough particles
  // read data of their own (last collision times, angular velocities) at random places, so the
  // other rules compile to nothing.
  GG_ALWAYS_INLINE void prefetch(std::uint32_t i) const {
    if constexpr (Fx::kTc) __builtin_prefetch(&last_collision[i]);
    if constexpr (Fx::kRough) __builtin_prefetch(&spin[i]);
    if constexpr (!Fx::kTc && !Fx::kRough) (void)i;
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
    double virial;  // r_ij . Delta p_i
    if constexpr (Fx::kMixture) {
      const double wa = mb / (ma + mb), wb = ma / (ma + mb);
      const double dva = wa * (1 + e) * vn, dvb = wb * (1 + e) * vn;  // speed changes along -n and n
      for (int k = 0; k < D; ++k) {
        a.v[k] -= dva * n[k];
        b.v[k] += dvb * n[k];
      }
      virial = -ma * dva * dist;  // -(1+e) mu (n.v_ij) |r_ij|, mu = m_i m_j/(m_i+m_j)
    } else {
      (void)ma, (void)mb;
      const double impulse = 0.5 * (1 + e) * vn;  // |Delta p| along -n for i (mass 1)
      for (int k = 0; k < D; ++k) {
        const double dv = impulse * n[k];
        a.v[k] -= dv;
        b.v[k] += dv;
      }
      virial = -impulse * dist;  // -(1+e)/2 (n.v_ij) |r_ij|
    }
    if constexpr (Fx::kRough && D > 1) rough(a.v, b.v, spin[ia], spin[ib], n);
    ++a.collisions;
    ++b.collisions;
    if constexpr (Fx::kVirial) return virial;
    (void)virial;
    return 0;
  }

 private:
  // The tangential part of a rough collision, after the normal one (which leaves g_t as it was:
  // it changes v_ij along n only). The velocities get exactly the normal impulse plus one that is
  // exactly 0 at beta = -1, so that beta = -1 is the smooth rule bit for bit. The tangential
  // impulse does no virial work: r_ij . J_t = 0.
  void rough(Vec<D>& va, Vec<D>& vb, Spin<D>& wa, Spin<D>& wb, const Vec<D>& n) const {
    // g = v_ij - (sigma/2)(w_i + w_j) x n (sigma = 1); in 2D w x n = w (-n_y, n_x).
    Vec<D> g;
    if constexpr (D == 2) {
      const double w = wa + wb;
      g = {va[0] - vb[0] + 0.5 * w * n[1], va[1] - vb[1] - 0.5 * w * n[0]};
    } else {
      const Vec<3> w{wa[0] + wb[0], wa[1] + wb[1], wa[2] + wb[2]};
      g = {va[0] - vb[0] - 0.5 * (w[1] * n[2] - w[2] * n[1]), va[1] - vb[1] - 0.5 * (w[2] * n[0] - w[0] * n[2]),
           va[2] - vb[2] - 0.5 * (w[0] * n[1] - w[1] * n[0])};
    }
    const double gn = dot<D>(g, n);
    for (int k = 0; k < D; ++k) g[k] -= gn * n[k];  // g_t
    const double half_eta = 0.5 * p.inertia * (1 + p.beta) / (1 + p.inertia);
    for (int k = 0; k < D; ++k) {
      const double dv = half_eta * g[k];
      va[k] -= dv;
      vb[k] += dv;
    }
    const double c = (1 + p.beta) / (1 + p.inertia);  // dw = c n x g_t
    if constexpr (D == 2) {
      const double dw = c * (n[0] * g[1] - n[1] * g[0]);
      wa += dw;
      wb += dw;
    } else {
      const Vec<3> dw{c * (n[1] * g[2] - n[2] * g[1]), c * (n[2] * g[0] - n[0] * g[2]), c * (n[0] * g[1] - n[1] * g[0])};
      for (int k = 0; k < 3; ++k) wa[k] += dw[k], wb[k] += dw[k];
    }
  }
};

}  // namespace ggsim
