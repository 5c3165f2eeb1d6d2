#pragma once
// Part of the engine (engine.hpp, which includes it after its class): the shells (cell_grid.hpp):
// how large they are and how far a search reaches, where a particle's new shell goes and how long
// the particle stays in it (simulate/PERFORMANCE.md "Shells instead of cell crossings").
// Not to be included on its own.
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "gg/errors.hpp"
#include "ggsim/particles.hpp"
#include "ggsim/prediction.hpp"

namespace ggsim {

// Gives particle i (at now) a new shell and returns how long i stays in it. The shell goes not
// on i but ahead of it along its velocity, kShellLead times the shell radius away (inside, with room for
// round-off), so that i crosses nearly the shell's whole diameter, the longest chord, before it
// leaves: a third of the shell exits of a shell centred on i (simulate/PERFORMANCE.md "Shells
// instead of cell crossings"). Any centre keeps the dynamics exact. Moving straight
// through the centre, i leaves a radius past it, (1 + 0.98) R / |v| from now, less the time to
// cross the distance between the centre and its stored code (exit_path_): i is inside its shell
// until the event (an early exit only costs an event), and no exit quadratic is solved for a
// new shell. A particle at (nearly) rest gets its shell centred on it.
// A path that curves (gravity) gets its shell centred on it instead: the exit is then a bound.
// The particle is first folded into the box along the axes advance() leaves, and a shell whose
// centre the boundary refuses (a sheared box's, across its sliding edge) is centred on it instead.
template <int D, class Fx>
inline double Engine<D, Fx>::give_new_shell(std::uint32_t i) {
  Particle<D>& q = p_[i];
  box_.fold(q.r, q.v, now_, effects_.image_count(i));
  const double v2 = dot<D>(q.v, q.v);
  if (v2 < kTinySpeed2 || motion_.bends()) {
    grid_.move(i, q.r);
    return time_in_shell(i);
  }
  const double speed = std::sqrt(v2);
  Vec<D> c = position_after(q, lead_time(speed));
  if (!box_.may_centre_shell_at(c)) {
    grid_.move(i, q.r);
    return time_in_shell(i);
  }
  for (int k = 0; k < D; ++k) c[k] = box_.wrap_near(c[k], k);
  grid_.move(i, c);
  return box_.stay(grid_, grid_.code(i), exit_path_ / speed);
}

// How long particle i (at now) stays in its present shell, or before it searches again if the
// boundary wants it sooner (a sheared box's sliding edge).
template <int D, class Fx>
inline double Engine<D, Fx>::time_in_shell(std::uint32_t i) const {
  const Particle<D>& q = p_[i];
  const double stay = motion_.template time_to_leave_sphere<D>(box_.separation(q.r, grid_.centre(i)), q.v, shell_radius_);
  return box_.stay(grid_, grid_.code(i), stay);
}

// Shells of radius skin/2 (no wider than the cells allow), and the reach: two particles can
// touch before either leaves its shell only if their centres are at most sigma + 2 x radius
// apart. The reach gets a relative margin of 1e-6 against round-off in positions and exits.
// Shell centres are kept to a step of L/2^32 (cell_grid.hpp), at most half a step along each
// axis from where they were asked for: held below a hundredth of the radius, that keeps a new
// shell's particle (kShellLead = 0.98 of the radius from the centre asked for) inside its shell.
template <int D, class Fx>
inline void Engine<D, Fx>::set_reach(double skin) {
  const double room = usable_skin(box_, skin, diameter_cap());
  shell_radius_ = 0.5 * std::min(grid_.min_cell_width() - diameter_cap(), room);
  if (!(grid_.code_error() <= 0.01 * shell_radius_) && room < skin) {
    double L = box_.L[0];
    for (int k = 1; k < D; ++k) L = std::min(L, box_.L[k]);
    throw gg::UsageError("the box (L = " + std::to_string(L) + " diameters) is too small: the engine needs every "
                         "edge a little over 2 diameters, so that each pair has one nearest image; raise --N or "
                         "--L, or lower --rho");
  }
  if (!(grid_.code_error() <= 0.01 * shell_radius_))
    throw gg::UsageError("the skin (" + std::to_string(2 * shell_radius_) + ") is too thin for a box this long: shell "
                         "centres are kept to L/2^32; raise --skin above " + std::to_string(200 * grid_.code_error()));
  // Twice the code error: the centre's own computation rounds too, far below a code step.
  exit_path_ = (1 + kShellLead) * shell_radius_ - 2 * grid_.code_error();
  look_ahead_.set_shell_lead(kShellLead * shell_radius_);
  const double reach = (diameter_cap() + 2 * shell_radius_) * (1 + 1e-6);
  reach2_ = reach * reach;
  // Holds for every box with room for a shell (L > 2 sigma, usable_skin); the search needs it.
  if (!(reach2_ < grid_.hidden_distance2())) throw std::logic_error("box too small for the neighbour search");
  box_.prepare_search(grid_, reach);
}

}  // namespace ggsim
