#pragma once
// The hot data of the engine, kept compact (at most 120 bytes per particle, so that N = 1e7 fits
// in a little over 1 GB): in 2D everything an event reads about one particle fills exactly one
// 64-byte cache line.
#include <cstdint>
#include <string>

#include "gg/errors.hpp"

#include "ggsim/prediction.hpp"

namespace ggsim {

// What a particle last predicted: its earliest collision with a particle near it (valid while
// the partner's counter still equals `partner_collisions`), possibly later than leaving its
// shell. Its scheduled event is the earlier of the two; after a shell exit the collision stays
// valid (the trajectory is unchanged), so only particles that came into reach are searched.
struct PendingEvent {
  static constexpr std::uint32_t kNone = 0xffffffffu;
  double collision_time = kNever;
  std::uint32_t partner = kNone;
  std::uint32_t partner_collisions = 0;
};

// One particle as it was last touched: position r at its own time t (particles are advanced
// lazily, only when an event involves them), velocity v, its collision counter, which
// invalidates events predicted with its old velocity (Smallenburg's EDMD: stale events are
// recognised, not searched for and deleted), and its pending prediction. The centre of its
// shell lives with the cell lists (cell_grid.hpp), which are searched by centre.
template <int D>
struct alignas(D == 2 ? 64 : alignof(double)) Particle {
  Vec<D> r;
  Vec<D> v;
  double t;
  std::uint32_t collisions;
  // Consecutive events of this particle at one clock value. Inelastic collapse (infinitely many
  // collisions in finite time, McNamara & Young 1992) shows up in double precision as a few
  // particles colliding over and over while the clock no longer moves.
  std::uint32_t events_at_this_time;
  PendingEvent next;
};

static_assert(sizeof(Particle<2>) == 64, "a 2D particle should fill one cache line");

// How far two hard spheres may come closer than one diameter and still count as touching, in
// sigma: room for a few hundred ulps of a position in the largest box the tests run (L = 1e4,
// an ulp 1.8e-12), gathered by advancing particles and solving contact times in double
// precision; a missed or late collision overlaps by the relative speed times the delay, orders
// of magnitude more. The tests' overlap checks and a start read from a file use it.
inline constexpr double kOverlapTolerance = 1e-9;

// The most particles an engine takes: the cell lists link entries by 32-bit byte offsets
// (cell_grid.hpp), 16 bytes per entry in 2D.
inline constexpr std::uint64_t kMaxParticles = (std::uint64_t{1} << 28) - 1;

// Refuses n particles beyond `most`, as the command line's check and the engine's own (a start
// read from a file; in 3D, with longer entries, the cell lists hold fewer) alike.
inline void require_engine_holds(std::uint64_t n, std::uint64_t most = kMaxParticles) {
  if (n > most)
    throw gg::UsageError("N = " + std::to_string(n) + " is more than the engine holds (" + std::to_string(most) +
                         ": its cell lists are addressed in 32 bits); lower --N, --L or --rho");
}

}  // namespace ggsim
