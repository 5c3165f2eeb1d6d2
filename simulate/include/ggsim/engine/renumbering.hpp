#pragma once
// Part of the engine (engine.hpp, which includes it after its class): the renumbering of the
// particles in the order of their cells (simulate/PERFORMANCE.md "Renumbering in space").
// Not to be included on its own.
#include "ggsim/particles.hpp"
#include "ggsim/permutation.hpp"

namespace ggsim {

// Every par.renumber_every events per particle, the particles are renumbered in the order of their
// cells: the start is sorted in space, but particles drift, and an event reads the records of
// its neighbours, which should then share cache lines and pages (simulate/PERFORMANCE.md
// "Renumbering in space"). Observers keep
// the numbers of the start (the grid's labels move with the particles). The grid holds the new
// numbers while the arrays move, so a renumbering adds only a bit per particle (permutation.hpp).
// Particles merged away are in no cell: a merging contact first drops them (rebuild()).
template <int D, class Fx>
void Engine<D, Fx>::renumber() {
  contact_.before_renumbering(*this);
  renumber_at_ += renumber_period_;
  grid_.renumber_in_cell_order([&](const auto& rank) {
    for (Particle<D>& q : p_)
      if (q.next.partner != PendingEvent::kNone) q.next.partner = rank(q.next.partner);
    permute_by_rank(p_, rank);
    calendar_.renumber(rank);
    effects_.permute(rank);
  });
}

}  // namespace ggsim
