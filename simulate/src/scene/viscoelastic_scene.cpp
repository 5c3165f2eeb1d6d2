// Viscoelastic particles' part of a scene: --viscoelastic K (docs/PHYSICS.md "Viscoelastic
// particles"; the engine's side is effects/viscoelastic_restitution.hpp).
#include <cmath>

#include "gg/h5file.hpp"
#include "scene_effects.hpp"

namespace ggsim {

namespace {

class ViscoelasticScene final : public SceneEffect {
 public:
  void add_options(SceneOptions& options, SimConfig& c) const override {
    options.number("--viscoelastic", c.viscoelastic,
                   "Viscoelastic particles: K = A alpha^(2/5) of the dissipative Hertz law; each collision's e is "
                   "epsilon(K g^(1/5)) at its normal impact speed g, 1 - 1.15344 K g^(1/5) + ... (Brilliantov et al. "
                   "1996), instead of --e (0 = off)");
  }

  void check(SimConfig& c) const override {
    require(std::isfinite(c.viscoelastic) && c.viscoelastic >= 0,
            "--viscoelastic must be >= 0 (got " + str(c.viscoelastic) + "): K = A alpha^(2/5) of the dissipative Hertz law");
    if (c.viscoelastic == 0) return;
    require(!c.aggregate, "--viscoelastic is not available with --aggregate (merging particles do not bounce); drop one");
  }

  std::string restitution_flag(const SimConfig& c) const override { return c.viscoelastic != 0 ? "--viscoelastic" : ""; }

  void fingerprint(const SimConfig& c, std::ostream& s) const override {
    if (c.viscoelastic > 0) s << " viscoelastic=" << c.viscoelastic;
  }

  std::vector<SceneKey> keys() const override {
    return {{"viscoelastic", "viscoelastic", [](SimConfig& c, const std::string& s) { c.viscoelastic = number(s); }}};
  }

  void write_parameters(gg::H5Output& out, const SimConfig& c, const SceneSize&) const override {
    if (c.viscoelastic > 0) out.attr("/parameters", "viscoelastic", c.viscoelastic);
  }
};

}  // namespace

const SceneEffect& viscoelastic_scene() {
  static const ViscoelasticScene scene;
  return scene;
}

}  // namespace ggsim
