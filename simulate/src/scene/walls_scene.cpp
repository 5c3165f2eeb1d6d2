// Walls and gravity's part of a scene: --walls H, --wall-e, --wall-T, --wall-amplitude,
// --wall-frequency, --gravity (docs/PHYSICS.md
// "Walls and gravity"; the engine's side is effects/walls.hpp and motion.hpp's UniformGravity).
#include <cmath>

#include "gg/h5file.hpp"
#include "ggsim/engine_variants.hpp"
#include "scene_effects.hpp"

namespace ggsim {

namespace {

// The engine's box is this much longer than the walls' distance along their axis (effects/walls.hpp):
// a pair never meets through that axis's periodic image before one of the two meets its wall.
constexpr double kGap = 1;

class WallsScene final : public SceneEffect {
 public:
  void add_options(SceneOptions& options, SimConfig& c) const override {
    options.number("--walls", c.walls_height,
                   "Hard flat walls across the last axis (y in 2D, z in 3D) at 0 and H = this height, in diameters; "
                   "--L is then the edge of the other, periodic, axes (give --N and --L; 0 = no walls)");
    options.number("--wall-e", c.wall_e, "Normal restitution of the walls, 0 < e_w <= 1 (default 1: elastic)");
    options.number("--wall-T", c.wall_T, "Make the bottom wall thermal at this temperature: a particle leaves it with a "
                   "velocity drawn from the flux of a Maxwellian at T_w (0 = not thermal)");
    options.number("--wall-amplitude", c.wall_amplitude, "Vibrate the bottom wall with this amplitude A: its velocity is "
                   "A w cos(w t), w = 2 pi f, its position stays 0 (the zero-amplitude model of a vibrated bed)");
    options.number("--wall-frequency", c.wall_frequency, "Frequency f of the bottom wall's vibration (with --wall-amplitude)");
    options.number("--gravity", c.gravity, "Constant acceleration g towards the bottom wall, in sigma/tau^2 (needs --walls)");
  }

  void check(SimConfig& c) const override {
    require(std::isfinite(c.walls_height) && c.walls_height >= 0,
            "--walls must be a height >= 0 in diameters (got " + str(c.walls_height) + ")");
    if (c.walls_height == 0) {
      require(c.wall_e == 1 && c.wall_T == 0 && c.wall_amplitude == 0 && c.wall_frequency == 0 && c.gravity == 0,
              "--wall-e, --wall-T, --wall-amplitude, --wall-frequency and --gravity belong to walls; give --walls HEIGHT "
              "or drop them");
      return;
    }
    require(c.dim >= 2, "--walls needs --dim 2 or 3 (walls across the last axis of a plane or a box)");
    require(c.walls_height > 2, "--walls " + str(c.walls_height) + " leaves no room between the walls; give a height "
                                "above 2 diameters");
    require(std::isfinite(c.wall_e) && c.wall_e > 0 && c.wall_e <= 1, "--wall-e must lie in (0, 1] (got " + str(c.wall_e) + ")");
    require(std::isfinite(c.wall_T) && c.wall_T >= 0, "--wall-T must be a temperature >= 0 (got " + str(c.wall_T) + ")");
    require(std::isfinite(c.wall_amplitude) && c.wall_amplitude >= 0 && std::isfinite(c.wall_frequency) &&
                c.wall_frequency >= 0 && (c.wall_amplitude > 0) == (c.wall_frequency > 0),
            "--wall-amplitude and --wall-frequency go together, each > 0 (got " + str(c.wall_amplitude) + " and " +
                str(c.wall_frequency) + ")");
    require(c.wall_amplitude == 0 || c.wall_T == 0, "the bottom wall is either thermal (--wall-T) or vibrated "
                                                    "(--wall-amplitude); drop one");
    require(std::isfinite(c.gravity) && c.gravity >= 0, "--gravity must be >= 0 (got " + str(c.gravity) + "); it "
                                                        "points towards the bottom wall");
    require(!c.starts_from_file() && c.equilibrate == 0,
            "--walls starts from particles drawn between its walls; drop --init FILE and --equilibrate");
    require(!c.rho_given, "with --walls give --N and --L (the edge of the periodic axes); the density N / (L^(d-1) H) "
                          "follows");
    require(wanted_effects(c) == kWallsBit, "--walls combines with --e only (not with --aggregate, a cutoff, t_c, the "
                                            "pressure, images, a drive, rough particles, a mixture or --viscoelastic)");
    c.rho = static_cast<double>(c.N) / (std::pow(c.L, c.dim - 1) * c.walls_height);
  }

  // The box: periodic edge L, and H plus the gap along the last axis; the particles are drawn in a
  // box of height H - sigma and put sigma/2 above the bottom wall, so that none overlaps a wall.
  void shape_start(const SimConfig& c, StartShape& shape) const override {
    if (c.walls_height == 0) return;
    shape.edges.back() = c.walls_height + kGap;
    shape.region.back() = c.walls_height - 1;
    shape.offset.back() = 0.5;
  }

  void fingerprint(const SimConfig& c, std::ostream& s) const override {
    if (c.walls_height > 0)
      s << " walls=" << c.walls_height << " wall_e=" << c.wall_e << " wall_T=" << c.wall_T
        << " wall_amplitude=" << c.wall_amplitude << " wall_frequency=" << c.wall_frequency << " gravity=" << c.gravity;
  }

  std::vector<SceneKey> keys() const override {
    return {{"walls", "walls", [](SimConfig& c, const std::string& s) { c.walls_height = number(s); }, "0"},
            {"wall_e", "wall-e", [](SimConfig& c, const std::string& s) { c.wall_e = number(s); }, "1"},
            {"wall_T", "wall-T", [](SimConfig& c, const std::string& s) { c.wall_T = number(s); }, "0"},
            {"wall_amplitude", "wall-amplitude", [](SimConfig& c, const std::string& s) { c.wall_amplitude = number(s); }, "0"},
            {"wall_frequency", "wall-frequency", [](SimConfig& c, const std::string& s) { c.wall_frequency = number(s); }, "0"},
            {"gravity", "gravity", [](SimConfig& c, const std::string& s) { c.gravity = number(s); }, "0"}};
  }

  // The output's rho is N over the box's volume; between the walls the gas is denser.
  void write_parameters(gg::H5Output& out, const SimConfig& c, const SceneSize& size) const override {
    if (c.walls_height == 0) return;
    out.attr("/parameters", "walls", c.walls_height);
    out.attr("/parameters", "wall_e", c.wall_e);
    out.attr("/parameters", "wall_T", c.wall_T);
    out.attr("/parameters", "wall_amplitude", c.wall_amplitude);
    out.attr("/parameters", "wall_frequency", c.wall_frequency);
    out.attr("/parameters", "gravity", c.gravity);
    out.attr("/parameters", "rho_between_walls", size.n / size.volume * (c.walls_height + kGap) / c.walls_height);
  }
};

}  // namespace

const SceneEffect& walls_scene() {
  static const WallsScene scene;
  return scene;
}

}  // namespace ggsim
