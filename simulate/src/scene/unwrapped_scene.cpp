// The image counts' part of a scene: --unwrapped (docs/DESIGN.md "Files"; the engine's side is
// effects/image_counts.hpp, the snapshots' image field the recorder's).
#include "scene_effects.hpp"

namespace ggsim {

namespace {

class UnwrappedScene final : public SceneEffect {
 public:
  void add_options(SceneOptions& options, SimConfig& c) const override {
    options.flag("--unwrapped", c.unwrapped, "Store with the snapshots how often each particle has crossed each "
                 "periodic boundary (H5MD image: position + image x edges is the unwrapped position)");
  }

  void check(SimConfig& c) const override {
    require(!(c.aggregate && c.unwrapped),
            "--unwrapped is not available with --aggregate (a merged particle has no single image); drop it");
  }

  void fingerprint(const SimConfig& c, std::ostream& s) const override {
    if (c.unwrapped) s << " unwrapped=1";
  }

  std::vector<SceneKey> keys() const override {
    return {{"unwrapped", "unwrapped", [](SimConfig& c, const std::string& s) { c.unwrapped = s == "1"; }, "0"}};
  }

  // The images are in the snapshots (/particles/all/image); /parameters has no key of its own.
  void write_parameters(gg::H5Output&, const SimConfig&, const SceneSize&) const override {}
};

}  // namespace

const SceneEffect& unwrapped_scene() {
  static const UnwrappedScene scene;
  return scene;
}

}  // namespace ggsim
