#pragma once
// The velocity cutoff (gg-sim --delta): a collision whose normal relative speed is below delta is
// elastic (McNamara 1993; Ben-Naim et al., paper section II), which keeps a cooling gas from
// collapsing. A collision part only: no state, nothing written.
#include <cmath>
#include <cstdint>

#include "ggsim/effects/effect_parameters.hpp"
#include "ggsim/effects/effect_state.hpp"
#include "ggsim/effects/hooks.hpp"
#include "ggsim/effects/registry_entry.hpp"

namespace ggsim {

// What a scene asks of the cutoff (src/scene/collapse_cutoff_scenes.cpp): delta, 0 for none.
struct CutoffParameters {
  double delta = 0;
};

class VelocityCutoff {
 public:
  static constexpr Hooks kHooks = hook::restitution;

  template <class Parameters>
  VelocityCutoff(const Parameters& par, const EffectStart&) : delta_(effect_parameters<CutoffParameters>(par).delta) {}

  // |n.v_ij| < delta: elastic. At the threshold itself the collision is inelastic.
  void restitution(double& e, double vn, std::uint32_t, std::uint32_t, double) const {
    if (std::abs(vn) < delta_) e = 1;
  }

 private:
  double delta_;
};

// Its entry in the registry (effects/registry.hpp, registry_entry.hpp).
struct CutoffEffect {
  static constexpr std::string_view kName = "cutoff";
  template <int D>
  using Unit = VelocityCutoff;
  static const SceneEffect& scene();  // src/scene/collapse_cutoff_scenes.cpp
};

}  // namespace ggsim
