// Impact-speed restitution's part of a scene: --e-speed V, --e-exponent p (docs/PHYSICS.md
// "Impact-speed restitution"; the engine's side is effects/impact_speed_restitution.hpp).
#include <cmath>

#include "ggsim/effects/effect_set.hpp"
#include "scene_effects.hpp"

namespace ggsim {

namespace {

class ImpactSpeedScene final : public SceneEffect {
 public:
  void add_options(SceneOptions& options, SimConfig& c) const override {
    ImpactSpeedParameters& p = c.effects.set<ImpactSpeedParameters>();
    options.number("--e-speed", p.speed,
                   "Restitution that rises to 1 for slow impacts: below this normal impact speed V, e(g) = 1 - (1 - e) "
                   "(g/V)^p; --e above V (Bizon et al. 1998; 0 = off)");
    options.number("--e-exponent", p.exponent, "The exponent p of --e-speed's law (default 0.75)");
  }

  std::string option() const override { return "--e-speed"; }

  std::vector<Exclusion> exclusions() const override {
    return {{kBit<ViscoelasticEffect>, "both are laws of the restitution"}};
  }

  void check(SimConfig& c) const override {
    const ImpactSpeedParameters& p = law(c);
    require(std::isfinite(p.speed) && p.speed >= 0, "--e-speed must be a speed >= 0 (got " + str(p.speed) + ")");
    if (p.speed == 0) {
      require(p.exponent == ImpactSpeedParameters{}.exponent, "--e-exponent belongs to --e-speed; give --e-speed V or drop it");
      return;
    }
    require(std::isfinite(p.exponent) && p.exponent > 0, "--e-exponent must be > 0 (got " + str(p.exponent) + ")");
  }

  std::vector<SceneKey> keys() const override {
    return {scene_key("e_speed", &ImpactSpeedParameters::speed, "0"),
            scene_key("e_exponent", &ImpactSpeedParameters::exponent, str(ImpactSpeedParameters{}.exponent))};
  }

  bool used(const SimConfig& c) const override { return law(c).speed > 0; }

 private:
  static const ImpactSpeedParameters& law(const SimConfig& c) { return c.effects.get<ImpactSpeedParameters>(); }
};

}  // namespace

const SceneEffect& ImpactSpeedEffect::scene() {
  static const ImpactSpeedScene scene;
  return scene;
}

}  // namespace ggsim
