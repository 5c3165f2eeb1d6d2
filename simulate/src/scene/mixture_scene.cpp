// A mixture's part of a scene: --radii, --masses, --fractions (docs/DESIGN.md "Mixtures",
// mixture.hpp; the engine's side is effects/particle_sizes.hpp), and the sizes of a start from a
// mixture's output. Its sizes, species and temperatures are outputs of the run (run_output.cpp).
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "gg/errors.hpp"
#include "gg/h5file.hpp"
#include "gg/particle_volume.hpp"
#include "gg/trajectory.hpp"
#include "ggsim/effects/effect_set.hpp"
#include "ggsim/mixture.hpp"
#include "ggsim/recorder.hpp"
#include "scene_effects.hpp"

namespace ggsim {

namespace {

// Whether a file is the output of a mixture (docs/DESIGN.md "Mixtures").
bool holds_mixture(const gg::H5Input& in) { return in.exists("/observables/temperature_species"); }

// The sizes of a mixture's output at its last frame, and the species of its n particles.
Sizes sizes_from_file(const gg::H5Input& in, std::size_t n, const std::string& path) {
  Sizes s;
  const std::size_t last = in.shape("/particles/all/mass/value").at(0) - 1;
  s.radius = in.read_rows("/particles/all/radius/value", {last}).data;
  s.mass = in.read_rows("/particles/all/mass/value", {last}).data;
  for (std::int64_t x : in.read_int("/particles/all/species")) s.species.push_back(static_cast<std::uint32_t>(x));
  bool valid = s.radius.size() == n && s.mass.size() == n && s.species.size() == n;
  for (std::size_t i = 0; valid && i < n; ++i) {
    valid = s.radius[i] > 0 && s.mass[i] > 0 && std::isfinite(s.radius[i]) && std::isfinite(s.mass[i]);
    s.species_count = std::max(s.species_count, s.species[i] + 1);
  }
  if (!valid)
    throw gg::RuntimeError("--init " + path + ": /particles/all/radius, mass or species do not give every particle a "
                           "positive radius and mass; give an output of gg-sim --radii or --masses");
  return s;
}

class MixtureScene final : public SceneEffect {
 public:
  // A mixture's lists stay text: MixtureSpec parses them.
  void add_options(SceneOptions& options, SimConfig& c) const override {
    MixtureParameters& m = c.effects.set<MixtureParameters>();
    options.list("--radii", m.radii, "A mixture: the radius of each species, R1,R2,... (the unit of length stays "
                 "the diameter of a default particle, radius 0.5), or a polydisperse gas, uniform:LO:HI (radii "
                 "uniform in [LO, HI]); --rho stays the number density");
    options.list("--masses", m.masses, "The mass of each species, m1,m2,... (one with uniform: radii; default: "
                 "(2R)^dim, the volume at the material density of a mass-1 particle of radius 0.5)");
    options.list("--fractions", m.fractions, "The number fraction of each species, f1,f2,... summing to 1 "
                 "(default: equal)");
  }

  std::string option() const override { return "--radii or --masses"; }

  void check(SimConfig& c) const override {
    const MixtureParameters& m = mixture(c);
    if (!m.given()) {
      require(m.fractions.empty(), "--fractions belongs to a mixture; give --radii or --masses per species, or drop it");
      return;
    }
    const MixtureSpec spec = MixtureSpec::parse(m.radii, m.masses, m.fractions);
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

  std::vector<SceneKey> keys() const override {
    return {scene_key("radii", &MixtureParameters::radii), scene_key("masses", &MixtureParameters::masses),
            scene_key("fractions", &MixtureParameters::fractions)};
  }

  bool used(const SimConfig& c) const override { return mixture(c).given(); }

  // Drawn for --radii or --masses; a mixture's output as --init FILE gives those of its last frame.
  Sizes start_sizes(const SimConfig& c, const StartFile& file, std::size_t n, Random& rng) const override {
    const MixtureParameters& m = mixture(c);
    if (m.given()) return draw_sizes(MixtureSpec::parse(m.radii, m.masses, m.fractions), n, c.dim, rng);
    if (!file.in) return {};
    const bool sized = holds_mixture(*file.in);
    if (sized && c.equilibrate > 0)
      throw gg::UsageError("--init " + c.init + " holds a mixture; --equilibrate runs equal particles; drop it");
    if (file.in->exists("/particles/all/mass") && !sized)
      throw gg::UsageError("--init " + c.init + " holds aggregates of an --aggregate run (/particles/all/mass); gg-sim "
                           "starts only from particles of unit mass and diameter");
    return sized ? sizes_from_file(*file.in, n, c.init) : Sizes{};
  }

  // The number of species and the packing fraction of a run with species (docs/DESIGN.md
  // "Mixtures"). Their temperatures, [T][species], are an observable of the sizes effect
  // (effects/particle_sizes.hpp), the species of each particle goes with the snapshots and its
  // sizes with the more fields.
  void write_results(gg::H5Output& out, const SimConfig& c, const Recorder& rec, const SceneSize& size) const override {
    const auto temperatures = rec.effect_observables().find("temperature_species");
    if (temperatures == rec.effect_observables().end()) return;
    out.attr("/parameters", "species", static_cast<std::int64_t>(temperatures->second.width));
    double filled = 0;
    for (double r : rec.fixed("radius")) filled += gg::particle_volume(r, c.dim);
    out.attr("/parameters", "packing_fraction", filled / size.volume);
  }

  // A radius, a mass and a species in the engine (effects/particle_sizes.hpp), and a species and a
  // radius by particle number at the end of the run; a mass and a radius in each snapshot.
  SceneFootprint footprint(const SimConfig& c) const override {
    if (!mixture(c).given()) return {};
    return {.particle_bytes = 36, .frame_bytes = 16};
  }

 private:
  static const MixtureParameters& mixture(const SimConfig& c) { return c.effects.get<MixtureParameters>(); }
};

}  // namespace

const SceneEffect& MixtureEffect::scene() {
  static const MixtureScene scene;
  return scene;
}

}  // namespace ggsim
