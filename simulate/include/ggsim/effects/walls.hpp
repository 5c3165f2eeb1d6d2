#pragma once
// Walls and gravity (gg-sim --walls; docs/PHYSICS.md "Walls and gravity") as an effect of the
// registry: the walls are the engine's boundary (boundary/walls.hpp: when a particle meets one, what
// the meeting does, the energy and momentum they give the gas), particles fall under gravity between
// events (the motion law, motion/gravity.hpp), and the effect's own unit counts the energy the
// collisions take from the gas per particle (in a steady state without gravity's work it balances
// what the walls put in). A checkpoint keeps that count.
#include <cstdint>
#include <string_view>

#include "gg/trajectory.hpp"
#include "ggsim/boundary/walls.hpp"
#include "ggsim/effects/effect_parameters.hpp"
#include "ggsim/effects/effect_state.hpp"
#include "ggsim/effects/hooks.hpp"
#include "ggsim/effects/registry_entry.hpp"
#include "ggsim/motion/gravity.hpp"

namespace ggsim {

template <int D>
class CollisionLoss {
 public:
  static constexpr Hooks kHooks = hook::restitution | hook::observables | hook::save;

  template <class Parameters>
  CollisionLoss(const Parameters&, const EffectStart& s) : n_(static_cast<double>(s.n)) {
    if (!s.records) return;
    if (const auto saved = s.records->take_real("collision_loss", 1); !saved.empty()) lost_ = saved[0];
  }

  // A collision's restitution is the scene's (walls combine with no other effect); the count is
  // the energy it takes, (1 - e^2) (n.v_ij)^2 / 4 for equal masses.
  void restitution(double& e, double vn, std::uint32_t, std::uint32_t, double) { lost_ += 0.25 * (1 - e * e) * vn * vn; }

  void observables(const ObservableSink& out) const { out("collision_loss", gg::kUnitEnergy, lost_ / n_); }
  void save(const EffectSink& out) const { out.real("collision_loss", {lost_}); }

 private:
  double n_;
  double lost_ = 0;
};

// Gravity's motion law (motion/gravity.hpp) with the g the scene gives the walls (--gravity).
struct WallsGravity : UniformGravity {
  template <class Parameters>
  explicit WallsGravity(const Parameters& par) : UniformGravity(effect_parameters<WallParameters>(par).gravity) {}
};

// Its entry in the registry (effects/registry.hpp, registry_entry.hpp).
struct WallsEffect {
  static constexpr std::string_view kName = "walls";
  template <int D>
  using Unit = CollisionLoss<D>;
  // The box is closed by the walls along its last axis.
  template <int D>
  using Boundary = WalledBoundary<D>;
  // Particles fall under the walls' gravity (which may be 0) between events.
  using Motion = WallsGravity;
  static const SceneEffect& scene();  // src/scene/walls_scene.cpp
};

}  // namespace ggsim
