#pragma once
// Viscoelastic restitution (gg-sim --viscoelastic K; docs/PHYSICS.md "Viscoelastic particles"): the
// coefficient of normal restitution of viscoelastic spheres depends on the normal impact speed g.
// Two spheres pressed together by xi obey the dissipative Hertz law (Brilliantov, Spahn, Hertzsch &
// Poschel, PRE 53, 5382 (1996))
//   xi'' + alpha xi^(3/2) + A alpha xi^(1/2) xi' = 0,   xi(0) = 0, xi'(0) = g,
// and epsilon = -xi'(t_end) / g when xi returns to 0. In units of its own scales the law has one
// parameter, kappa = A alpha^(2/5) g^(1/5) = K g^(1/5), so epsilon is a function of kappa alone,
//   epsilon = 1 - 1.15344 kappa + 0.79826 kappa^2 -+ ...   (Ramirez, Poschel, Brilliantov &
// Schwager, PRE 60, 4465 (1999)). The series converges only for small kappa; epsilon(kappa) is
// here the law itself, integrated once on a table (restitution_table.cpp) and read by cubic
// interpolation, so it holds at every speed: 1 for grazing impacts (a cooling gas that never
// collapses), small for fast ones.
#include <cmath>
#include <cstdint>

#include "ggsim/effects/effect_parameters.hpp"
#include "ggsim/effects/effect_state.hpp"
#include "ggsim/effects/hooks.hpp"
#include "ggsim/effects/registry_entry.hpp"

namespace ggsim {

// epsilon(kappa) of the dissipative Hertz law (kappa >= 0).
double viscoelastic_epsilon(double kappa);

// What a scene asks of the law (src/scene/viscoelastic_scene.cpp): K = A alpha^(2/5), 0 for none.
struct ViscoelasticParameters {
  double k = 0;
};

class ViscoelasticRestitution {
 public:
  static constexpr Hooks kHooks = hook::restitution;

  template <class Parameters>
  ViscoelasticRestitution(const Parameters& par, const EffectStart&) : k_(effect_parameters<ViscoelasticParameters>(par).k) {}

  // The impact speed |n.v_ij| sets e; K = 0 (a scene without the law) leaves the scene's e.
  void restitution(double& e, double vn, std::uint32_t, std::uint32_t, double) const {
    if (k_ > 0) e = viscoelastic_epsilon(k_ * std::pow(std::abs(vn), 0.2));
  }

 private:
  double k_;
};

// Its entry in the registry (effects/registry.hpp, registry_entry.hpp).
struct ViscoelasticEffect {
  static constexpr std::string_view kName = "viscoelastic";
  template <int D>
  using Unit = ViscoelasticRestitution;
  static const SceneEffect& scene();  // src/scene/viscoelastic_scene.cpp
};

}  // namespace ggsim
