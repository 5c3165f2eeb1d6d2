// Walls and gravity's part of a scene: --walls H, --wall-e, --wall-T, --wall-amplitude,
// --wall-frequency, --gravity (docs/PHYSICS.md
// "Walls and gravity"; the engine's side is boundary/walls.hpp, effects/walls.hpp and motion/gravity.hpp).
#include <cmath>

#include "gg/h5file.hpp"
#include "ggsim/effects/effect_set.hpp"
#include "scene_effects.hpp"

namespace ggsim {

namespace {

// The engine's box is this much longer than the walls' distance along their axis (boundary/walls.hpp):
// a pair never meets through that axis's periodic image before one of the two meets its wall.
constexpr double kGap = 1;

class WallsScene final : public SceneEffect {
 public:
  void add_options(SceneOptions& options, SimConfig& c) const override {
    WallParameters& w = c.effects.set<WallParameters>();
    options.number("--walls", w.height,
                   "Hard flat walls across the last axis (y in 2D, z in 3D) at 0 and H = this height, in diameters; "
                   "--L is then the edge of the other, periodic, axes (give --N and --L; 0 = no walls)");
    options.number("--wall-e", w.restitution, "Normal restitution of the walls, 0 < e_w <= 1 (default 1: elastic)");
    options.number("--wall-T", w.temperature, "Make the bottom wall thermal at this temperature: a particle leaves it with a "
                   "velocity drawn from the flux of a Maxwellian at T_w (0 = not thermal)");
    options.number("--wall-amplitude", w.amplitude, "Vibrate the bottom wall with this amplitude A: its velocity is "
                   "A w cos(w t), w = 2 pi f, its position stays 0 (the zero-amplitude model of a vibrated bed)");
    options.number("--wall-frequency", w.frequency, "Frequency f of the bottom wall's vibration (with --wall-amplitude)");
    options.number("--gravity", w.gravity, "Constant acceleration g towards the bottom wall, in sigma/tau^2 (needs --walls)");
  }

  std::string option() const override { return "--walls"; }

  // Walls are compiled with no other effect (GG_ENGINE_VARIANTS, simulate/CMakeLists.txt).
  std::vector<Exclusion> exclusions() const override { return {{kEveryOtherEffect, "a box with walls runs with no other effect"}}; }

  void check(SimConfig& c) const override {
    const WallParameters& w = walls(c);
    require(std::isfinite(w.height) && w.height >= 0,
            "--walls must be a height >= 0 in diameters (got " + str(w.height) + ")");
    if (w.height == 0) {
      require(w.restitution == 1 && w.temperature == 0 && w.amplitude == 0 && w.frequency == 0 && w.gravity == 0,
              "--wall-e, --wall-T, --wall-amplitude, --wall-frequency and --gravity belong to walls; give --walls HEIGHT "
              "or drop them");
      return;
    }
    require(c.dim >= 2, "--walls needs --dim 2 or 3 (walls across the last axis of a plane or a box)");
    require(w.height > 2, "--walls " + str(w.height) + " leaves no room between the walls; give a height "
                                "above 2 diameters");
    require(std::isfinite(w.restitution) && w.restitution > 0 && w.restitution <= 1, "--wall-e must lie in (0, 1] (got " + str(w.restitution) + ")");
    require(std::isfinite(w.temperature) && w.temperature >= 0, "--wall-T must be a temperature >= 0 (got " + str(w.temperature) + ")");
    require(std::isfinite(w.amplitude) && w.amplitude >= 0 && std::isfinite(w.frequency) &&
                w.frequency >= 0 && (w.amplitude > 0) == (w.frequency > 0),
            "--wall-amplitude and --wall-frequency go together, each > 0 (got " + str(w.amplitude) + " and " +
                str(w.frequency) + ")");
    require(w.amplitude == 0 || w.temperature == 0, "the bottom wall is either thermal (--wall-T) or vibrated "
                                                    "(--wall-amplitude); drop one");
    require(std::isfinite(w.gravity) && w.gravity >= 0, "--gravity must be >= 0 (got " + str(w.gravity) + "); it "
                                                        "points towards the bottom wall");
    require(!c.starts_from_file() && c.equilibrate == 0,
            "--walls starts from particles drawn between its walls; drop --init FILE and --equilibrate");
    require(!c.rho_given, "with --walls give --N and --L (the edge of the periodic axes); the density N / (L^(d-1) H) "
                          "follows");
    c.rho = static_cast<double>(c.N) / (std::pow(c.L, c.dim - 1) * w.height);
  }

  // The box: periodic edge L, and H plus the gap along the last axis; the particles are drawn in a
  // box of height H - sigma and put sigma/2 above the bottom wall, so that none overlaps a wall.
  void shape_start(const SimConfig& c, StartShape& shape) const override {
    const WallParameters& w = walls(c);
    if (w.height == 0) return;
    shape.edges.back() = w.height + kGap;
    shape.region.back() = w.height - 1;
    shape.offset.back() = 0.5;
  }

  // The walls close the last axis: the box is not periodic along it.
  void close_axes(const SimConfig& c, std::vector<bool>& periodic) const override {
    if (walls(c).height > 0) periodic.back() = false;
  }

  std::vector<SceneKey> keys() const override {
    return {scene_key("walls", &WallParameters::height, "0"),
            scene_key("wall_e", &WallParameters::restitution, "1"),
            scene_key("wall_T", &WallParameters::temperature, "0"),
            scene_key("wall_amplitude", &WallParameters::amplitude, "0"),
            scene_key("wall_frequency", &WallParameters::frequency, "0"),
            scene_key("gravity", &WallParameters::gravity, "0")};
  }

  // The output's rho is N over the box's volume; between the walls the gas is denser.
  void write_results(gg::H5Output& out, const SimConfig& c, const Recorder&, const SceneSize& size) const override {
    const WallParameters& w = walls(c);
    if (w.height > 0) out.attr("/parameters", "rho_between_walls", size.n / size.volume * (w.height + kGap) / w.height);
  }

  bool used(const SimConfig& c) const override { return walls(c).height > 0; }

  // A thermal wall draws from the scene's seed.
  void start_parameters(const SimConfig& c, const SceneSize&, EffectParameters& p) const override {
    if (walls(c).height > 0) p.set<WallParameters>().seed = c.seed;
  }

 private:
  static const WallParameters& walls(const SimConfig& c) { return c.effects.get<WallParameters>(); }
};

}  // namespace

const SceneEffect& WallsEffect::scene() {
  static const WallsScene scene;
  return scene;
}

}  // namespace ggsim
