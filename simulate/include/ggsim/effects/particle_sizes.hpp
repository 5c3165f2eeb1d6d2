#pragma once
// A radius and a mass per particle (gg-sim --radii, --masses: a mixture or a polydisperse gas,
// mixture.hpp; and the aggregates of the ballistic aggregation model, aggregation.hpp): contact at
// R_i + R_j, impulses weighted by the masses. The engine reads them wherever a particle's size
// matters (its neighbour search, its cells, the kinetic energy), asking its effects whether they
// hold sizes (EffectSet::kSizes). Given sizes are state: a checkpoint keeps them in the engine's
// numbering with the radius cap, as aggregates have them when it is written (they grow), and a
// mixture's are those of its start; particles without given sizes have radius 1/2 and mass 1,
// which collide as the plain engine's particles do.
#include <algorithm>
#include <cstdint>
#include <vector>

#include "gg/errors.hpp"
#include "gg/trajectory.hpp"
#include "ggsim/effects/effect_state.hpp"
#include "ggsim/effects/registry_entry.hpp"
#include "ggsim/permutation.hpp"

namespace ggsim {

class ParticleSizes {
 public:
  static constexpr bool kSizes = true;

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
  }

  template <class Rank>
  void permute(const Rank& rank) {
    permute_by_rank(mass, rank);
    permute_by_rank(radius, rank);
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
  }

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
    return true;
  }

  bool given_;  // sizes given (a mixture, aggregates); else 1/2 and 1 throughout
};

// Its entry in the registry (effects/registry.hpp, registry_entry.hpp).
struct MixtureEffect {
  static constexpr std::string_view kName = "mixture";
  template <int D>
  using Unit = ParticleSizes;
  static const SceneEffect& scene();  // src/scene/mixture_scene.cpp
};

}  // namespace ggsim
