#pragma once
// An effect's part of a scene (docs/DESIGN.md "Where an effect lives"): its command-line options,
// their checks, its keys in the fingerprint a checkpoint compares and resumes from, and what it
// writes to the output's /parameters. gg-sim, SimConfig, the resume code and the output ask every
// effect in scene_effects() in turn, so an effect's scene options live in one file of src/scene/.
// (The engine's side of an effect is its class in effects/.)
#include <functional>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "ggsim/config.hpp"

namespace gg {
class H5Output;
}

namespace ggsim {

// A fingerprint key: the option that sets it (long name without the dashes), how its text goes
// back into a SimConfig, and the value a fingerprint leaves out.
struct SceneKey {
  std::string name;
  std::string flag;
  std::function<void(SimConfig&, const std::string&)> set;
  std::string absent = "";
};

// What the output's /parameters needs beyond the scene: the particles and the box volume.
struct SceneSize {
  double n = 0, volume = 0;
};

// Where an effect declares its command-line options; gg-sim's CLI11 application stands behind it
// (cli_scene_options.hpp), so that the scene parts do not compile the CLI library.
class SceneOptions {
 public:
  virtual ~SceneOptions() = default;
  virtual void number(const std::string& flag, double& value, const std::string& help) = 0;
  virtual void number(const std::string& flag, std::optional<double>& value, const std::string& help) = 0;
  virtual void text(const std::string& flag, std::string& value, const std::string& help) = 0;
  virtual void flag(const std::string& flag, bool& value, const std::string& help) = 0;
  // A comma-separated list kept as its text: a scene file's "radii = 0.5,0.7" arrives as two items,
  // the command line's as one; both leave "0.5,0.7".
  virtual void list(const std::string& flag, std::string& value, const std::string& help) = 0;
};

// The box of a fresh start and where its particles go: the edges of the engine's box, and the box
// the positions are drawn in (its edges, and an offset added to every position drawn). Both are the
// cube of edge --L unless an effect shapes them.
struct StartShape {
  std::vector<double> edges;
  std::vector<double> region;
  std::vector<double> offset;
};

class SceneEffect {
 public:
  virtual ~SceneEffect() = default;
  virtual void add_options(SceneOptions& options, SimConfig& c) const = 0;
  // Checks the effect's options against the rest of the scene (gg::UsageError naming the flag and
  // the fix) and fills in its defaults; called by SimConfig::resolve().
  virtual void check(SimConfig& c) const = 0;
  // The flag of a law that gives every collision its restitution when the scene uses it (then
  // --e has no meaning), else empty.
  virtual std::string restitution_flag(const SimConfig&) const { return {}; }
  // Shapes the box of a fresh start (walls: a longer box, the particles between the walls).
  virtual void shape_start(const SimConfig&, StartShape&) const {}
  // Appends " key=value" for each of its keys when the scene uses the effect.
  virtual void fingerprint(const SimConfig& c, std::ostream& s) const = 0;
  virtual std::vector<SceneKey> keys() const = 0;
  virtual void write_parameters(gg::H5Output& out, const SimConfig& c, const SceneSize& size) const = 0;
};

// The effects with options of their own, in the order of the fingerprint.
const std::vector<const SceneEffect*>& scene_effects();

}  // namespace ggsim
