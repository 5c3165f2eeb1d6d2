#pragma once
// The TC model (gg-sim --tc; Luding & McNamara, Granular Matter 1, 113 (1998)): a collision is
// elastic if either partner collided less than t_c before. Each particle keeps the time of its
// last collision, which a checkpoint saves as "last_collision".
#include <cstdint>
#include <limits>
#include <vector>

#include "ggsim/effects/effect_parameters.hpp"
#include "ggsim/effects/effect_state.hpp"
#include "ggsim/effects/hooks.hpp"
#include "ggsim/effects/registry_entry.hpp"
#include "ggsim/permutation.hpp"

namespace ggsim {

// What a scene asks of the TC model (src/scene/collapse_cutoff_scenes.cpp): t_c, 0 for none.
struct TcParameters {
  double tc = 0;
};

class TcModel {
 public:
  static constexpr Hooks kHooks = hook::restitution | hook::prefetch | hook::permute | hook::save;

  template <class Parameters>
  TcModel(const Parameters& par, const EffectStart& s) : tc_(effect_parameters<TcParameters>(par).tc) {
    last_ = s.records ? s.records->take_real("last_collision", s.n) : std::vector<double>();
    if (last_.empty()) last_.assign(s.n, -std::numeric_limits<double>::infinity());  // never collided
  }

  // Elastic if a partner collided less than t_c before t; both remember t, elastic or not.
  void restitution(double& e, double, std::uint32_t ia, std::uint32_t ib, double t) {
    if (t - last_[ia] < tc_ || t - last_[ib] < tc_) e = 1;
    last_[ia] = last_[ib] = t;
  }
  // An array read at random places: the engine's look-ahead asks for it early.
  void prefetch(std::uint32_t i) const { __builtin_prefetch(&last_[i]); }
  template <class Rank>
  void permute(const Rank& rank) { permute_by_rank(last_, rank); }
  void save(const EffectSink& out) const { out.real("last_collision", last_); }

  std::vector<double>& last_collision() { return last_; }

 private:
  double tc_;
  std::vector<double> last_;
};

// Its entry in the registry (effects/registry.hpp, registry_entry.hpp).
struct TcEffect {
  static constexpr std::string_view kName = "tc";
  template <int D>
  using Unit = TcModel;
  static const SceneEffect& scene();  // src/scene/collapse_cutoff_scenes.cpp
};

}  // namespace ggsim
