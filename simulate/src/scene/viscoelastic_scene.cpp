// Viscoelastic particles' part of a scene: --viscoelastic K (docs/PHYSICS.md "Viscoelastic
// particles"; the engine's side is effects/viscoelastic_restitution.hpp).
#include <cmath>

#include "gg/h5file.hpp"
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

  void check(SimConfig& c) const override {
    const double k = law(c);
    require(std::isfinite(k) && k >= 0, "--viscoelastic must be >= 0 (got " + str(k) + "): K = A alpha^(2/5) of the dissipative Hertz law");
    if (k == 0) return;
    require(!c.aggregate, "--viscoelastic is not available with --aggregate (merging particles do not bounce); drop one");
  }

  std::string replaces_restitution(const SimConfig& c) const override {
    return law(c) != 0 ? "--viscoelastic (it sets the restitution of every collision)" : "";
  }

  void fingerprint(const SimConfig& c, std::ostream& s) const override {
    if (law(c) > 0) s << " viscoelastic=" << law(c);
  }

  std::vector<SceneKey> keys() const override {
    return {{"viscoelastic", "viscoelastic", [](SimConfig& c, const std::string& s) { c.effects.set<ViscoelasticParameters>().k = number(s); }}};
  }

  void write_parameters(gg::H5Output& out, const SimConfig& c, const SceneSize&) const override {
    if (law(c) > 0) out.attr("/parameters", "viscoelastic", law(c));
  }

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
