#pragma once
// Which engine a scene runs. Every effect is a bit of a variant's key (effects/effect_set.hpp); the engines compiled are a
// list (simulate/CMakeLists.txt, GG_ENGINE_VARIANTS), each in a translation unit of its own, and
// a scene runs the compiled variant with the fewest effects that holds every effect it uses
// (docs/DESIGN.md "Engine variants"). An effect present but unused is exact: a cutoff of 0 or a
// t_c of 0 never makes a collision elastic, a virial or an image count that is not written changes
// nothing, a drive of strength 0 never kicks, a tangential restitution of -1 (the default) is the
// smooth rule bit for bit, radii of 1/2 and masses of 1 collide as the plain engine's particles do,
// so a scene gets the same trajectory from any variant
// that holds its effects, only at a different speed. Only aggregation changes what a collision
// is, and only walls change how particles move (gravity), so each is present exactly when the
// scene asks for it.
#include <bit>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>

#include "ggsim/effects/effect_set.hpp"
#include "ggsim/config.hpp"
#include "ggsim/scene_effect.hpp"

namespace ggsim {

// The bits a variant must match exactly rather than hold.
inline constexpr unsigned kExactBits = kAggregateBit | kWallsBit | kShearBit;

// The effects a run uses: each scene part's (scene_effect.hpp), and sizes if its start gives
// particles sizes (`sized_start`: a mixture's output read as --init FILE, or its checkpoint).
inline unsigned wanted_effects(const SimConfig& cfg, bool sized_start = false) {
  unsigned bits = sized_start ? kMixtureBit : 0u;
  for (const SceneEffect* effect : scene_effects()) bits |= effect->bits(cfg);
  return bits;
}

// The position in `compiled` of the variant with the fewest effects (the first of equals) that
// holds every bit of `wanted` and matches its exact bits. Throws std::logic_error if none does:
// the list must hold a variant for every scene (the one with every effect but aggregation, and
// aggregation alone).
inline std::size_t choose_variant(unsigned wanted, std::span<const unsigned> compiled) {
  std::size_t best = compiled.size();
  for (std::size_t k = 0; k < compiled.size(); ++k) {
    const unsigned v = compiled[k];
    if ((v & wanted) != wanted || (v & kExactBits) != (wanted & kExactBits)) continue;
    if (best == compiled.size() || std::popcount(v) < std::popcount(compiled[best])) best = k;
  }
  if (best == compiled.size())
    throw std::logic_error("no compiled engine variant holds the effects " + std::to_string(wanted) +
                           " (simulate/CMakeLists.txt, GG_ENGINE_VARIANTS)");
  return best;
}

}  // namespace ggsim
