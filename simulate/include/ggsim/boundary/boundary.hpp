#pragma once
// The boundary: what the box does at its edges (docs/DESIGN.md "Boundary and motion law"), as
// DynamO's boundary classes (BC/) keep them out of its dynamics. The boundary a scene runs is its
// variant's (EngineVariant::Boundary, effects/effect_set.hpp), fixed at compile time:
//   PeriodicBoundary  periodic on every axis (periodic.hpp): gg::Box itself, every member below
//                     empty or the plain answer, so that it costs what the box costs;
//   ShearedBoundary   Lees-Edwards sliding-brick images across the gradient axis (sheared.hpp;
//                     uniform shear flow, docs/PHYSICS.md "Uniform shear flow");
//   WalledBoundary    hard walls across the last axis (walls.hpp), periodic along the others: a
//                     particle's meeting with a wall is one of its events.
// A boundary is built from the box, the engine's parameters (its own in their effects' store) and
// the start's arrays (effects/effect_state.hpp's EffectStart), from which one with a state (the
// walls') takes what a checkpoint kept of it.
//
// What the engine asks of its boundary (EngineBoundary below checks every answer's shape):
//   folds_when_advancing(k)     whether a particle brought to now is folded into the box along
//                               axis k (else it is folded when it gets a new shell: fold())
//   fold(r, v, t[, image])      folds (r, v) at time t into the box from less than an edge outside,
//                               along the axes folds_when_advancing() leaves
//   to_touching_image(a, r, v, t, image)
//                               moves (r, v) to its image that touches a at time t
//   separation(a, b)            a - b at their nearest image, for positions less than an edge apart
//   peculiar(v, r)              the velocity v at r less the mean flow there
//   may_centre_shell_at(x)      whether a shell may be centred at x (unfolded), ahead of its particle
//   prepare_search(grid, reach) sets up for a search within `reach` on the cells `grid`
//   stay(grid, centre, t)       the longest a particle whose shell is centred at `centre` may go
//                               before it searches again, at most t (its time in the shell)
//   search_near_edges(i, ...)   searches particle i's collisions itself when its shell is near the
//                               box's edges, true if it did (false: the periodic search does)
//   edge_event(q, i, now)       particle i's (q's, at now) next meeting with the box's edges as its
//                               pending event, with which its search starts (none: PendingEvent{})
//   is_edge_event(ev, i)        whether ev, particle i's event now due, is that meeting
//   meet_edge(q)                what the meeting does to q (at the edge now): its new velocity
//   observables(sink), save(sink)
//                               what it reports at a sample time, and its state in a checkpoint
// The cell grid's own codes wrap periodically (cell_grid.hpp) under every boundary.
#include <concepts>
#include <cstddef>
#include <cstdint>

#include "gg/box.hpp"
#include "ggsim/cell_grid.hpp"
#include "ggsim/particles.hpp"

namespace ggsim {

// a - b at their nearest periodic image, for positions less than an edge apart along each axis.
template <int D>
Vec<D> nearest_separation(const gg::Box<D>& box, const Vec<D>& a, const Vec<D>& b) {
  Vec<D> d;
  for (int k = 0; k < D; ++k) d[k] = box.min_image_near(a[k] - b[k], k);
  return d;
}

// The answers of a boundary without events or a state of its own (periodic, sheared): none, and
// the engine's calls compile away.
template <int D>
struct WithoutEdgeEvents {
  static constexpr PendingEvent edge_event(const Particle<D>&, std::uint32_t, double) { return {}; }
  static constexpr bool is_edge_event(const PendingEvent&, std::uint32_t) { return false; }
  static void meet_edge(Particle<D>&) {}
  template <class Sink>
  static void observables(const Sink&) {}
  template <class Sink>
  static void save(const Sink&) {}
};

template <class B, int D>
concept EngineBoundary =
    std::derived_from<B, gg::Box<D>> &&
    requires(B& b, const B& cb, Vec<D>& r, Vec<D>& v, const Vec<D>& x, double t, int k, const CellGrid<D>& grid,
             const typename CellGrid<D>::Code& centre, Particle<D>& q, const PendingEvent& ev, std::uint32_t i) {
      { B::folds_when_advancing(k) } -> std::same_as<bool>;
      cb.fold(r, v, t);
      cb.to_touching_image(x, r, v, t, nullptr);
      { cb.separation(x, x) } -> std::same_as<Vec<D>>;
      { cb.peculiar(x, x) } -> std::same_as<Vec<D>>;
      { cb.may_centre_shell_at(x) } -> std::same_as<bool>;
      b.prepare_search(grid, t);
      { cb.stay(grid, centre, t) } -> std::same_as<double>;
      { cb.edge_event(q, i, t) } -> std::same_as<PendingEvent>;
      { cb.is_edge_event(ev, i) } -> std::same_as<bool>;
      b.meet_edge(q);
    };

}  // namespace ggsim
