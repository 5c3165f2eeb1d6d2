#pragma once
// The engine's dynamic state for a checkpoint (checkpoint.hpp): what restoring an engine takes
// (EngineState, Engine's restoring constructor, engine.hpp) and what saving one reads in place
// (EngineView, Engine::view()).
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "ggsim/cell_grid.hpp"
#include "ggsim/effects/effect_state.hpp"
#include "ggsim/event_calendar.hpp"
#include "ggsim/huge_pages.hpp"
#include "ggsim/particles.hpp"

namespace ggsim {

// The complete dynamic state of an engine: restoring it continues a run bit for bit
// (checkpoints). Event order depends only on (time, particle index), so the calendar is rebuilt
// from the event times; the cell lists are kept as they were, since their order decides which of
// two exactly equal collision times a particle predicts. Particles are in the engine's current
// numbering; id[k] is the number in the start of the particle numbered k.
template <int D>
struct EngineState {
  ParticleArray<Particle<D>> particles;  // the engine's own array type: a restore moves it in
  std::vector<std::uint32_t> id;
  std::vector<Vec<D>> centres;
  std::vector<double> event_time;
  std::vector<std::int32_t> cell_head, cell_next;
  double now = 0;
  std::uint64_t collisions = 0, events = 0, shell_exits = 0, stale_events = 0;
  // The event count of the next renumbering: a multiple of the period from the start, but not
  // once a merging run has rebuilt its cells (rebuild()).
  std::uint64_t renumber_at = 0;
  EffectRecords effects;  // each effect's own arrays (effects/effect_state.hpp), and the boundary's (walls)
};

// The same state read in place, without a copy (a copy would double the memory of a run while a
// checkpoint is written); valid until the engine runs again.
template <int D>
struct EngineView {
  std::span<const Particle<D>> particles;
  const CellGrid<D>& grid;         // centres, start numbers (labels) and cell lists
  const EventCalendar& calendar;   // event times
  double now;
  std::uint64_t collisions, events, shell_exits, stale_events, renumber_at;
  std::function<void(const EffectSink&)> save_effects;  // each effect's (and the boundary's) arrays, one at a time
};

}  // namespace ggsim
