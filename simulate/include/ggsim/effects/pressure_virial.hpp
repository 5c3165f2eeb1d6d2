#pragma once
// The pressure (gg-sim --pressure; docs/PHYSICS.md "Pressure"): the collisional virial, the sum of
// r_ij . Delta p_i over the collisions between two sample times, gives at each sample time t
//   P = rho T + (1 / (d V dt)) sum r_ij . Delta p_i over (t - dt, t],   T = 2 E / d,
// the observable "pressure" (docs/DESIGN.md). A checkpoint saves the sum not yet reported as
// "virial" and the time of the last sample as "virial_since".
#include <string>
#include <vector>

#include "gg/trajectory.hpp"
#include "ggsim/effects/effect_parameters.hpp"
#include "ggsim/effects/effect_state.hpp"
#include "ggsim/effects/hooks.hpp"
#include "ggsim/effects/registry_entry.hpp"

namespace ggsim {

// Whether a scene asks for the pressure (src/scene/switch_scenes.cpp).
struct PressureParameters {
  bool on = false;
};

class PressureVirial {
 public:
  static constexpr Hooks kHooks = hook::add_virial | hook::observables | hook::save;

  template <class Parameters>
  PressureVirial(const Parameters& par, const EffectStart& s) : used_(effect_parameters<PressureParameters>(par).on), since_(s.t0) {
    if (!s.records) return;
    if (const auto saved = s.records->take_real("virial", 1); !saved.empty()) sum_ = saved[0];
    if (const auto saved = s.records->take_real("virial_since", 1); !saved.empty()) since_ = saved[0];
  }

  void add_virial(double w) { sum_ += w; }
  // The sum since the last sample (the tests compute a pressure of their own from it).
  double virial() const { return sum_; }
  // The pressure over the time since the last sample (none at the first, which starts the sum).
  void observables(const ObservableSink& out, const Sample& at) {
    if (!used_) return;
    const double dt = at.t - since_;
    if (dt > 0) {
      const double T = 2 * at.kinetic_energy / at.dim;
      out("pressure", gg::pressure_unit(at.dim), at.n / at.volume * T + sum_ / (at.dim * at.volume * dt));
    }
    sum_ = 0;
    since_ = at.t;
  }
  void save(const EffectSink& out) const {
    out.real("virial", {sum_});
    out.real("virial_since", {since_});
  }

 private:
  bool used_;  // whether the scene asks for the pressure
  double sum_ = 0;
  double since_;  // the last sample time
};

// Its entry in the registry (effects/registry.hpp, registry_entry.hpp).
struct VirialEffect {
  static constexpr std::string_view kName = "virial";
  template <int D>
  using Unit = PressureVirial;
  static const SceneEffect& scene();  // src/scene/switch_scenes.cpp (--pressure)
};

}  // namespace ggsim
