// The pressure's part of a scene: --pressure (docs/PHYSICS.md "Hard disks at equilibrium"; the
// engine's side is effects/pressure_virial.hpp).
#include "gg/h5file.hpp"
#include "scene_effects.hpp"

namespace ggsim {

namespace {

class PressureScene final : public SceneEffect {
 public:
  void add_options(SceneOptions& options, SimConfig& c) const override {
    options.flag("--pressure", c.pressure, "Record the pressure (kinetic + collisional virial)");
  }

  void check(SimConfig& c) const override {
    require(!(c.aggregate && c.pressure),
            "--pressure has no meaning with --aggregate (touching particles merge); drop it");
  }

  void fingerprint(const SimConfig& c, std::ostream& s) const override {
    if (c.pressure) s << " pressure=1";
  }

  std::vector<SceneKey> keys() const override {
    return {{"pressure", "pressure", [](SimConfig& c, const std::string& s) { c.pressure = s == "1"; }, "0"}};
  }

  void write_parameters(gg::H5Output& out, const SimConfig& c, const SceneSize&) const override {
    out.attr("/parameters", "pressure", static_cast<std::int64_t>(c.pressure));
  }
};

}  // namespace

const SceneEffect& pressure_scene() {
  static const PressureScene scene;
  return scene;
}

}  // namespace ggsim
