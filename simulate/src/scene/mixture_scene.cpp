// A mixture's part of a scene: --radii, --masses, --fractions (docs/DESIGN.md "Mixtures",
// mixture.hpp; the engine's side is effects/particle_sizes.hpp). Its sizes, species and
// temperatures are outputs of the run (run_output.cpp).
#include <cstdio>

#include "gg/h5file.hpp"
#include "ggsim/mixture.hpp"
#include "scene_effects.hpp"

namespace ggsim {

namespace {

class MixtureScene final : public SceneEffect {
 public:
  // A mixture's lists stay text: MixtureSpec parses them.
  void add_options(SceneOptions& options, SimConfig& c) const override {
    options.list("--radii", c.radii, "A mixture: the radius of each species, R1,R2,... (the unit of length stays "
                 "the diameter of a default particle, radius 0.5), or a polydisperse gas, uniform:LO:HI (radii "
                 "uniform in [LO, HI]); --rho stays the number density");
    options.list("--masses", c.masses, "The mass of each species, m1,m2,... (one with uniform: radii; default: "
                 "(2R)^dim, the volume at the material density of a mass-1 particle of radius 0.5)");
    options.list("--fractions", c.fractions, "The number fraction of each species, f1,f2,... summing to 1 "
                 "(default: equal)");
  }

  void check(SimConfig& c) const override {
    if (!c.mixture()) {
      require(c.fractions.empty(), "--fractions belongs to a mixture; give --radii or --masses per species, or drop it");
      return;
    }
    const MixtureSpec spec = MixtureSpec::parse(c.radii, c.masses, c.fractions);
    require(!c.aggregate, "--radii and --masses are not available with --aggregate (aggregates have the sizes their "
                          "merging gives them); drop one");
    require(c.init != "lattice", "--init lattice places equal particles; a mixture starts from --init random");
    require(!c.starts_from_file(), "--radii and --masses describe a start of gg-sim's own; --init " + c.init +
                                       " starts from the file's particles; drop them");
    require(c.equilibrate == 0, "--equilibrate runs equal particles; drop it for a mixture");
    // Random sequential addition jams at these packing fractions (Widom; Feder; Cooper): a
    // mixture beyond them cannot be placed.
    constexpr double kJammed[] = {0.7476, 0.547, 0.384};
    const double phi = c.rho * spec.mean_volume(c.dim);
    char text[160];
    std::snprintf(text, sizeof text, "--radii at --rho %.4g fill a packing fraction of %.4g, more than the random "
                  "start can place (%g in %dD); lower --rho or the radii", c.rho, phi, kJammed[c.dim - 1], c.dim);
    require(phi < kJammed[c.dim - 1], text);
  }

  void fingerprint(const SimConfig& c, std::ostream& s) const override {
    if (c.mixture()) s << " radii=" << c.radii << " masses=" << c.masses << " fractions=" << c.fractions;
  }

  std::vector<SceneKey> keys() const override {
    return {{"radii", "radii", [](SimConfig& c, const std::string& s) { c.radii = s; }},
            {"masses", "masses", [](SimConfig& c, const std::string& s) { c.masses = s; }},
            {"fractions", "fractions", [](SimConfig& c, const std::string& s) { c.fractions = s; }}};
  }

  void write_parameters(gg::H5Output& out, const SimConfig& c, const SceneSize&) const override {
    if (!c.mixture()) return;
    out.attr("/parameters", "radii", c.radii);
    out.attr("/parameters", "masses", c.masses);
    out.attr("/parameters", "fractions", c.fractions);
  }
};

}  // namespace

const SceneEffect& mixture_scene() {
  static const MixtureScene scene;
  return scene;
}

}  // namespace ggsim
