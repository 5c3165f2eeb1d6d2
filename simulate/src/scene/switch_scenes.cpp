// The parts of a scene of two effects that are switched on by a flag alone: --pressure, the
// collisional virial (effects/pressure_virial.hpp), and --unwrapped, the periodic images of the
// snapshots (effects/image_counts.hpp).
#include "gg/trajectory.hpp"
#include "ggsim/effects/effect_set.hpp"
#include "scene_effects.hpp"

namespace ggsim {

namespace {

// P: the effect's parameters, whose `on` the flag sets.
template <class P>
class SwitchScene : public SceneEffect {
 public:
  // `written`: whether /parameters records it (as 1 or 0).
  SwitchScene(const char* key, const char* help, Written written) : key_(key), help_(help), written_(written) {}

  void add_options(SceneOptions& options, SimConfig& c) const override { options.flag(option(), c.effects.set<P>().on, help_); }

  std::string option() const override { return "--" + std::string(key_); }

  void check(SimConfig&) const override {}

  std::vector<SceneKey> keys() const override { return {scene_key(key_, &P::on, "0", written_)}; }

  bool used(const SimConfig& c) const override { return on(c); }

 protected:
  static bool on(const SimConfig& c) { return c.effects.get<P>().on; }

 private:
  const char* key_;
  const char* help_;
  Written written_;
};

class PressureScene final : public SwitchScene<PressureParameters> {
 public:
  PressureScene()
      : SwitchScene("pressure", "Record the pressure (kinetic + collisional virial)", Written::kAlways) {}

  SceneFootprint footprint(const SimConfig& c) const override { return {.sample_values = on(c) ? 1.0 : 0.0}; }
};

// The images are in the snapshots (/particles/all/image); /parameters has no key of its own.
class UnwrappedScene final : public SwitchScene<ImageParameters> {
 public:
  UnwrappedScene()
      : SwitchScene("unwrapped",
                    "Store with the snapshots how often each particle has crossed each periodic boundary (H5MD "
                    "image: position + image x edges is the unwrapped position; with --shear-rate a add image_y a L_y t along x)",
                    Written::kNever) {}

  void check(SimConfig& c) const override {
    c.require_snapshots_for(on(c), option(), "stores the images with the snapshots");
  }

  // A start from a file that has images goes on counting from them.
  void start_state(const SimConfig& c, const StartFile& file, std::size_t, Random&, EffectRecords& out) const override {
    if (!on(c) || !file.frame || file.frame->image.empty()) return;
    std::vector<std::int64_t>& image = out.integer["image"];
    for (double x : file.frame->image) image.push_back(static_cast<std::int64_t>(x));
  }

  // A 32-bit image per axis in the engine and in the start, and one per axis in each snapshot.
  SceneFootprint footprint(const SimConfig& c) const override {
    if (!on(c)) return {};
    return {.particle_bytes = 8.0 * c.dim, .frame_bytes = 8.0 * c.dim};
  }
};

}  // namespace

const SceneEffect& VirialEffect::scene() {
  static const PressureScene scene;
  return scene;
}

const SceneEffect& ImagesEffect::scene() {
  static const UnwrappedScene scene;
  return scene;
}

}  // namespace ggsim
