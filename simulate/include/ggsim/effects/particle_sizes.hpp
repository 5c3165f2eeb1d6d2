#pragma once
// A radius and a mass per particle (gg-sim --radii, --masses: a mixture or a polydisperse gas,
// mixture.hpp; and the aggregates of the ballistic aggregation model, contact/aggregate.hpp): contact at
// R_i + R_j, impulses weighted by the masses. The unit declares hook::sizes, and the engine asks its
// effects (EffectSet::mass(), radius(), contact2(), diameter_cap()) wherever a particle's size
// matters: its neighbour search, its cells, the kinetic energy; without a unit that declares it every
// particle has radius 1/2 and mass 1, constants the compiler folds into the plain engine's code.
// Given sizes are state: they reach the unit as its arrays (effect_state.hpp), from the start
// (add_start(): a mixture's, by particle number) or from a checkpoint (in the engine's
// numbering, with the radius cap, as aggregates have them when it is written: they grow). A mixture's
// particles have a species each too, whose temperatures are its observable (docs/PHYSICS.md
// "Mixtures"), and whose species and radii are fixed values of the output.
#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "gg/errors.hpp"
#include "gg/trajectory.hpp"
#include "ggsim/effects/effect_state.hpp"
#include "ggsim/effects/hooks.hpp"
#include "ggsim/effects/registry_entry.hpp"
#include "ggsim/mixture.hpp"
#include "ggsim/permutation.hpp"

namespace ggsim {

class ParticleSizes {
 public:
  static constexpr Hooks kHooks = hook::sizes | hook::compact | hook::permute | hook::observables |
                                  hook::fixed_values | hook::frame_values | hook::save;

  // The sizes its arrays give (none: radius 1/2 and mass 1 each, and none written).
  template <class Parameters>
  ParticleSizes(const Parameters&, const EffectStart& s) : ParticleSizes(s, false) {}

  double mass(std::uint32_t i) const { return mass_[i]; }
  double radius(std::uint32_t i) const { return radius_[i]; }
  // No radius exceeds it (the engine's cells are twice that plus a skin wide).
  double radius_cap() const { return cap_; }
  // A merge changes sizes (0 and 0: a particle merged away, until the engine drops it) and may
  // raise the cap.
  void set_size(std::uint32_t i, double m, double r) { mass_[i] = m, radius_[i] = r; }
  void set_radius_cap(double cap) { cap_ = cap; }

  template <class Rank>
  void permute(const Rank& rank) {
    permute_by_rank(mass_, rank);
    permute_by_rank(radius_, rank);
    if (!species_.empty()) permute_by_rank(species_, rank);
  }
  // The particles `kept` (their numbers, ascending) are numbered 0, 1, ... and the others dropped.
  void compact(const std::vector<std::uint32_t>& kept) {
    keep(mass_, kept);
    keep(radius_, kept);
    if (!species_.empty()) keep(species_, kept);
  }

  // A mixture's temperature of each species, T_s = sum over its particles of m v^2 / (d N_s).
  void observables(const ObservableSink& out, const Sample& at) const {
    if (species_.empty()) return;
    const std::vector<double> v2 = at.squared_speeds();
    std::vector<double> sum(particles_of_.size(), 0.0);
    for (std::size_t i = 0; i < v2.size(); ++i) sum[species_[i]] += mass_[i] * v2[i];
    for (std::size_t k = 0; k < sum.size(); ++k) sum[k] = particles_of_[k] > 0 ? sum[k] / (at.dim * particles_of_[k]) : 0.0;
    out("temperature_species", gg::kUnitEnergy, sum);
  }

  // A mixture's species and radii, fixed in time.
  void fixed_values(const FrameSink& out) const {
    if (species_.empty()) return;
    out("species", std::vector<double>(species_.begin(), species_.end()));
    out("radius", radius_);
  }

  // Given sizes go with every snapshot: a mixture's, the same in each, and aggregates', which grow
  // (0 for a start particle merged into another).
  std::vector<FrameField> frame_fields() const {
    if (!given_) return {};
    return {{.name = "mass", .unit = "m"}, {.name = "radius", .unit = gg::kUnitLength}};
  }
  void frame_values(const FrameSink& out) const {
    if (!given_) return;
    out("mass", mass_);
    out("radius", radius_);
  }

  // Its arrays, which its constructor takes back.
  void save(const EffectSink& out) const {
    if (!given_) return;
    out.real(kMassRecord, mass_);
    out.real(kRadiusRecord, radius_);
    out.real(kCapRecord, {cap_});
    if (species_.empty()) return;
    out.integer(kSpeciesRecord, std::vector<std::int64_t>(species_.begin(), species_.end()));
    out.integer(kSpeciesCountRecord, {static_cast<std::int64_t>(particles_of_.size())});
  }

  // The sizes of a start's particles by their number (a mixture's, mixture.hpp) as the arrays the
  // unit starts from, added to the start's other effects' (none for empty sizes).
  static void add_start(Sizes sizes, EffectRecords& start) {
    if (sizes.empty()) return;
    start.real[kCapRecord] = {*std::max_element(sizes.radius.begin(), sizes.radius.end())};
    start.real[kMassRecord] = std::move(sizes.mass);
    start.real[kRadiusRecord] = std::move(sizes.radius);
    if (sizes.species.empty()) return;
    start.integer[kSpeciesRecord].assign(sizes.species.begin(), sizes.species.end());
    start.integer[kSpeciesCountRecord] = {sizes.species_count};
  }

 protected:
  // `always_given`: sizes that are written even when the arrays give none (aggregates', which
  // start at 1/2 and 1 and grow).
  ParticleSizes(const EffectStart& s, bool always_given) : mass_(s.n, 1.0), radius_(s.n, 0.5), given_(always_given) {
    if (s.records) take(*s.records, s.n);
  }

 private:
  static constexpr const char* kMassRecord = "mass";
  static constexpr const char* kRadiusRecord = "radius";
  static constexpr const char* kCapRecord = "radius_cap";
  static constexpr const char* kSpeciesRecord = "species";
  static constexpr const char* kSpeciesCountRecord = "species_count";

  // The sizes the arrays give, if they give any.
  void take(EffectRecords& saved, std::size_t n) {
    std::vector<double> m = saved.take_real(kMassRecord, n), r = saved.take_real(kRadiusRecord, n),
                        c = saved.take_real(kCapRecord, 1);
    if (m.empty() && r.empty() && c.empty()) return;
    if (m.empty() || r.empty() || c.empty())
      throw gg::RuntimeError("the checkpoint holds only part of the particles' sizes (mass, radius, radius_cap); it is damaged");
    mass_ = std::move(m), radius_ = std::move(r), cap_ = c[0];
    given_ = true;
    const std::vector<std::int64_t> k = saved.take_integer(kSpeciesRecord, n), count = saved.take_all_integer(kSpeciesCountRecord);
    if (k.empty() != count.empty() || count.size() > 1)
      throw gg::RuntimeError("the checkpoint holds only part of a mixture's species (species, species_count); it is damaged");
    if (k.empty()) return;
    species_.assign(k.begin(), k.end());
    count_species(static_cast<std::uint32_t>(count[0]));
  }

  // The particles of each of `count` species (as doubles, the divisor of the temperatures).
  void count_species(std::uint32_t count) {
    particles_of_.assign(count, 0.0);
    for (std::uint32_t k : species_) {
      if (k >= count) throw gg::RuntimeError("a particle's species is beyond the mixture's " + std::to_string(count));
      particles_of_[k] += 1;
    }
  }

  template <class T>
  static void keep(std::vector<T>& a, const std::vector<std::uint32_t>& kept) {
    for (std::size_t n = 0; n < kept.size(); ++n) a[n] = a[kept[n]];
    a.resize(kept.size());
  }

  // Aggregates: 0 for a particle merged away, until the engine drops it.
  std::vector<double> mass_, radius_;
  double cap_ = 0.5;
  bool given_;  // sizes given (a mixture, aggregates); else 1/2 and 1 throughout
  std::vector<std::uint32_t> species_;  // a mixture's (empty: none)
  std::vector<double> particles_of_;    // particles of each species
};

// Its entry in the registry (effects/registry.hpp, registry_entry.hpp).
struct MixtureEffect {
  static constexpr std::string_view kName = "mixture";
  template <int D>
  using Unit = ParticleSizes;
  static const SceneEffect& scene();  // src/scene/mixture_scene.cpp
};

}  // namespace ggsim
