#pragma once
// A radius and a mass per particle (gg-sim --radii, --masses: a mixture or a polydisperse gas,
// mixture.hpp; and the aggregates of the ballistic aggregation model, contact/aggregate.hpp): contact at
// R_i + R_j, impulses weighted by the masses. The engine reads them wherever a particle's size
// matters (its neighbour search, its cells, the kinetic energy), asking its effects whether they
// hold sizes (hook::sizes, EffectSet::kSizes). Given sizes are state: a checkpoint keeps them in the engine's
// numbering with the radius cap, as aggregates have them when it is written (they grow), and a
// mixture's are those of its start; particles without given sizes have radius 1/2 and mass 1,
// which collide as the plain engine's particles do. A mixture's particles have a species each too,
// whose temperatures are its observable (docs/PHYSICS.md "Mixtures"), and whose species and radii
// are fixed values of the output.
#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "gg/errors.hpp"
#include "gg/trajectory.hpp"
#include "ggsim/effects/effect_state.hpp"
#include "ggsim/effects/hooks.hpp"
#include "ggsim/effects/registry_entry.hpp"
#include "ggsim/permutation.hpp"

namespace ggsim {

class ParticleSizes {
 public:
  static constexpr Hooks kHooks =
      hook::sizes | hook::permute | hook::observables | hook::fixed_values | hook::frame_values | hook::save;

  template <class Parameters>
  ParticleSizes(const Parameters& par, const EffectStart& s)
      : radius(s.n, 0.5), mass(s.n, 1.0), given_(!par.radius.empty()) {
    if (s.records && restore(*s.records, s.n)) return;
    if (!given_) return;
    for (std::uint32_t i = 0; i < s.n; ++i) {
      radius[i] = par.radius.at(s.start_number(i));
      mass[i] = par.mass.at(s.start_number(i));
    }
    cap = *std::max_element(par.radius.begin(), par.radius.end());
    if (par.species.empty()) return;
    species_.resize(s.n);
    for (std::uint32_t i = 0; i < s.n; ++i) species_[i] = par.species.at(s.start_number(i));
    count_species(par.species_count);
  }

  template <class Rank>
  void permute(const Rank& rank) {
    permute_by_rank(mass, rank);
    permute_by_rank(radius, rank);
    if (!species_.empty()) permute_by_rank(species_, rank);
  }

  // A mixture's temperature of each species, T_s = sum over its particles of m v^2 / (d N_s).
  void observables(const ObservableSink& out, const Sample& at) const {
    if (species_.empty()) return;
    const std::vector<double> v2 = at.squared_speeds();
    std::vector<double> sum(particles_of_.size(), 0.0);
    for (std::size_t i = 0; i < v2.size(); ++i) sum[species_[i]] += mass[i] * v2[i];
    for (std::size_t k = 0; k < sum.size(); ++k) sum[k] = particles_of_[k] > 0 ? sum[k] / (at.dim * particles_of_[k]) : 0.0;
    out("temperature_species", gg::kUnitEnergy, sum);
  }

  // A mixture's species and radii, fixed in time.
  void fixed_values(const FrameSink& out) const {
    if (species_.empty()) return;
    out("species", std::vector<double>(species_.begin(), species_.end()));
    out("radius", radius);
  }

  // Given sizes go with every snapshot: a mixture's, the same in each, and aggregates', which grow
  // (0 for a start particle merged into another).
  std::vector<FrameField> frame_fields() const {
    if (!given_) return {};
    return {{.name = "mass", .unit = "m"}, {.name = "radius", .unit = gg::kUnitLength}};
  }
  void frame_values(const FrameSink& out) const {
    if (!given_) return;
    out("mass", mass);
    out("radius", radius);
  }

  static constexpr const char* kCapRecord = "radius_cap";
  void save(const EffectSink& out) const {
    if (!given_) return;
    out.real("mass", mass);
    out.real("radius", radius);
    out.real(kCapRecord, {cap});
    if (species_.empty()) return;
    out.integer("species", std::vector<std::int64_t>(species_.begin(), species_.end()));
    out.integer(kSpeciesCountRecord, {static_cast<std::int64_t>(particles_of_.size())});
  }
  static constexpr const char* kSpeciesCountRecord = "species_count";

  // Aggregates: 0 for a particle merged away, until the engine drops it.
  std::vector<double> radius, mass;
  double cap = 0.5;  // no radius exceeds it (the engine's cells are twice that plus a skin wide)

 private:
  // The sizes a checkpoint saved, if it saved any.
  bool restore(EffectRecords& saved, std::size_t n) {
    std::vector<double> m = saved.take_real("mass", n), r = saved.take_real("radius", n), c = saved.take_real(kCapRecord, 1);
    if (m.empty() && r.empty() && c.empty()) return false;
    if (m.empty() || r.empty() || c.empty())
      throw gg::RuntimeError("the checkpoint holds only part of the particles' sizes (mass, radius, radius_cap); it is damaged");
    mass = std::move(m), radius = std::move(r), cap = c[0];
    given_ = true;
    const std::vector<std::int64_t> k = saved.take_integer("species", n), count = saved.take_all_integer(kSpeciesCountRecord);
    if (k.empty() != count.empty() || count.size() > 1)
      throw gg::RuntimeError("the checkpoint holds only part of a mixture's species (species, species_count); it is damaged");
    if (k.empty()) return true;
    species_.assign(k.begin(), k.end());
    count_species(static_cast<std::uint32_t>(count[0]));
    return true;
  }

  // The particles of each of `count` species (as doubles, the divisor of the temperatures).
  void count_species(std::uint32_t count) {
    particles_of_.assign(count, 0.0);
    for (std::uint32_t k : species_) {
      if (k >= count) throw gg::RuntimeError("a particle's species is beyond the mixture's " + std::to_string(count));
      particles_of_[k] += 1;
    }
  }

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
