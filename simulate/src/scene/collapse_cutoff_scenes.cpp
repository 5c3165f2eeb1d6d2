// The two collapse cutoffs' parts of a scene: --delta, the velocity cutoff, and --tc, the TC model
// (docs/PHYSICS.md "Inelastic collapse"; the engine's sides are effects/velocity_cutoff.hpp and
// effects/tc_model.hpp). Each is one number >= 0 of the scene, 0 for none.
#include <cmath>

#include "gg/h5file.hpp"
#include "ggsim/effects/effect_set.hpp"
#include "scene_effects.hpp"

namespace ggsim {

namespace {

// P: the effect's parameters, whose number `value` the option sets; `particle_bytes`: what the effect keeps per particle.
template <class P>
class CutoffScene final : public SceneEffect {
 public:
  CutoffScene(const char* key, double P::*value, double particle_bytes, const char* help)
      : key_(key), value_(value), particle_bytes_(particle_bytes), help_(help) {}

  void add_options(SceneOptions& options, SimConfig& c) const override {
    options.number(flag(), c.effects.set<P>().*value_, help_);
  }

  void check(SimConfig& c) const override {
    const double x = value(c);
    require(std::isfinite(x) && x >= 0, flag() + " must be >= 0 (got " + str(x) + ")");
    require(!(c.aggregate && x > 0), flag() + " has no meaning with --aggregate (touching particles merge); drop it");
  }

  std::string collapse_cutoff() const override { return flag() + " 1e-4"; }

  void fingerprint(const SimConfig& c, std::ostream& s) const override {
    if (value(c) > 0) s << " " << key_ << "=" << value(c);
  }

  std::vector<SceneKey> keys() const override {
    const auto value = value_;
    return {{key_, key_, [value](SimConfig& c, const std::string& s) { c.effects.set<P>().*value = number(s); }, "0"}};
  }

  // Written for every run (0: none), as the study's scripts read it.
  void write_parameters(gg::H5Output& out, const SimConfig& c, const SceneSize&) const override {
    out.attr("/parameters", key_, value(c));
  }

  bool used(const SimConfig& c) const override { return value(c) > 0; }

  SceneFootprint footprint(const SimConfig& c) const override {
    return {.particle_bytes = value(c) > 0 ? particle_bytes_ : 0.0};
  }

 private:
  double value(const SimConfig& c) const { return c.effects.get<P>().*value_; }
  std::string flag() const { return "--" + std::string(key_); }
  const char* key_;
  double P::*value_;
  double particle_bytes_;
  const char* help_;
};

}  // namespace

const SceneEffect& CutoffEffect::scene() {
  static const CutoffScene<CutoffParameters> scene("delta", &CutoffParameters::delta, 0,
                                 "Velocity cutoff: collisions with |n.v_ij| < delta are elastic (default 0: off)");
  return scene;
}

const SceneEffect& TcEffect::scene() {
  static const CutoffScene<TcParameters> scene("tc", &TcParameters::tc,
                                                  8,  // each particle's last collision time
                                 "TC model: elastic if a partner collided less than tc ago (default 0: off)");
  return scene;
}

}  // namespace ggsim
