// Uniform shear flow's part of a scene: --shear-rate (docs/PHYSICS.md "Uniform shear flow"; the
// engine's side is boundary/sheared.hpp's ShearedBoundary and effects/shear_stress.hpp).
#include <cmath>

#include "ggsim/effects/effect_set.hpp"
#include "scene_effects.hpp"

namespace ggsim {

namespace {

class ShearScene final : public SceneEffect {
 public:
  void add_options(SceneOptions& options, SimConfig& c) const override {
    options.number("--shear-rate", c.effects.set<ShearParameters>().rate,
                   "Shear the gas at this rate a with Lees-Edwards images: the mean flow u_x = a (y - L/2) along x "
                   "(axis 0) varies along y (axis 1); the start has it (0 = no shear). Adds pressure_xx, _yy, "
                   "(_zz,) _xy to the observables; E(t) is then the energy of the velocities less the mean flow");
  }

  std::string option() const override { return "--shear-rate"; }

  // The sheared box is compiled with the image counts and no other effect (GG_ENGINE_VARIANTS,
  // simulate/CMakeLists.txt).
  std::vector<Exclusion> exclusions() const override {
    return {{kEveryOtherEffect & ~kBit<ImagesEffect>, "a sheared box runs with no other effect but --unwrapped"}};
  }

  void check(SimConfig& c) const override {
    const double a = rate(c);
    require(std::isfinite(a), "--shear-rate must be a finite number (got " + str(a) + ")");
    if (a == 0) return;
    require(c.dim >= 2, "--shear-rate needs --dim 2 or 3 (a flow axis x and a gradient axis y)");
    require(!c.starts_from_file() && c.equilibrate == 0,
            "--shear-rate starts from its own flow; drop --init FILE and --equilibrate");
  }

  void shape_start(const SimConfig& c, StartShape& shape) const override { shape.shear = rate(c); }

  std::vector<SceneKey> keys() const override { return {scene_key("shear_rate", &ShearParameters::rate, "0")}; }

  bool used(const SimConfig& c) const override { return rate(c) != 0; }

 private:
  static double rate(const SimConfig& c) { return c.effects.get<ShearParameters>().rate; }
};

}  // namespace

const SceneEffect& ShearEffect::scene() {
  static const ShearScene scene;
  return scene;
}

}  // namespace ggsim
