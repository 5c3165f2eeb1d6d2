#pragma once
// Which engine a scene runs. Every registered effect is a bit of a variant's key (effects/effect_set.hpp,
// kBit); the engines compiled are a list (simulate/CMakeLists.txt, GG_ENGINE_VARIANTS), each in a
// translation unit of its own, and
// a scene runs the compiled variant with the fewest effects that holds every effect it uses
// (docs/DESIGN.md "Engine variants"). An effect present but unused is exact: a cutoff of 0 or a
// t_c of 0 never makes a collision elastic, a virial or an image count that is not written changes
// nothing, a drive of strength 0 never kicks, a tangential restitution of -1 (the default) is the
// smooth rule bit for bit, radii of 1/2 and masses of 1 collide as the plain engine's particles do,
// so a scene gets the same trajectory from any variant
// that holds its effects, only at a different speed. Only aggregation changes what a contact does,
// only walls change how particles move (gravity) and only shear changes the box, so each is present
// exactly when the scene asks for it (kExactBits).
#include <bit>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>

#include "ggsim/effects/effect_set.hpp"
#include "ggsim/config.hpp"
#include "ggsim/scene_effect.hpp"

namespace ggsim {

template <class... E>
unsigned used_bits(const SimConfig& cfg, EffectList<E...>) {
  return (0u | ... | (E::scene().used(cfg) ? kBit<E> : 0u));
}

// The effects a run uses: each whose scene part says so (scene_effect.hpp), and sizes if its start gives
// particles sizes (`sized_start`: a mixture's output read as --init FILE, or its checkpoint).
inline unsigned wanted_effects(const SimConfig& cfg, bool sized_start = false) {
  return (sized_start ? kBit<MixtureEffect> : 0u) | used_bits(cfg, Registry{});
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
