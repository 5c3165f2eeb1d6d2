// Viscoelastic particles' part of a scene: --viscoelastic K (docs/PHYSICS.md "Viscoelastic
// particles"; the engine's side is effects/viscoelastic_restitution.hpp).
#include <cmath>

#include "ggsim/effects/effect_set.hpp"
#include "scene_effects.hpp"

namespace ggsim {

namespace {

class ViscoelasticScene final : public SceneEffect {
 public:
  void add_options(SceneOptions& options, SimConfig& c) const override {
    options.number("--viscoelastic", c.effects.set<ViscoelasticParameters>().k,
                   "Viscoelastic particles: K = A alpha^(2/5) of the dissipative Hertz law; each collision's e is "
                   "epsilon(K g^(1/5)) at its normal impact speed g, 1 - 1.15344 K g^(1/5) + ... (Brilliantov et al. "
                   "1996), instead of --e (0 = off)");
  }

  std::string option() const override { return "--viscoelastic"; }

  void check(SimConfig& c) const override {
    const double k = law(c);
    require(std::isfinite(k) && k >= 0, "--viscoelastic must be >= 0 (got " + str(k) + "): K = A alpha^(2/5) of the dissipative Hertz law");
  }

  std::string replaces_restitution(const SimConfig& c) const override {
    return law(c) != 0 ? "--viscoelastic (it sets the restitution of every collision)" : "";
  }

  std::vector<SceneKey> keys() const override { return {scene_key("viscoelastic", &ViscoelasticParameters::k)}; }

  bool used(const SimConfig& c) const override { return law(c) > 0; }

 private:
  static double law(const SimConfig& c) { return c.effects.get<ViscoelasticParameters>().k; }
};

}  // namespace

const SceneEffect& ViscoelasticEffect::scene() {
  static const ViscoelasticScene scene;
  return scene;
}

}  // namespace ggsim
