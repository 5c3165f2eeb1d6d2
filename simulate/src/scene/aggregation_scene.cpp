// The ballistic aggregation model's part of a scene: --aggregate (contact/aggregate.hpp; docs/DESIGN.md
// "Where an effect lives"). Not an effect but another kind of contact (contact/: the engine's
// Contact policy merges): its scene is asked as an effect's is.
#include "gg/h5file.hpp"
#include "ggsim/effects/effect_set.hpp"
#include "scene_effects.hpp"

namespace ggsim {

namespace {

class AggregationScene final : public SceneEffect {
 public:
  void add_options(SceneOptions& options, SimConfig& c) const override {
    options.flag("--aggregate", c.aggregate, "Ballistic aggregation model: touching particles merge at their centre "
                 "of mass, summing mass, momentum and volume (no --e)");
  }

  // (Each effect's scene part refuses what has no meaning for merging particles.)
  void check(SimConfig& c) const override {
    require(!(c.aggregate && c.continue_clock),
            "--continue has no meaning with --aggregate (touching particles merge); drop it");
  }

  std::string replaces_restitution(const SimConfig& c) const override {
    return c.aggregate ? "--aggregate (touching particles merge)" : "";
  }

  void fingerprint(const SimConfig& c, std::ostream& s) const override {
    if (c.aggregate) s << " aggregate=1";
  }

  std::vector<SceneKey> keys() const override {
    return {{"aggregate", "aggregate", [](SimConfig& c, const std::string& s) { c.aggregate = s == "1"; }, "0"}};
  }

  void write_parameters(gg::H5Output& out, const SimConfig& c, const SceneSize&) const override {
    if (c.aggregate) out.attr("/parameters", "aggregate", std::int64_t{1});
  }

  bool used(const SimConfig& c) const override { return c.aggregate; }
};

}  // namespace

const SceneEffect& AggregateEffect::scene() {
  static const AggregationScene scene;
  return scene;
}

}  // namespace ggsim
