// The two collapse cutoffs' parts of a scene: --delta, the velocity cutoff, and --tc, the TC model
// (docs/PHYSICS.md "Inelastic collapse"; the engine's sides are effects/velocity_cutoff.hpp and
// effects/tc_model.hpp). Each is one number >= 0 of the scene, 0 for none.
#include <cmath>

#include "gg/h5file.hpp"
#include "scene_effects.hpp"

namespace ggsim {

namespace {

class CutoffScene final : public SceneEffect {
 public:
  CutoffScene(const char* key, double SimConfig::*value, const char* help) : key_(key), value_(value), help_(help) {}

  void add_options(SceneOptions& options, SimConfig& c) const override { options.number(flag(), c.*value_, help_); }

  void check(SimConfig& c) const override {
    const double x = c.*value_;
    require(std::isfinite(x) && x >= 0, flag() + " must be >= 0 (got " + str(x) + ")");
    require(!(c.aggregate && x > 0), flag() + " has no meaning with --aggregate (touching particles merge); drop it");
  }

  void fingerprint(const SimConfig& c, std::ostream& s) const override {
    if (c.*value_ > 0) s << " " << key_ << "=" << c.*value_;
  }

  std::vector<SceneKey> keys() const override {
    const auto value = value_;
    return {{key_, key_, [value](SimConfig& c, const std::string& s) { c.*value = number(s); }, "0"}};
  }

  // Written for every run (0: none), as the study's scripts read it.
  void write_parameters(gg::H5Output& out, const SimConfig& c, const SceneSize&) const override {
    out.attr("/parameters", key_, c.*value_);
  }

 private:
  std::string flag() const { return "--" + std::string(key_); }
  const char* key_;
  double SimConfig::*value_;
  const char* help_;
};

}  // namespace

const SceneEffect& cutoff_scene() {
  static const CutoffScene scene("delta", &SimConfig::delta,
                                 "Velocity cutoff: collisions with |n.v_ij| < delta are elastic (default 0: off)");
  return scene;
}

const SceneEffect& tc_scene() {
  static const CutoffScene scene("tc", &SimConfig::tc,
                                 "TC model: elastic if a partner collided less than tc ago (default 0: off)");
  return scene;
}

}  // namespace ggsim
