#pragma once
// What a touching pair does: the engine's contact policy (EngineVariant::Contact, effects/effect_set.hpp).
//   Bounce            the pair collides by the collision rule (collision_rule.hpp) and both fly on:
//                     every scene but aggregation; its answers below are empty or the engine's own;
//   Aggregates<D, E>  the pair merges into one particle (aggregate.hpp, the ballistic aggregation
//                     model), which then takes in every particle it overlaps.
// The engine asks its policy at its start, its checkpoint (save, restore), each contact (meet), each
// renumbering, for whether a particle is still there and for why a run stopped; a policy acts on the
// engine only through what the engine offers a contact policy (engine.hpp: a merge removes
// particles from the cells and the calendar, and may rebuild both; docs/DESIGN.md "Engine variants").
#include <cstddef>
#include <cstdint>

#include "ggsim/hot_path.hpp"
#include "ggsim/stop_reason.hpp"

namespace ggsim {

struct Bounce {
  static constexpr bool kMerges = false;  // for the outputs (a merging run keeps every start particle's row)
  template <class Engine>
  static void start(const Engine&) {}
  template <class Engine, class Records>
  static void restore(const Engine&, Records&) {}
  template <class Sink>
  static void save(const Sink&) {}
  // The particles of the start: every particle the engine has.
  template <class Engine>
  static std::size_t start_count(const Engine& eng) {
    return eng.slots();
  }
  template <class Engine>
  static void before_renumbering(Engine&) {}
  // Particles i and j (both at now) touch: they collide (the engine's collision).
  template <class Engine>
  GG_ALWAYS_INLINE static bool meet(Engine& eng, std::uint32_t i, std::uint32_t j) {
    eng.bounce(i, j);
    return true;
  }
  template <class Effects>
  static constexpr bool present(const Effects&, std::uint32_t) {
    return true;
  }
  // A run stops by its contacts only when its clock stalls (inelastic collapse).
  static constexpr StopReason stop_reason() { return StopReason::kCollapse; }
};

}  // namespace ggsim
