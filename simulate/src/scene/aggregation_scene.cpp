// The ballistic aggregation model's part of a scene: --aggregate (contact/aggregate.hpp; docs/DESIGN.md
// "Where an effect lives"). Not an effect but another kind of contact (contact/: the engine's
// Contact policy merges): its scene is asked as an effect's is.
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

  std::string option() const override { return "--aggregate"; }

  // Merging replaces the collision that every other effect adds to or reads.
  std::vector<Exclusion> exclusions() const override {
    return {{kBit<ImagesEffect>, "a merged particle has no single image"},
            {kBit<MixtureEffect>, "aggregates have the sizes their merging gives them"},
            {kEveryOtherEffect, "aggregation merges at contact"}};
  }

  void check(SimConfig& c) const override {
    require(!(c.aggregate && c.continue_clock),
            "--continue has no meaning with --aggregate (touching particles merge); drop it");
  }

  std::string replaces_restitution(const SimConfig& c) const override {
    return c.aggregate ? "--aggregate (touching particles merge)" : "";
  }

  std::vector<SceneKey> keys() const override { return {scene_key("aggregate", &SimConfig::aggregate, "0")}; }

  bool used(const SimConfig& c) const override { return c.aggregate; }
};

}  // namespace

const SceneEffect& AggregateEffect::scene() {
  static const AggregationScene scene;
  return scene;
}

}  // namespace ggsim
