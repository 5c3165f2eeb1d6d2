// The two collapse cutoffs' parts of a scene: --delta, the velocity cutoff, and --tc, the TC model
// (docs/PHYSICS.md "Inelastic collapse"; the engine's sides are effects/velocity_cutoff.hpp and
// effects/tc_model.hpp). Each is one number >= 0 of the scene, 0 for none.
#include <cmath>

#include "ggsim/effects/effect_set.hpp"
#include "scene_effects.hpp"

namespace ggsim {

namespace {

// P: the effect's parameters, whose number `value` the option sets; `particle_bytes`: what the effect keeps per particle.
template <class P>
class CutoffScene final : public SceneEffect {
 public:
  CutoffScene(const char* key, double P::*value, double particle_bytes, const char* help)
      : key_(key), value_(value), particle_bytes_(particle_bytes), help_(help) {}

  void add_options(SceneOptions& options, SimConfig& c) const override {
    options.number(option(), c.effects.set<P>().*value_, help_);
  }

  std::string option() const override { return "--" + std::string(key_); }

  void check(SimConfig& c) const override {
    const double x = value(c);
    require(std::isfinite(x) && x >= 0, option() + " must be >= 0 (got " + str(x) + ")");
  }

  std::string collapse_cutoff() const override { return option() + " 1e-4"; }

  // In /parameters for every run (0: none), as the study's scripts read it.
  std::vector<SceneKey> keys() const override { return {scene_key(key_, value_, "0", Written::kAlways)}; }

  bool used(const SimConfig& c) const override { return value(c) > 0; }

  SceneFootprint footprint(const SimConfig& c) const override {
    return {.particle_bytes = value(c) > 0 ? particle_bytes_ : 0.0};
  }

 private:
  double value(const SimConfig& c) const { return c.effects.get<P>().*value_; }
  const char* key_;
  double P::*value_;
  double particle_bytes_;
  const char* help_;
};

}  // namespace

const SceneEffect& CutoffEffect::scene() {
  static const CutoffScene<CutoffParameters> scene("delta", &CutoffParameters::delta, 0,
                                 "Velocity cutoff: collisions with |n.v_ij| < delta are elastic (default 0: off)");
  return scene;
}

const SceneEffect& TcEffect::scene() {
  static const CutoffScene<TcParameters> scene("tc", &TcParameters::tc,
                                                  8,  // each particle's last collision time
                                 "TC model: elastic if a partner collided less than tc ago (default 0: off)");
  return scene;
}

}  // namespace ggsim
