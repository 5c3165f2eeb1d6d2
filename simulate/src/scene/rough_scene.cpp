// Rough particles' part of a scene: --beta, --inertia, --T0-rot (docs/PHYSICS.md "Rough
// particles"; the engine's side is effects/rough_particles.hpp).
#include <cmath>

#include "gg/errors.hpp"
#include "gg/h5file.hpp"
#include "ggsim/effects/effect_set.hpp"
#include "scene_effects.hpp"

namespace ggsim {

namespace {

class RoughScene final : public SceneEffect {
 public:
  void add_options(SceneOptions& options, SimConfig& c) const override {
    RoughParameters& r = c.effects.set<RoughParameters>();
    options.number("--beta", r.beta, "Rough particles (--dim 2 or 3): tangential restitution, -1 <= beta <= 1 (-1: "
                   "smooth, 1: perfectly rough; Walton 1993, Huthmann & Zippelius 1997)");
    options.number("--inertia", r.inertia, "q of the moment of inertia I = q m sigma^2 / 4 of rough particles, 0 < q "
                   "<= 1 (default 1/2 in 2D, a uniform disk; 2/5 in 3D, a uniform sphere)");
    options.number("--T0-rot", r.T0_rot, "Rotational temperature of the start of rough particles (default 0: no "
                   "rotation)");
  }

  std::string option() const override { return "--beta"; }

  std::vector<Exclusion> exclusions() const override {
    return {{kBit<MixtureEffect>, "the rough collision rule is written for particles of one size and mass"}};
  }

  void check(SimConfig& c) const override {
    RoughParameters& r = c.effects.set<RoughParameters>();
    if (!r.beta) {
      require(!r.inertia && !r.T0_rot, "--inertia and --T0-rot belong to rough particles; give --beta or drop them");
      return;
    }
    require(c.dim > 1, "--beta needs rotation, which rods in 1D have not; give --dim 2 or 3, or drop --beta");
    require(std::isfinite(*r.beta) && *r.beta >= -1 && *r.beta <= 1, "--beta must lie in [-1, 1] (got " + str(*r.beta) + ")");
    if (!r.inertia) r.inertia = default_inertia(c.dim);
    require(std::isfinite(*r.inertia) && *r.inertia > 0 && *r.inertia <= 1,
            "--inertia must lie in (0, 1] (got " + str(*r.inertia) + "): q of I = q m sigma^2 / 4");
    require(!r.T0_rot || (std::isfinite(*r.T0_rot) && *r.T0_rot >= 0),
            "--T0-rot must be >= 0 (got " + str(r.T0_rot.value_or(0)) + ")");
  }

  // (beta is set whenever the keys are read: the scene uses rough particles.)
  std::vector<SceneKey> keys() const override {
    return {scene_key("beta", &RoughParameters::beta, zero),
            scene_key("inertia", &RoughParameters::inertia, [](const SimConfig& c) { return default_inertia(c.dim); }),
            scene_key("T0_rot", &RoughParameters::T0_rot, zero)};
  }

  bool used(const SimConfig& c) const override { return rough(c).beta.has_value(); }

  // The angular velocities at the start: a Maxwellian at --T0-rot (I <w_k^2> = T0_rot for each of
  // the rotational degrees of freedom, one in 2D, three in 3D), else those of the last frame of
  // --init FILE if it has them, else 0.
  void start_state(const SimConfig& c, const StartFile& file, std::size_t n, Random& rng,
                   EffectRecords& out) const override {
    const RoughParameters& r = rough(c);
    if (!r.beta) return;
    const std::size_t components = c.dim == 3 ? 3 : 1;
    std::vector<double>& spin = out.real["spin"];
    spin.assign(n * components, 0.0);
    if (r.T0_rot) {
      const double sd = std::sqrt(*r.T0_rot / moment_of_inertia(*r.inertia));
      for (double& w : spin) w = sd * rng.normal();
    } else if (file.in && file.in->exists(kSpinFrames)) {
      const auto shape = file.in->shape(kSpinFrames);
      if (shape.size() < 2 || shape[1] != n || (shape.size() > 2 ? shape[2] : 1) != components)
        throw gg::RuntimeError("--init " + c.init + ": " + kSpinFrames + " does not hold " + std::to_string(components) +
                               " angular velocity components for each of its " + std::to_string(n) + " particles");
      spin = file.in->read_rows(kSpinFrames, {shape[0] - 1}).data;
    }
  }

 private:
  static double zero(const SimConfig&) { return 0; }
  static constexpr const char* kSpinFrames = "/particles/all/angular_velocity/value";
  static const RoughParameters& rough(const SimConfig& c) { return c.effects.get<RoughParameters>(); }
};

}  // namespace

const SceneEffect& RoughEffect::scene() {
  static const RoughScene scene;
  return scene;
}

}  // namespace ggsim
