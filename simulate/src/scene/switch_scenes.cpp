// The parts of a scene of two effects that are switched on by a flag alone: --pressure, the
// collisional virial (effects/pressure_virial.hpp), and --unwrapped, the periodic images of the
// snapshots (effects/image_counts.hpp). Neither has a meaning for merging particles.
#include "gg/h5file.hpp"
#include "gg/trajectory.hpp"
#include "ggsim/effects/effect_set.hpp"
#include "scene_effects.hpp"

namespace ggsim {

namespace {

// P: the effect's parameters, whose `on` the flag sets.
template <class P>
class SwitchScene : public SceneEffect {
 public:
  // `why_not_aggregate`: why --aggregate refuses it; `in_parameters`: whether /parameters records it.
  SwitchScene(const char* key, const char* help, const char* why_not_aggregate, bool in_parameters)
      : key_(key), help_(help), why_not_aggregate_(why_not_aggregate), in_parameters_(in_parameters) {}

  void add_options(SceneOptions& options, SimConfig& c) const override { options.flag(flag(), c.effects.set<P>().on, help_); }

  void check(SimConfig& c) const override {
    require(!(c.aggregate && on(c)), flag() + " " + why_not_aggregate_ + "; drop it");
  }

  void fingerprint(const SimConfig& c, std::ostream& s) const override {
    if (on(c)) s << " " << key_ << "=1";
  }

  std::vector<SceneKey> keys() const override {
    return {{key_, key_, [](SimConfig& c, const std::string& s) { c.effects.set<P>().on = s == "1"; }, "0"}};
  }

  void write_parameters(gg::H5Output& out, const SimConfig& c, const SceneSize&) const override {
    if (in_parameters_) out.attr("/parameters", key_, static_cast<std::int64_t>(on(c)));
  }

  bool used(const SimConfig& c) const override { return on(c); }

 protected:
  static bool on(const SimConfig& c) { return c.effects.get<P>().on; }

 private:
  std::string flag() const { return "--" + std::string(key_); }
  const char* key_;
  const char* help_;
  const char* why_not_aggregate_;
  bool in_parameters_;
};

class PressureScene final : public SwitchScene<PressureParameters> {
 public:
  PressureScene()
      : SwitchScene("pressure", "Record the pressure (kinetic + collisional virial)",
                    "has no meaning with --aggregate (touching particles merge)", true) {}

  SceneFootprint footprint(const SimConfig& c) const override { return {.sample_values = on(c) ? 1.0 : 0.0}; }
};

// The images are in the snapshots (/particles/all/image); /parameters has no key of its own.
class UnwrappedScene final : public SwitchScene<ImageParameters> {
 public:
  UnwrappedScene()
      : SwitchScene("unwrapped",
                    "Store with the snapshots how often each particle has crossed each periodic boundary (H5MD "
                    "image: position + image x edges is the unwrapped position; with --shear-rate a add image_y a L_y t along x)",
                    "is not available with --aggregate (a merged particle has no single image)", false) {}

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
