#pragma once
// Restitution that rises to 1 for slow impacts (gg-sim --e-speed V; docs/PHYSICS.md "Impact-speed
// restitution"). Below the impact speed V the coefficient of normal restitution is
//   e(g) = 1 - (1 - e) (g / V)^p,
// and the scene's e at and above V, with p = 3/4 unless --e-exponent says otherwise: the law Bizon,
// Shattuck, Swift, McCormick & Swinney used for vibrated layers (PRL 80, 57 (1998), V = sqrt(g sigma)),
// which mimics that real grains bounce back almost elastically from slow impacts. A cooling gas
// then dissipates less the colder it is: once its impacts are below V, dT/dt ~ -T^(3/2 + p/2), so
// T ~ t^(-2/(1+p)) (t^(-8/7) at p = 3/4) instead of Haff's t^(-2).
#include <cmath>
#include <cstdint>

#include "ggsim/effects/effect_parameters.hpp"
#include "ggsim/effects/effect_state.hpp"
#include "ggsim/effects/hooks.hpp"
#include "ggsim/effects/registry_entry.hpp"

namespace ggsim {

// What a scene asks of the law (src/scene/impact_speed_scene.cpp): the speed V (0: no law) and p.
struct ImpactSpeedParameters {
  double speed = 0;
  double exponent = 0.75;
};

class ImpactSpeedRestitution {
 public:
  static constexpr Hooks kHooks = hook::restitution;

  template <class Parameters>
  ImpactSpeedRestitution(const Parameters& par, const EffectStart&)
      : speed_(effect_parameters<ImpactSpeedParameters>(par).speed),
        exponent_(effect_parameters<ImpactSpeedParameters>(par).exponent) {}

  // The scene's e above V; V = 0 (a scene without the law) leaves it at every speed.
  void restitution(double& e, double vn, std::uint32_t, std::uint32_t, double) const {
    const double g = std::abs(vn);
    if (g < speed_) e = 1 - (1 - e) * std::pow(g / speed_, exponent_);
  }

 private:
  double speed_, exponent_;
};

// Its entry in the registry (effects/registry.hpp, registry_entry.hpp).
struct ImpactSpeedEffect {
  static constexpr std::string_view kName = "impact";
  template <int D>
  using Unit = ImpactSpeedRestitution;
  static const SceneEffect& scene();  // src/scene/impact_speed_scene.cpp
};

}  // namespace ggsim
