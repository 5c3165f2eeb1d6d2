// The white-noise drive's part of a scene: --drive, --drive-strength, --drive-rate
// (docs/PHYSICS.md "Driven gas"; the engine's side is effects/white_noise_drive.hpp).
#include <cmath>

#include "gg/errors.hpp"
#include "gg/h5file.hpp"
#include "ggsim/effects/white_noise_drive.hpp"
#include "scene_effects.hpp"

namespace ggsim {

namespace {

class DriveScene final : public SceneEffect {
 public:
  void add_options(SceneOptions& options, SimConfig& c) const override {
    options.text("--drive", c.drive, "Drive the gas: white-noise (random kicks to pairs of particles that keep the "
                 "total momentum; Williams & MacKintosh 1996, van Noije et al. 1999)");
    options.number("--drive-strength", c.drive_strength, "XI of the drive: d<v^2>/dt = 2 dim XI^2 per particle");
    options.number("--drive-rate", c.drive_rate, "Kicks per particle per unit time (default: 20 per collision at the "
                   "steady temperature the Enskog energy balance predicts)");
  }

  void check(SimConfig& c) const override {
    if (!c.driven()) {
      require(c.drive_strength == 0 && c.drive_rate == 0,
              "--drive-strength and --drive-rate belong to a driven gas; give --drive white-noise or drop them");
      return;
    }
    require(c.drive == "white-noise", "--drive '" + c.drive + "' is not a drive gg-sim has; give --drive white-noise");
    require(std::isfinite(c.drive_strength) && c.drive_strength > 0,
            "--drive-strength must be positive (got " + str(c.drive_strength) + "): XI of d<v^2>/dt = 2 d XI^2");
    require(std::isfinite(c.drive_rate) && c.drive_rate >= 0, "--drive-rate must be positive kicks per particle per "
                                                              "unit time (got " + str(c.drive_rate) + "), or 0 for the default");
    require(!c.aggregate, "--drive is not available with --aggregate (a driven gas of aggregates is not a model "
                          "gg-sim has); drop one");
    require(c.N >= 2 || c.starts_from_file(), "--drive kicks pairs of particles: give --N of at least 2");
    // Opposite velocity kicks keep the momentum of equal masses only.
    require(!c.mixture(), "--drive is not available with --radii or --masses (its kicks keep the momentum of "
                          "equal masses only); drop one");
  }

  void fingerprint(const SimConfig& c, std::ostream& s) const override {
    if (c.driven()) s << " drive=" << c.drive << " drive_strength=" << c.drive_strength << " drive_rate=" << c.drive_rate;
  }

  std::vector<SceneKey> keys() const override {
    return {{"drive", "drive", [](SimConfig& c, const std::string& s) { c.drive = s; }},
            {"drive_strength", "drive-strength", [](SimConfig& c, const std::string& s) { c.drive_strength = number(s); }, "0"},
            {"drive_rate", "drive-rate", [](SimConfig& c, const std::string& s) { c.drive_rate = number(s); }, "0"}};
  }

  // The rate a run used: --drive-rate, else the default for its density.
  void write_parameters(gg::H5Output& out, const SimConfig& c, const SceneSize& size) const override {
    if (!c.driven()) return;
    out.attr("/parameters", "drive", c.drive);
    out.attr("/parameters", "drive_strength", c.drive_strength);
    out.attr("/parameters", "drive_rate", c.drive_rate > 0 ? c.drive_rate
                                              : default_drive_rate(c.dim, size.n / size.volume, c.e,
                                                                   c.drive_strength, c.T0));
  }
};

}  // namespace

const SceneEffect& drive_scene() {
  static const DriveScene scene;
  return scene;
}

}  // namespace ggsim
