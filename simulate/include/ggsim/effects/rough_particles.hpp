#pragma once
// Rough particles (gg-sim --beta, --inertia, --T0-rot; docs/PHYSICS.md "Rough particles"): a
// tangential restitution beta and an angular velocity per particle. The particles rotate freely
// between collisions; a collision adds a tangential impulse to the smooth one (Walton 1993;
// Huthmann & Zippelius, Phys. Rev. E 56, R6275 (1997)): with g the relative velocity of the
// contact points and g_t its part perpendicular to n, eta' = q (1 + beta) / (1 + q),
//   v_i' = v_i + J_t, v_j' = v_j - J_t, J_t = -eta'/2 g_t,  w_i' = w_i + dw, w_j' = w_j + dw,
//   dw = (1 + beta) / ((1 + q) sigma) n x g_t,
// so that g_t' = -beta g_t. beta = -1 adds an impulse of exactly 0: the smooth rule bit for bit.
// (Particles of one mass and diameter: gg-sim refuses rough particles in a mixture.) The
// angular velocities are saved as "spin", [N] in 2D, [N][3] in 3D, and a start may give them; the
// snapshots hold them as "angular_velocity".
#include <array>
#include <cstdint>
#include <optional>
#include <type_traits>
#include <vector>

#include "gg/trajectory.hpp"
#include "ggsim/effects/effect_parameters.hpp"
#include "ggsim/effects/effect_state.hpp"
#include "ggsim/effects/hooks.hpp"
#include "ggsim/effects/registry_entry.hpp"
#include "ggsim/permutation.hpp"
#include "ggsim/prediction.hpp"

namespace ggsim {

// The angular velocity of a particle: a 3-vector in 3D, its z component in 2D (rods in 1D have no
// tangential direction, so a rough collision there is a smooth one and the value stays 0).
template <int D>
using Spin = std::conditional_t<D == 3, Vec<3>, double>;
template <int D>
inline constexpr int kSpinComponents = D == 3 ? 3 : 1;

// What a scene asks of rough particles (src/scene/rough_scene.cpp): beta, unset for smooth ones (a
// rough effect compiled in then acts as beta = -1, the smooth rule, and records nothing); q of
// the moment of inertia I = q m sigma^2 / 4 (unset: default_inertia); the rotational temperature
// of the start (unset: no rotation).
struct RoughParameters {
  std::optional<double> beta{}, inertia{}, T0_rot{};
};

// The moment of inertia of a uniform disk (2D) or sphere (3D), in units of m sigma^2 / 4.
inline double default_inertia(int dim) { return dim == 3 ? 0.4 : 0.5; }

// The moment of inertia of a rough particle (m = sigma = 1), I = q m sigma^2 / 4.
inline double moment_of_inertia(double q) { return 0.25 * q; }

// Angular velocities as the flat array a start or a checkpoint holds, and back.
template <int D>
std::vector<double> flatten_spins(const std::vector<Spin<D>>& spin) {
  std::vector<double> a;
  a.reserve(spin.size() * kSpinComponents<D>);
  for (const Spin<D>& w : spin) {
    if constexpr (D == 3) a.insert(a.end(), w.begin(), w.end());
    else a.push_back(w);
  }
  return a;
}

template <int D>
class RoughParticles {
 public:
  static constexpr Hooks kHooks = hook::after_impulse | hook::prefetch | hook::permute | hook::save | hook::observables | hook::frame_values;

  template <class Parameters>
  RoughParticles(const Parameters& par, const EffectStart& s)
      : RoughParticles(effect_parameters<RoughParameters>(par), s) {}
  RoughParticles(const RoughParameters& p, const EffectStart& s)
      : used_(p.beta.has_value()), beta_(p.beta.value_or(-1)), inertia_(p.inertia.value_or(default_inertia(D))),
        spin_(s.n, Spin<D>{}) {
    if (!s.records) return;
    const std::vector<double> saved = s.records->take_real("spin", s.n * kSpinComponents<D>);
    for (std::size_t i = 0; i < spin_.size() && !saved.empty(); ++i) {
      if constexpr (D == 3) std::copy(&saved[3 * i], &saved[3 * i] + 3, spin_[i].begin());
      else spin_[i] = saved[i];
    }
  }

  // The tangential part of a collision, after the normal one (which changes v_ij along n only,
  // leaving g_t as it was). The tangential impulse does no virial work: r_ij . J_t = 0.
  void after_impulse(Vec<D>& va, Vec<D>& vb, std::uint32_t ia, std::uint32_t ib, const Vec<D>& n) {
    if constexpr (D > 1) tangential(va, vb, spin_[ia], spin_[ib], n);
    else (void)va, (void)vb, (void)ia, (void)ib, (void)n;
  }
  void prefetch(std::uint32_t i) const { __builtin_prefetch(&spin_[i]); }
  template <class Rank>
  void permute(const Rank& rank) { permute_by_rank(spin_, rank); }
  void save(const EffectSink& out) const { out.real("spin", flatten_spins<D>(spin_)); }

  // Rotational energy per particle, I w^2 / 2 summed afresh.
  double rotational_energy() const {
    double s = 0;
    for (const Spin<D>& w : spin_) {
      if constexpr (D == 3) s += dot<3>(w, w);
      else s += w * w;
    }
    return 0.5 * moment_of_inertia(inertia_) * s / static_cast<double>(spin_.size());
  }
  void observables(const ObservableSink& out) const {
    if (used_) out("rotational_energy", gg::kUnitEnergy, rotational_energy());
  }
  // The angular velocities go with the snapshots' velocities (docs/DESIGN.md "Files").
  std::vector<FrameField> frame_fields() const {
    if (!used_) return {};
    return {{.name = "angular_velocity", .components = kSpinComponents<D>, .unit = "tau-1", .with_velocities = true}};
  }
  void frame_values(const FrameSink& out) const {
    if (used_) out("angular_velocity", flatten_spins<D>(spin_));
  }
  const std::vector<Spin<D>>& spins() const { return spin_; }
  std::vector<Spin<D>>& spins() { return spin_; }

 private:
  void tangential(Vec<D>& va, Vec<D>& vb, Spin<D>& wa, Spin<D>& wb, const Vec<D>& n) const {
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
    const double half_eta = 0.5 * inertia_ * (1 + beta_) / (1 + inertia_);
    for (int k = 0; k < D; ++k) {
      const double dv = half_eta * g[k];
      va[k] -= dv;
      vb[k] += dv;
    }
    const double c = (1 + beta_) / (1 + inertia_);  // dw = c n x g_t
    if constexpr (D == 2) {
      const double dw = c * (n[0] * g[1] - n[1] * g[0]);
      wa += dw;
      wb += dw;
    } else {
      const Vec<3> dw{c * (n[1] * g[2] - n[2] * g[1]), c * (n[2] * g[0] - n[0] * g[2]), c * (n[0] * g[1] - n[1] * g[0])};
      for (int k = 0; k < 3; ++k) wa[k] += dw[k], wb[k] += dw[k];
    }
  }

  bool used_;  // whether the scene has rough particles (else the smooth rule, beta = -1)
  double beta_, inertia_;
  std::vector<Spin<D>> spin_;
};

// Its entry in the registry (effects/registry.hpp, registry_entry.hpp).
struct RoughEffect {
  static constexpr std::string_view kName = "rough";
  template <int D>
  using Unit = RoughParticles<D>;
  static const SceneEffect& scene();  // src/scene/rough_scene.cpp
};

}  // namespace ggsim
