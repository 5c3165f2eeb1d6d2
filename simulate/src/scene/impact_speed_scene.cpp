// Impact-speed restitution's part of a scene: --e-speed V, --e-exponent p (docs/PHYSICS.md
// "Impact-speed restitution"; the engine's side is effects/impact_speed_restitution.hpp).
#include <cmath>

#include "gg/h5file.hpp"
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

  void check(SimConfig& c) const override {
    const ImpactSpeedParameters& p = law(c);
    require(std::isfinite(p.speed) && p.speed >= 0, "--e-speed must be a speed >= 0 (got " + str(p.speed) + ")");
    if (p.speed == 0) {
      require(p.exponent == ImpactSpeedParameters{}.exponent, "--e-exponent belongs to --e-speed; give --e-speed V or drop it");
      return;
    }
    require(std::isfinite(p.exponent) && p.exponent > 0, "--e-exponent must be > 0 (got " + str(p.exponent) + ")");
    require(!c.aggregate, "--e-speed is not available with --aggregate (merging particles do not bounce); drop one");
    require(c.effects.get<ViscoelasticParameters>().k == 0,
            "--e-speed and --viscoelastic are two laws of the restitution; drop one");
  }

  void fingerprint(const SimConfig& c, std::ostream& s) const override {
    if (law(c).speed > 0) s << " e_speed=" << law(c).speed << " e_exponent=" << law(c).exponent;
  }

  std::vector<SceneKey> keys() const override {
    return {{"e_speed", "e-speed", [](SimConfig& c, const std::string& s) { c.effects.set<ImpactSpeedParameters>().speed = number(s); }, "0"},
            {"e_exponent", "e-exponent",
             [](SimConfig& c, const std::string& s) { c.effects.set<ImpactSpeedParameters>().exponent = number(s); },
             str(ImpactSpeedParameters{}.exponent)}};
  }

  void write_parameters(gg::H5Output& out, const SimConfig& c, const SceneSize&) const override {
    if (law(c).speed == 0) return;
    out.attr("/parameters", "e_speed", law(c).speed);
    out.attr("/parameters", "e_exponent", law(c).exponent);
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
