#pragma once
// The engine's look-ahead: fetches what the events a few buckets ahead in the calendar will read,
// so that an event that would miss every cache finds its data on the way. Events come in time
// order, which is random in space, so at large N each of an event's reads (its record, its cells,
// their entries, the neighbours' records) misses otherwise, and each waits for the one before.
// It only asks memory for data, never changes it: the trajectory is the same with or without it
// (tests/simulate/look_ahead_test.cpp). Why each step pays: simulate/PERFORMANCE.md "The look-ahead".
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "ggsim/cell_grid.hpp"
#include "ggsim/effects/effect_set.hpp"
#include "ggsim/event_calendar.hpp"
#include "ggsim/hot_path.hpp"
#include "ggsim/huge_pages.hpp"
#include "ggsim/motion/position.hpp"
#include "ggsim/particles.hpp"
#include "ggsim/prediction.hpp"

namespace ggsim {

// Whether the look-ahead takes its deeper steps for n particles: where the arrays (~110 bytes per
// particle) outgrow the caches but an event's reads still come back fast enough that more of them
// in flight pays. Below 2^16 everything is in cache and only the extra instructions count; above
// 2^22 the reads come from main memory, and the extra ones crowd out those an event waits for.
inline bool fetches_deeper(std::size_t n) { return n >= (std::size_t{1} << 16) && n <= (std::size_t{1} << 22); }

template <int D, class Fx>
class LookAhead {
 public:
  using Grid = CellGrid<D>;
  using Code = typename Grid::Code;

  explicit LookAhead(bool deeper) : deeper_(deeper) {}

  // How far ahead of its particle a new shell is centred (the engine's kShellLead radii), which
  // tells where a shell exit's search will be.
  void set_shell_lead(double distance) { shell_lead_ = distance; }

  // One call per event, in three steps one event apart, each reading only what the step before
  // fetched: the particle's record and shell centre (and the calendar's node, by its walk); the
  // list heads of the cells around where its search will be (search_centre()), and the partner's
  // record; the first entry of each of those cells and its particle's record. With the deeper
  // steps, the third also fetches the heads around a collision partner's position at the
  // collision, and a fourth the second entry of every cell around the event's search and the
  // first entries around the partner, with their records.
  void fetch(const ParticleArray<Particle<D>>& p, const Grid& grid, EventCalendar& calendar,
             const typename Fx::template Set<D>& effects, const typename Fx::Motion& motion) {
    if (p.empty()) return;
    const std::uint32_t step2 = (calls_ - 1) % kSteps, step3 = (calls_ - 2) % kSteps;
    const auto fetch_record = [&p](typename Grid::Slot s) GG_ALWAYS_INLINE_LAMBDA {
      __builtin_prefetch(Grid::element_address(p.data(), s));
    };
    if (deeper_) {
      const std::uint32_t step4 = (calls_ - 3) % kSteps;
      grid.template prefetch_entries_around<2>(cell_[step4], fetch_record);
      grid.template prefetch_entries_around<1>(partner_cell_[step4], fetch_record);
      partner_cell_[step3] = grid.prefetch_heads_around(partner_position(p, grid, calendar, motion, particle_[step3]));
    }
    grid.template prefetch_entries_around<1>(cell_[step3], fetch_record);
    const std::uint32_t j1 = particle_[step2];
    cell_[step2] = grid.prefetch_heads_around(search_centre(p, grid, calendar, motion, j1));
    // The partner's record; without a partner (kNone) the last particle's, a harmless fetch
    // chosen without a branch (a select on kNone compiles to a branch taken at random).
    const auto partner = static_cast<std::uint32_t>(std::min<std::size_t>(p[j1].next.partner, p.size() - 1));
    __builtin_prefetch(&p[partner]);
    // What the effects will read of the two in a collision: with the TC model their last
    // collision times (an array read at random places), nothing without such effects.
    effects.prefetch(j1);
    effects.prefetch(partner);
    calendar.look_ahead([&](std::uint32_t j) {
      __builtin_prefetch(&p[j]);
      grid.prefetch(j);
      particle_[calls_ % kSteps] = j;
    });
    ++calls_;
  }

 private:
  // Where particle j's event will search, as far as j's record tells: its position at the event,
  // and for a shell exit the new shell's centre. (Its present shell centre lies up to 1.98 shell
  // radii from there, often in another cell.) A collision's search is around its new shell, up to
  // kShellLead radii from the contact point, which is as near as j's record alone allows.
  Code search_centre(const ParticleArray<Particle<D>>& p, const Grid& grid, const EventCalendar& calendar,
                     const typename Fx::Motion& motion, std::uint32_t j) const {
    const Particle<D>& q = p[j];
    const double t = calendar.time(j);
    const double v2 = dot<D>(q.v, q.v);
    // The lead goes in by a product, not a branch (exits and collisions come at random); the
    // speed is bounded below so that the lead is finite even when it is not taken.
    const bool exits = (t < q.next.collision_time) & (v2 >= kTinySpeed2);
    const double lead = shell_lead_ / std::sqrt(std::max(v2, kTinySpeed2));
    return code_at(grid, motion, q, t - q.t + lead * static_cast<double>(exits));
  }

  // Where the partner of particle j's collision will be at its time, as far as the partner's
  // record tells (its new shell is within kShellLead radii of there); j's own position then if j's
  // event is a shell exit or j has no partner.
  Code partner_position(const ParticleArray<Particle<D>>& p, const Grid& grid, const EventCalendar& calendar,
                        const typename Fx::Motion& motion, std::uint32_t j) const {
    const Particle<D>& q = p[j];
    const double t = calendar.time(j);
    const bool collides = t >= q.next.collision_time && q.next.partner != PendingEvent::kNone;
    const Particle<D>& o = p[collides ? q.next.partner : j];
    return code_at(grid, motion, o, t - o.t);
  }

  // The grid code of where q is `ahead` after its record's time. The code wraps into the box by
  // itself (arithmetic modulo 2^32, cell_grid.hpp). A particle without an event (t = kNever; only
  // particle_'s first entries can name one) gets a meaningless code, which only sends one fetch astray.
  static Code code_at(const Grid& grid, const typename Fx::Motion& motion, const Particle<D>& q, double ahead) {
    return grid.encode(position_after<D>(motion, q, ahead));
  }

  // The particles whose events the calendar reported in the last calls, one per step; one more
  // than the deepest step reads, since the calendar reports a particle again while it waits.
  static constexpr std::uint32_t kSteps = 4;
  std::array<std::uint32_t, kSteps> particle_{};
  // Their cells, once found (-1: none; a 0 left by a shorter initializer would be read as a cell).
  std::array<std::int32_t, kSteps> cell_ = [] {
    std::array<std::int32_t, kSteps> none;
    none.fill(-1);
    return none;
  }();
  // The cells around the collision partners of those events (deeper steps only), as cell_.
  std::array<std::int32_t, kSteps> partner_cell_ = cell_;
  bool deeper_;
  double shell_lead_ = 0;
  std::uint32_t calls_ = 0;
};

}  // namespace ggsim
