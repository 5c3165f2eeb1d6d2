// The parts of a scene of two effects that are switched on by a flag alone: --pressure, the
// collisional virial (effects/pressure_virial.hpp), and --unwrapped, the periodic images of the
// snapshots (effects/image_counts.hpp). Neither has a meaning for merging particles.
#include "gg/h5file.hpp"
#include "scene_effects.hpp"

namespace ggsim {

namespace {

class SwitchScene final : public SceneEffect {
 public:
  // `why_not_aggregate`: why --aggregate refuses it; `in_parameters`: whether /parameters records it.
  SwitchScene(const char* key, bool SimConfig::*on, const char* help, const char* why_not_aggregate,
              bool in_parameters)
      : key_(key), on_(on), help_(help), why_not_aggregate_(why_not_aggregate), in_parameters_(in_parameters) {}

  void add_options(SceneOptions& options, SimConfig& c) const override { options.flag(flag(), c.*on_, help_); }

  void check(SimConfig& c) const override {
    require(!(c.aggregate && c.*on_), flag() + " " + why_not_aggregate_ + "; drop it");
  }

  void fingerprint(const SimConfig& c, std::ostream& s) const override {
    if (c.*on_) s << " " << key_ << "=1";
  }

  std::vector<SceneKey> keys() const override {
    const auto on = on_;
    return {{key_, key_, [on](SimConfig& c, const std::string& s) { c.*on = s == "1"; }, "0"}};
  }

  void write_parameters(gg::H5Output& out, const SimConfig& c, const SceneSize&) const override {
    if (in_parameters_) out.attr("/parameters", key_, static_cast<std::int64_t>(c.*on_));
  }

 private:
  std::string flag() const { return "--" + std::string(key_); }
  const char* key_;
  bool SimConfig::*on_;
  const char* help_;
  const char* why_not_aggregate_;
  bool in_parameters_;
};

}  // namespace

const SceneEffect& pressure_scene() {
  static const SwitchScene scene("pressure", &SimConfig::pressure, "Record the pressure (kinetic + collisional virial)",
                                 "has no meaning with --aggregate (touching particles merge)", true);
  return scene;
}

// The images are in the snapshots (/particles/all/image); /parameters has no key of its own.
const SceneEffect& unwrapped_scene() {
  static const SwitchScene scene("unwrapped", &SimConfig::unwrapped,
                                 "Store with the snapshots how often each particle has crossed each periodic boundary "
                                 "(H5MD image: position + image x edges is the unwrapped position)",
                                 "is not available with --aggregate (a merged particle has no single image)", false);
  return scene;
}

}  // namespace ggsim
