#pragma once
// The ballistic aggregation model (BAM; Carnevale, Pomeau & Young, PRL 64, 2913 (1990); the
// paper's eqs. 4-5): two particles that touch merge into one at their centre of mass, with the sum
// of their masses and momenta. The material density is fixed, so mass is volume (length in 1D,
// area in 2D): a start particle has mass 1 and radius 1/2, and an aggregate of mass m has radius
// m^(1/d) / 2, i.e. R^d = R_a^d + R_b^d (as Trizac & Hansen, PRL 74, 4114 (1995), in 2D;
// Frachebourg, PRL 82, 1502 (1999), in 1D, where lengths add).
// Aggregates is the model's contact policy (bounce.hpp): what the engine does when two touch.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "gg/box.hpp"
#include "gg/errors.hpp"
#include "ggsim/effects/effect_state.hpp"
#include "ggsim/effects/particle_sizes.hpp"
#include "ggsim/effects/registry_entry.hpp"
#include "ggsim/particles.hpp"
#include "ggsim/prediction.hpp"
#include "ggsim/stop_reason.hpp"

namespace ggsim {

// Radius of a particle made of two of radii ra, rb at one material density.
template <int D>
double merged_radius(double ra, double rb) {
  if constexpr (D == 1) return ra + rb;
  else if constexpr (D == 2) return std::sqrt(ra * ra + rb * rb);
  else return std::cbrt(ra * ra * ra + rb * rb * rb);
}

// Merges b (mass mb) into a (mass ma), both at the same time: a moves to their centre of mass,
// r_ab = r_a - r_b being their minimum-image separation, and takes their summed momentum.
template <int D>
void merge_into(Particle<D>& a, double ma, const Particle<D>& b, double mb, const Vec<D>& r_ab, const gg::Box<D>& box) {
  const double m = ma + mb, wb = mb / m;
  for (int k = 0; k < D; ++k) {
    a.r[k] = box.wrap_near(a.r[k] - wb * r_ab[k], k);
    a.v[k] = (ma * a.v[k] + mb * b.v[k]) / m;
  }
}

// The engine's part of the model (a contact policy, bounce.hpp): particles i and j touch and
// merge; merged particles leave the cells and the calendar, and the cells grow with the largest
// aggregate, through what the engine offers a contact policy (engine.hpp). The masses and radii are
// those of the effect that declares hook::sizes (AggregateSizes below), which the policy asks through
// the engine's effects, 0 for a particle merged away until the engine drops it (Engine::rebuild()).
template <int D, class E>
class Aggregates {
 public:
  static constexpr bool kMerges = true;
  // Every start particle of mass 1 and radius sigma/2 (AggregateSizes' start), merged into none.
  void start(const E& eng) {
    static_assert(!E::Effects::kTimed, "aggregates acted on between collisions are not a model gg-sim has");
    n_start_ = alive_ = eng.slots();
    joined_.resize(n_start_);
    for (std::uint32_t k = 0; k < joined_.size(); ++k) joined_[k] = k;
  }
  // A checkpoint's aggregates: which start particle each start particle merged into (their count
  // is the number of the start), the particles left being those with a mass.
  void save(const EffectSink& out) const {
    out.integer(kJoinedRecord, std::vector<std::int64_t>(joined_.begin(), joined_.end()));
  }
  void restore(const E& eng, EffectRecords& saved) {
    const std::vector<std::int64_t> joined = saved.take_all_integer(kJoinedRecord);
    if (joined.size() < eng.slots())
      throw gg::RuntimeError("the checkpoint of an aggregating run has no valid '" + std::string(kJoinedRecord) +
                             "'; it is damaged");
    n_start_ = joined.size();
    joined_.resize(n_start_);
    for (std::size_t k = 0; k < n_start_; ++k) {
      if (joined[k] < 0 || static_cast<std::size_t>(joined[k]) >= n_start_)
        throw gg::RuntimeError("the checkpoint of an aggregating run names a particle out of range; it is damaged");
      joined_[k] = static_cast<std::uint32_t>(joined[k]);
    }
    alive_ = 0;
    for (std::uint32_t k = 0; k < eng.slots(); ++k) alive_ += eng.effects().mass(k) > 0;
  }

  // The particles of the start (an aggregating run keeps their rows in its outputs) and those left.
  std::size_t start_count(const E&) const { return n_start_; }
  std::size_t start_count() const { return n_start_; }
  std::size_t alive() const { return alive_; }
  // The number in the start of the particle left that start particle `label` is part of.
  std::uint32_t aggregate_of(std::uint32_t label) const {
    while (joined_[label] != label) label = joined_[label] = joined_[joined_[label]];  // path halving
    return label;
  }
  // Its observables at a sample time: N(t), the particles left, and the mean mass N0 / N(t) (at.n
  // is N0, the particles of the start; docs/DESIGN.md "Aggregates").
  void observables(const ObservableSink& out, const Sample& at) const {
    const auto left = static_cast<double>(alive_);
    out("number_of_particles", "", left);
    out("mean_mass", "m", at.n / left);
  }

  // Why merging stopped the run: one particle left, or one too large for the box.
  StopReason stop_reason() const { return stop_; }
  // Whether particle i is still there (one merged away has mass 0 until the engine drops it).
  template <class Effects>
  static bool present(const Effects& fx, std::uint32_t i) {
    return fx.mass(i) > 0;
  }

  // Before the engine renumbers its particles: those merged away are in no cell, so they go first.
  void before_renumbering(E& eng) {
    if (alive_ < eng.slots()) {
      eng.rebuild(nullptr);
      eng.predict_all();
    }
  }

  // Particles i and j (both at now) touch: they merge into i, and i then takes in every particle it
  // overlaps, until it overlaps none (cascade merging, as Trizac & Hansen do). Grows the cells first
  // whenever i outgrows them (grow()), so that the overlap search and every prediction stay exact.
  // False (stop_reason() says why) if one particle is left or i has outgrown the box.
  bool meet(E& eng, std::uint32_t i, std::uint32_t j) {
    bool regridded = false;
    for (;;) {
      absorb(eng, i, j);
      if (alive_ == 1) return stop(StopReason::kOneLeft);
      if (eng.effects().radius(i) > eng.effects().radius_cap()) {
        if (!grow(eng, &i)) return stop(StopReason::kOutgrewBox);
        regridded = true;
      }
      j = overlapping(eng, i);
      if (j == PendingEvent::kNone) break;
      eng.bring_to_now(j);
    }
    if (regridded || 2 * alive_ < eng.slots()) {
      if (!regridded) grow(eng, &i);
      eng.centre_shell_on(i);  // i has moved since the cells were built if it merged again
      eng.predict_all();
      return true;
    }
    eng.predict_anew(i);
    return true;
  }

 private:
  static constexpr const char* kJoinedRecord = "aggregate_of";
  // The cells are built for this many times the largest radius: they grow geometrically, so a run
  // rebuilds them a few dozen times.
  static constexpr double kRadiusHeadroom = 1.25;

  bool stop(StopReason why) {
    stop_ = why;
    return false;
  }

  // b merges into a: a at the centre of mass with the summed momentum, mass and volume; b leaves
  // the grid and the calendar, and both counters move on, so that every event predicted with
  // either is stale.
  void absorb(E& eng, std::uint32_t a, std::uint32_t b) {
    auto& fx = eng.effects();
    Particle<D>&pa = eng.particle(a), &pb = eng.particle(b);
    merge_into<D>(pa, fx.mass(a), pb, fx.mass(b), eng.box().separation(pa.r, pb.r), eng.box());
    fx.set_size(a, fx.mass(a) + fx.mass(b), merged_radius<D>(fx.radius(a), fx.radius(b)));
    fx.set_size(b, 0, 0);
    eng.changed_course(a);
    eng.count_collision();
    joined_[eng.label(b)] = eng.label(a);
    eng.remove(b);
    --alive_;
  }

  // A particle that i (at now, radius within the cap) overlaps, or kNone. Its centre is within
  // R_i + R_j + a shell radius of i, at most a cell width: the cells around i hold it.
  static std::uint32_t overlapping(const E& eng, std::uint32_t i) {
    std::uint32_t found = PendingEvent::kNone;
    eng.for_each_near(i, [&](std::uint32_t j, const Vec<D>& d) {
      if (found == PendingEvent::kNone && dot<D>(d, d) < eng.contact2(i, j)) found = j;
    });
    return found;
  }

  // Rebuilds the engine's cells for a radius cap of kRadiusHeadroom times the largest radius (or
  // the largest radius itself if that leaves no room); *keep follows its particle. False if even
  // that leaves the box no room for a shell.
  static bool grow(E& eng, std::uint32_t* keep) {
    auto& fx = eng.effects();
    double r_max = 0;
    for (std::uint32_t k = 0; k < eng.slots(); ++k) r_max = std::max(r_max, fx.radius(k));
    double cap = std::max(fx.radius_cap(), kRadiusHeadroom * r_max);
    if (!eng.fits(cap)) cap = r_max;
    if (!eng.fits(cap)) return false;
    fx.set_radius_cap(cap);
    eng.rebuild(keep);
    return true;
  }

  // The start particle each start particle merged into (itself if none), the particles of the
  // start and those left, and why merging stopped the run.
  mutable std::vector<std::uint32_t> joined_;
  std::size_t n_start_ = 0, alive_ = 0;
  StopReason stop_ = StopReason::kCollapse;
};

// Aggregates' sizes: a start particle's 1/2 and 1, written with every snapshot and checkpoint since
// they grow (a mixture's are written only when given).
class AggregateSizes : public ParticleSizes {
 public:
  template <class Parameters>
  AggregateSizes(const Parameters&, const EffectStart& s) : ParticleSizes(s, true) {}
};

// Its entry in the registry (effects/registry.hpp, registry_entry.hpp).
struct AggregateEffect {
  static constexpr std::string_view kName = "aggregate";
  template <int D>
  using Unit = AggregateSizes;
  // Touching particles merge instead of colliding.
  template <int D, class Engine>
  using Contact = Aggregates<D, Engine>;
  static const SceneEffect& scene();  // src/scene/aggregation_scene.cpp
};

}  // namespace ggsim
