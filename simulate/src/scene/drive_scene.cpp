// The white-noise drive's part of a scene: --drive, --drive-strength, --drive-rate
// (docs/PHYSICS.md "Driven gas"; the engine's side is effects/white_noise_drive.hpp).
#include <cmath>

#include "gg/errors.hpp"
#include "gg/h5file.hpp"
#include "ggsim/effects/effect_set.hpp"
#include "scene_effects.hpp"

namespace ggsim {

namespace {

class DriveScene final : public SceneEffect {
 public:
  void add_options(SceneOptions& options, SimConfig& c) const override {
    DriveParameters& d = c.effects.set<DriveParameters>();
    options.text("--drive", d.kind, "Drive the gas: white-noise (random kicks to pairs of particles that keep the "
                 "total momentum; Williams & MacKintosh 1996, van Noije et al. 1999)");
    options.number("--drive-strength", d.strength, "XI of the drive: d<v^2>/dt = 2 dim XI^2 per particle");
    options.number("--drive-rate", d.rate, "Kicks per particle per unit time (default: 20 per collision at the "
                   "steady temperature the Enskog energy balance predicts)");
  }

  std::string option() const override { return "--drive"; }

  // Opposite velocity kicks keep the momentum of equal masses only.
  std::vector<Exclusion> exclusions() const override {
    return {{kBit<MixtureEffect>, "its kicks keep the momentum of equal masses only"}};
  }

  void check(SimConfig& c) const override {
    const DriveParameters& d = drive(c);
    if (d.kind.empty()) {
      require(d.strength == 0 && d.rate == 0,
              "--drive-strength and --drive-rate belong to a driven gas; give --drive white-noise or drop them");
      return;
    }
    require(d.kind == "white-noise", "--drive '" + d.kind + "' is not a drive gg-sim has; give --drive white-noise");
    require(std::isfinite(d.strength) && d.strength > 0,
            "--drive-strength must be positive (got " + str(d.strength) + "): XI of d<v^2>/dt = 2 d XI^2");
    require(std::isfinite(d.rate) && d.rate >= 0, "--drive-rate must be positive kicks per particle per "
                                                  "unit time (got " + str(d.rate) + "), or 0 for the default");
    require(c.N >= 2 || c.starts_from_file(), "--drive kicks pairs of particles: give --N of at least 2");
  }

  // The fingerprint keeps --drive-rate as given (0: the default), /parameters the rate the run used.
  std::vector<SceneKey> keys() const override {
    return {scene_key("drive", &DriveParameters::kind), scene_key("drive_strength", &DriveParameters::strength, "0"),
            scene_key("drive_rate", &DriveParameters::rate, "0", Written::kNever)};
  }

  void write_results(gg::H5Output& out, const SimConfig& c, const Recorder&, const SceneSize& size) const override {
    if (used(c)) out.attr("/parameters", "drive_rate", rate(c, size));
  }

  bool used(const SimConfig& c) const override { return !drive(c).kind.empty(); }

  // The engine's drive draws from the scene's seed at the rate of the run.
  void start_parameters(const SimConfig& c, const SceneSize& size, EffectParameters& p) const override {
    if (drive(c).kind.empty()) return;
    DriveParameters& d = p.set<DriveParameters>();
    d.seed = c.seed;
    d.rate = rate(c, size);
  }

 private:
  static const DriveParameters& drive(const SimConfig& c) { return c.effects.get<DriveParameters>(); }
  // The rate a run uses: --drive-rate, else the default for its density.
  static double rate(const SimConfig& c, const SceneSize& size) {
    const DriveParameters& d = drive(c);
    return d.rate > 0 ? d.rate : default_drive_rate(c.dim, size.n / size.volume, c.e, d.strength, c.T0);
  }
};

}  // namespace

const SceneEffect& DrivenEffect::scene() {
  static const DriveScene scene;
  return scene;
}

}  // namespace ggsim
