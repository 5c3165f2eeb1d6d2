#pragma once
// What a touching pair does: the engine's contact policy (EngineVariant::Contact, effects/effect_set.hpp).
//   Bounce            the pair collides by the collision rule (collision_rule.hpp) and both fly on:
//                     every scene but aggregation; the engine's own code, this policy adds none;
//   Aggregates<D, E>  the pair merges into one particle (aggregate.hpp, the ballistic aggregation
//                     model), which then takes in every particle it overlaps.
// A policy with kMerges is a friend of the engine: a merge removes particles from the cells and the
// calendar, and may rebuild both (docs/DESIGN.md "Engine variants").

namespace ggsim {

struct Bounce {
  static constexpr bool kMerges = false;
};

}  // namespace ggsim
