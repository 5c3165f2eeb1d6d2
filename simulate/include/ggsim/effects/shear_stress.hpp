#pragma once
// The pressure tensor of a sheared gas (gg-sim --shear-rate; docs/PHYSICS.md "Uniform shear flow"):
// at each sample time t, with V_i the velocity less the mean flow (boundary/sheared.hpp),
//   P_ab = (1 / V) [ sum_i m V_i,a V_i,b + (1 / dt) sum r_ij,a Delta p_i,b over the collisions in (t - dt, t] ],
// the kinetic part at t and the collisional transfer over the time since the last sample (Allen &
// Tildesley, Computer Simulation of Liquids, 2nd ed., sec. 2.7 and 3.7.3; none at the first sample,
// which starts the sum). Observables pressure_xx, pressure_yy, pressure_zz (3D) and pressure_xy;
// their trace over d is the pressure. A checkpoint keeps the sum not yet reported and the time of
// the last sample.
#include <string>
#include <vector>

#include "gg/trajectory.hpp"
#include "ggsim/boundary/sheared.hpp"
#include "ggsim/effects/effect_state.hpp"
#include "ggsim/effects/hooks.hpp"
#include "ggsim/effects/registry_entry.hpp"
#include "ggsim/particles.hpp"

namespace ggsim {

template <int D>
class ShearStress {
 public:
  static constexpr Hooks kHooks = hook::add_collision_stress | hook::observables | hook::save;

  template <class Parameters>
  ShearStress(const Parameters&, const EffectStart& s) : sum_(D * D, 0.0), since_(s.t0) {
    if (!s.records) return;
    if (auto saved = s.records->take_real("shear_stress", D * D); !saved.empty()) sum_ = std::move(saved);
    if (const auto saved = s.records->take_real("shear_stress_since", 1); !saved.empty()) since_ = saved[0];
  }

  // A collision gave particle i the momentum w r_ij (w > 0: pushed away from j).
  void add_collision_stress(const Vec<D>& r, double w) {
    for (int a = 0; a < D; ++a)
      for (int b = 0; b < D; ++b) sum_[a * D + b] += w * r[a] * r[b];
  }

  void observables(const ObservableSink& out, const Sample& at) {
    const double dt = at.t - since_;
    if (dt > 0) {
      const std::vector<double> kinetic = at.velocity_tensor();
      const auto element = [&](int a, int b) { return (kinetic[a * D + b] + sum_[a * D + b] / dt) / at.volume; };
      const std::string unit = gg::pressure_unit(D);
      out("pressure_xx", unit, element(0, 0));
      out("pressure_yy", unit, element(1, 1));
      if constexpr (D == 3) out("pressure_zz", unit, element(2, 2));
      out("pressure_xy", unit, element(0, 1));
    }
    sum_.assign(sum_.size(), 0.0);
    since_ = at.t;
  }
  void save(const EffectSink& out) const {
    out.real("shear_stress", sum_);
    out.real("shear_stress_since", {since_});
  }

 private:
  std::vector<double> sum_;  // sum of r_ij,a Delta p_i,b since the last sample, row-major
  double since_;             // the last sample time
};

// Its entry in the registry (effects/registry.hpp, registry_entry.hpp).
struct ShearEffect {
  static constexpr std::string_view kName = "shear";
  template <int D>
  using Unit = ShearStress<D>;
  // The box is the sliding brick of Lees-Edwards images.
  template <int D>
  using Boundary = ShearedBoundary<D>;
  static const SceneEffect& scene();  // src/scene/shear_scene.cpp
};

}  // namespace ggsim
