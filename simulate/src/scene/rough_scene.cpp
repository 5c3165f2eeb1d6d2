// Rough particles' part of a scene: --beta, --inertia, --T0-rot (docs/PHYSICS.md "Rough
// particles"; the engine's side is effects/rough_particles.hpp).
#include <cmath>

#include "gg/h5file.hpp"
#include "scene_effects.hpp"

namespace ggsim {

namespace {

class RoughScene final : public SceneEffect {
 public:
  void add_options(SceneOptions& options, SimConfig& c) const override {
    options.number("--beta", c.beta, "Rough particles (--dim 2 or 3): tangential restitution, -1 <= beta <= 1 (-1: "
                   "smooth, 1: perfectly rough; Walton 1993, Huthmann & Zippelius 1997)");
    options.number("--inertia", c.inertia, "q of the moment of inertia I = q m sigma^2 / 4 of rough particles, 0 < q "
                   "<= 1 (default 1/2 in 2D, a uniform disk; 2/5 in 3D, a uniform sphere)");
    options.number("--T0-rot", c.T0_rot, "Rotational temperature of the start of rough particles (default 0: no "
                   "rotation)");
  }

  void check(SimConfig& c) const override {
    if (!c.rough()) {
      require(!c.inertia && !c.T0_rot, "--inertia and --T0-rot belong to rough particles; give --beta or drop them");
      return;
    }
    require(c.dim > 1, "--beta needs rotation, which rods in 1D have not; give --dim 2 or 3, or drop --beta");
    require(std::isfinite(*c.beta) && *c.beta >= -1 && *c.beta <= 1, "--beta must lie in [-1, 1] (got " + str(*c.beta) + ")");
    if (!c.inertia) c.inertia = default_inertia(c.dim);
    require(std::isfinite(*c.inertia) && *c.inertia > 0 && *c.inertia <= 1,
            "--inertia must lie in (0, 1] (got " + str(*c.inertia) + "): q of I = q m sigma^2 / 4");
    require(!c.T0_rot || (std::isfinite(*c.T0_rot) && *c.T0_rot >= 0),
            "--T0-rot must be >= 0 (got " + str(c.T0_rot.value_or(0)) + ")");
    require(!c.aggregate, "--beta is not available with --aggregate (merging particles do not bounce); drop one");
    require(!c.mixture(), "--beta is not available with --radii or --masses (the rough collision rule is written for "
                          "particles of one size and mass); drop one");
  }

  void fingerprint(const SimConfig& c, std::ostream& s) const override {
    if (c.rough())
      s << " beta=" << *c.beta << " inertia=" << c.inertia.value_or(default_inertia(c.dim))
        << " T0_rot=" << c.T0_rot.value_or(0);
  }

  std::vector<SceneKey> keys() const override {
    return {{"beta", "beta", [](SimConfig& c, const std::string& s) { c.beta = number(s); }},
            {"inertia", "inertia", [](SimConfig& c, const std::string& s) { c.inertia = number(s); }},
            {"T0_rot", "T0-rot", [](SimConfig& c, const std::string& s) { c.T0_rot = number(s); }}};
  }

  void write_parameters(gg::H5Output& out, const SimConfig& c, const SceneSize&) const override {
    if (!c.rough()) return;
    out.attr("/parameters", "beta", *c.beta);
    out.attr("/parameters", "inertia", c.inertia.value_or(default_inertia(c.dim)));
    out.attr("/parameters", "T0_rot", c.T0_rot.value_or(0));
  }
};

}  // namespace

const SceneEffect& rough_scene() {
  static const RoughScene scene;
  return scene;
}

}  // namespace ggsim
