#pragma once
// Part of the engine (engine.hpp, which includes it after its class): the search of a particle's
// earliest collision among the particles within reach of its shell (simulate/PERFORMANCE.md "The
// neighbour search"); near the box's edges the boundary may search itself (boundary/boundary.hpp).
// Not to be included on its own.
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <tuple>

#include "ggsim/cell_grid.hpp"
#include "ggsim/particles.hpp"
#include "ggsim/prediction.hpp"

namespace ggsim {

// Earliest collision of particle i (at now) with any particle among those `Which` names, kept
// in i's pending event if earlier than what it holds (old_centre: i's centre before a shell
// exit; unused for Among::kAll).
template <int D, class Fx>
template <typename Engine<D, Fx>::Among Which>
inline void Engine<D, Fx>::find_collision(std::uint32_t i, const Code& old_centre) {
  if (grid_.far_from_edges(grid_.code(i))) search<false, Which>(i, old_centre);
  else if (!box_.search_near_edges(i, p_, grid_, motion_, now_, [this](std::uint32_t a, std::uint32_t b) {
             return contact2(a, b);
           }))
    search<true, Which>(i, old_centre);
}

// Flattened: GCC 12 otherwise stops inlining the visit and the lambdas below at its size
// limits, and the calls cost more than the branches the branch-free search saves.
template <int D, class Fx>
template <bool Periodic, typename Engine<D, Fx>::Among Which>
inline void Engine<D, Fx>::search(std::uint32_t i, const Code& old_centre) {
  Particle<D>& q = p_[i];
  PendingEvent& ev = q.next;
  const Code centre = grid_.code(i);
  const auto separation_at_now = [&](const Particle<D>& o, int k) {
    const double d = q.r[k] - motion_.coordinate(o, k, now_ - o.t);
    if constexpr (Periodic) return box_.min_image_near(d, k);
    return d;
  };
  // The relative motion of a pair is a free flight under every motion law (a common force
  // cancels), so only the partner's velocity must be brought to now.
  const auto velocity_at_now = [&](const Particle<D>& o, int k) { return motion_.velocity(o, k, now_ - o.t); };
  // The pairs in two passes: the invariants b = r.v, c = r.r - sigma^2, a = v.v of each, keeping
  // without a branch the pairs that approach and do not pass by (half of them or fewer, at
  // random); then the contact times of those kept, the earliest kept without a branch: a branch
  // per pair on each of the three tests is mispredicted about half the time (simulate/
  // PERFORMANCE.md "The neighbour search"). Same contact times and the same choice among equal
  // ones, so the same trajectories.
  struct Approach {
    double b, c, a;
    std::uint32_t j;
  };
  std::array<Approach, 64> approaching;
  const auto predict_pairs = [&](std::span<const typename Grid::Slot> slots) {
    std::size_t kept = 0;
    for (const typename Grid::Slot s : slots) {
      const std::uint32_t j = Grid::particle(s);
      const Particle<D>& o = p_[j];
      double b = 0, c = -contact2(i, j), a = 0;
      for (int k = 0; k < D; ++k) {
        const double r = separation_at_now(o, k);
        const double v = q.v[k] - velocity_at_now(o, k);
        b += r * v;
        c += r * r;
        a += v * v;
      }
      approaching[kept] = Approach{b, c, a, j};
      // time_to_contact(b, c, a) is finite; below kTinySpeed2 the rescaling form decides.
      kept += (b < 0) & ((a < kTinySpeed2) | (c <= 0) | (b * b - a * c >= 0));
    }
    double t_best = ev.collision_time;
    std::uint32_t j_best = ev.partner;
    for (std::size_t k = 0; k < kept; ++k) {
      const Approach& x = approaching[k];
      double t_contact;
      if (x.a < kTinySpeed2) [[unlikely]] {  // speeds near underflow (end of a collapse)
        Vec<D> r, v;
        for (int d = 0; d < D; ++d) r[d] = separation_at_now(p_[x.j], d), v[d] = q.v[d] - velocity_at_now(p_[x.j], d);
        t_contact = now_ + time_to_contact<D>(r, v, contact2(i, x.j));
      } else {
        t_contact = now_ + time_to_contact(x.b, x.c, x.a);
      }
      // The earlier of the two kept without a branch (GCC 12 makes two selects one branch, taken
      // at random): std::min(t_best, t_contact) is t_contact < t_best ? t_contact : t_best, a minsd.
      const std::uint32_t earlier = 0u - static_cast<std::uint32_t>(t_contact < t_best);  // all ones if so
      j_best ^= (j_best ^ x.j) & earlier;
      t_best = std::min(t_best, t_contact);
    }
    ev.collision_time = t_best;
    ev.partner = j_best;
  };
  // Two passes: the centres first, then the particles within reach, in the order of the cells
  // (the look-ahead has fetched every cell's first particle already). A quarter of the centres visited are within reach, at random: they are kept without a
  // branch (each is written down, and counted only if within reach). The grid also passes on
  // empty places (CellGrid::visit); those and i itself are hidden out of reach meanwhile, so
  // distance is the only test.
  std::array<typename Grid::Slot, 64> near;  // the grid's slots of the particles within reach
  std::size_t n_near = 0;
  const auto predict_near = [&] {
    if constexpr (Which == Among::kCameIntoReach) {
      std::size_t kept = 0;
      for (std::size_t k = 0; k < n_near; ++k) {
        near[kept] = near[k];
        kept += grid_.distance2(old_centre, grid_.code_in(near[k])) > reach2_;
      }
      n_near = kept;
    }
    predict_pairs(std::span<const typename Grid::Slot>(near.data(), n_near));
    n_near = 0;
  };
  // `near` has room for every cell's first places (the inner visit's fixed part), so only the
  // places after them need a room check, a branch fewer per place.
  const auto take = [&](typename Grid::Slot s, const Code& cj) {
    near[n_near] = s;
    n_near += grid_.distance2(centre, cj) <= reach2_;
  };
  const auto candidate = [&](typename Grid::Slot s, const Code& cj) {
    take(s, cj);
    if (n_near == near.size()) predict_near();
  };
  static_assert(std::tuple_size_v<decltype(near)> > Grid::kFirstPlaces);
  static_assert(std::tuple_size_v<decltype(approaching)> >= std::tuple_size_v<decltype(near)>);  // one per particle near
  grid_.hide_for_search(i);
  if constexpr (Periodic) grid_.template for_each_near<Visit::kWithEmptyPlaces>(centre, candidate);
  else grid_.for_each_near_inner(centre, take, candidate);
  grid_.unhide(i);
  predict_near();
  if (ev.partner != PendingEvent::kNone) ev.partner_collisions = p_[ev.partner].collisions;
}

}  // namespace ggsim
