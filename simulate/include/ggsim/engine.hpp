#pragma once
// The event-driven engine: exact ballistic motion between instantaneous binary collisions of
// hard spheres (disks in 2D, rods in 1D) in a periodic box, one pending event per particle. Where a
// particle is between its events is the motion law's to say, what the box's edges do the boundary's
// (motion/, boundary/: free flight and periodic images by default).
//
// The loop (run()) reads like the algorithm: take the earliest event, let due observations see
// the state before it, set the clock, then either leave a shell (a new one ahead, look at what
// came into reach), or collide (if the partner has not collided since the prediction), give both
// new shells and predict both again. Under a contact policy that merges (contact/: the
// ballistic aggregation model) the two merge instead, as the policy says.
// The scene's effects (effects/effect_set.hpp) are asked at fixed points: by the collision, for
// the time of their next act (the loop takes the earlier of that and the next event), when
// positions fold into the box, when particles are renumbered, by the look-ahead and by a
// checkpoint. The engine knows none of them by name.
#include <algorithm>
#include <array>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <span>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <vector>

#include "gg/box.hpp"
#include "gg/errors.hpp"
#include "ggsim/boundary/boundary.hpp"
#include "ggsim/cell_grid.hpp"
#include "ggsim/collision_rule.hpp"
#include "ggsim/effects/effect_set.hpp"
#include "ggsim/event_calendar.hpp"
#include "ggsim/hot_path.hpp"
#include "ggsim/huge_pages.hpp"
#include "ggsim/look_ahead.hpp"
#include "ggsim/motion/free_flight.hpp"
#include "ggsim/particles.hpp"
#include "ggsim/permutation.hpp"
#include "ggsim/prediction.hpp"
#include "ggsim/stop_reason.hpp"

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
  EffectRecords effects;  // each effect's own arrays (effects/effect_state.hpp)
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
  std::function<void(const EffectSink&)> save_effects;  // each effect's arrays, one at a time
};

struct EngineParameters {
  RuleParameters rule;
  std::optional<double> skin;  // sigma units; shells have radius skin/2 (cell_grid.hpp); unset: default_skin(D)
  double t0 = 0;      // clock at start
  std::uint64_t collisions0 = 0;  // collisions counted before the start (a run continued from a file)
  // Particles are renumbered in space after this many events per particle (see renumber()).
  double renumber_every = 16;
  // Whether the look-ahead takes its deeper steps (look_ahead.hpp); unset: by the number of
  // particles (fetches_deeper()). Either way the same trajectory.
  std::optional<bool> fetch_deeper;
};

template <int D, class Fx>
class Engine {
 public:
  using Effects = typename Fx::template Set<D>;
  // Where particles go between events and what the edges of the box do (motion/, boundary/).
  using Motion = typename Fx::Motion;
  using Boundary = typename Fx::template Boundary<D>;
  // What a touching pair does (contact/): collide, or merge through what the engine offers a
  // contact policy (below).
  using Contact = typename Fx::template Contact<D, Engine>;

 private:
  static_assert(EngineBoundary<Boundary, D>, "a boundary answers what the engine asks (boundary/boundary.hpp)");

 public:
  static constexpr double kSigma = 1;  // disk diameter, the unit of length
  static constexpr int kDim = D;

  // positions anywhere (wrapped here), no pair closer than sigma beyond round-off; `start`: what
  // the effects start from besides their parameters (the periodic images "image", angular
  // velocities "spin", a mixture's sizes; absent: image 0, no rotation, radius 1/2 and mass 1), in
  // the numbering of r.
  Engine(const gg::Box<D>& box, const std::vector<Vec<D>>& r, const std::vector<Vec<D>>& v,
         const EngineParameters& par, EffectRecords start = {})
      : box_(box, par),
        effects_(par, EffectStart{r.size(), par.t0, nullptr, &start}),
        grid_(box, effects_.diameter_cap() + usable_skin(box, skin_of(par), effects_.diameter_cap()), r.size()),
        calendar_(r.size()),
        motion_(par),
        now_(par.t0),
        look_ahead_(par.fetch_deeper.value_or(fetches_deeper(r.size()))) {
    set_reach(skin_of(par));
    skin_ = skin_of(par), renumber_every_ = par.renumber_every;
    restitution_ = par.rule.e;
    collisions_ = par.collisions0;
    const std::size_t n = r.size();
    p_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      Particle<D>& q = p_[i];
      for (int k = 0; k < D; ++k) q.r[k] = effects_.wrap(static_cast<std::uint32_t>(i), k, r[i][k], box_);
      q.v = v[i];
      q.t = now_;
      q.collisions = 0;
      q.events_at_this_time = 0;
      grid_.insert(static_cast<std::uint32_t>(i), q.r, static_cast<std::uint32_t>(i));
    }
    set_renumber_period(par.renumber_every);
    renumber_at_ = renumber_period_;
    contact_.start(*this);
    for (std::uint32_t i = 0; i < n; ++i) predict(i, time_in_shell(i));
  }

  // Continues from a saved state (same box and parameters as the engine that saved it), taking
  // over its arrays where it can and letting go of the rest as they are used.
  Engine(const gg::Box<D>& box, EngineState<D>&& st, const EngineParameters& par)
      : box_(box, par),
        // The effects take their saved arrays (the sizes, whose cap the cells were built for, among them).
        effects_(par, EffectStart{st.particles.size(), st.now, &st.id, &st.effects}),
        grid_(box, effects_.diameter_cap() + usable_skin(box, skin_of(par), effects_.diameter_cap()),
              st.particles.size()),
        calendar_(st.particles.size()),
        motion_(par),
        now_(st.now),
        look_ahead_(par.fetch_deeper.value_or(fetches_deeper(st.particles.size()))) {
    set_reach(skin_of(par));
    skin_ = skin_of(par), renumber_every_ = par.renumber_every;
    restitution_ = par.rule.e;
    p_ = std::move(st.particles);
    grid_.restore(std::exchange(st.cell_head, {}), std::exchange(st.cell_next, {}), std::exchange(st.centres, {}),
                  std::exchange(st.id, {}));
    collisions_ = st.collisions, events_ = st.events, shell_exits_ = st.shell_exits, stale_events_ = st.stale_events;
    set_renumber_period(par.renumber_every);
    renumber_at_ = st.renumber_at;
    contact_.restore(*this, st.effects);
    for (std::size_t i = 0; i < p_.size(); ++i) calendar_.schedule(static_cast<std::uint32_t>(i), st.event_time[i]);
  }

  EngineView<D> view() const {
    return {p_,
            grid_,
            calendar_,
            now_,
            collisions_,
            events_,
            shell_exits_,
            stale_events_,
            renumber_at_,
            [this](const EffectSink& out) {
              effects_.save(out);
              contact_.save(out);
            }};
  }

  // Largest skin that keeps the minimum image unique for every pair that can touch before it
  // is predicted again: relative positions change by at most 2 skin between predictions, so
  // L > 2 (sigma + 2 skin) is needed, i.e. skin < (L - 2 sigma) / 4. The cap stays kSkinRoom of
  // that bound, so that round-off in wrapped positions and in the reach's margin never puts a
  // pair's second image within reach in the smallest boxes.
  // (`diameter`: the largest contact distance, larger than sigma for aggregates.)
  static double skin_of(const EngineParameters& par) { return par.skin.value_or(default_skin(D)); }
  static double usable_skin(const gg::Box<D>& box, double wanted, double diameter = kSigma) {
    double L = box.L[0];
    for (int k = 1; k < D; ++k) L = std::min(L, box.L[k]);
    return std::min(wanted, kSkinRoom * (L - 2 * diameter) / 4);
  }
  static constexpr double kSkinRoom = 0.9;

  // Runs until the clock would pass t_end, the collision budget is spent, the observer asks to
  // stop (polled every 65536 events), or the dynamics stalls (inelastic collapse).
  template <class Observer>
  StopReason run(double t_end, std::uint64_t max_collisions, Observer& obs) {
    for (;;) {
      if (events_ >= renumber_at_) renumber();
      look_ahead_.fetch(p_, grid_, calendar_, effects_, motion_);
      // The other events of the calendar's current bucket come next: their records and shell
      // centres are fetched meanwhile. Since the look-ahead this matters only for the events filed
      // after it passed their bucket.
      const std::uint32_t i = calendar_.earliest([this](std::uint32_t j) {
        __builtin_prefetch(&p_[j]);
        grid_.prefetch(j);
      });
      double t = i == EventCalendar::kNone ? kNever : calendar_.time(i);
      bool timed = false;  // a timed effect acts first (an event at the same instant comes first)
      if constexpr (Effects::kTimed) {
        const double t_act = effects_.next_time();
        timed = t_act < t;
        t = std::min(t, t_act);
      }
      const double horizon = std::min(t, t_end);
      for (double to = obs.next_time(); to <= horizon && to < kNever; to = obs.next_time()) obs.observe(*this, to);
      if (t > t_end) {
        now_ = t_end;
        return StopReason::kTimeReached;
      }
      if (i == EventCalendar::kNone && !timed) return StopReason::kNothingLeft;
      if (collisions_ >= max_collisions) return StopReason::kCollisionBudget;
      if (--poll_countdown_ == 0) {
        poll_countdown_ = kPollInterval;
        if (obs.poll(*this)) return StopReason::kInterrupted;  // between events: a clean state
      }
      ++events_;
      now_ = t;
      bool done;
      if constexpr (Effects::kTimed) done = timed ? act() : process(i);
      else done = process(i);
      if (!done) return stall_reason();
    }
  }

  // --- read-only views for observers ---
  double now() const { return now_; }
  // The particles of the start (a merging run keeps their rows in its outputs).
  std::size_t size() const { return contact_.start_count(*this); }
  const Boundary& box() const { return box_; }
  std::uint64_t collisions() const { return collisions_; }
  std::uint64_t events() const { return events_; }
  std::uint64_t shell_exits() const { return shell_exits_; }
  std::uint64_t stale_events() const { return stale_events_; }
  double shell_radius() const { return shell_radius_; }
  // Kinetic energy per particle (mass 1) at time t, of the velocities less the mean flow in a
  // sheared box (t >= every particle's last update; now if
  // not given), summed afresh: no drift from incremental updates. For aggregates, per start
  // particle (per unit mass): sum m v^2 / 2 over the particles left, / N0; for a mixture,
  // sum m v^2 / 2 / N.
  double kinetic_energy(double t) const {
    double s = 0;
    for (std::size_t i = 0; i < p_.size(); ++i) {
      const Vec<D> v = peculiar_velocity(p_[i], t);
      s += effects_.mass(static_cast<std::uint32_t>(i)) * dot<D>(v, v);
    }
    return 0.5 * s / static_cast<double>(size());
  }
  double kinetic_energy() const { return kinetic_energy(now_); }
  // The sum over the particles of m V_a V_b at time t, V as in kinetic_energy(), row-major d x d.
  std::vector<double> velocity_tensor(double t) const {
    std::vector<double> s(D * D, 0.0);
    for (std::size_t i = 0; i < p_.size(); ++i) {
      const Vec<D> v = peculiar_velocity(p_[i], t);
      const double m = effects_.mass(static_cast<std::uint32_t>(i));
      for (int a = 0; a < D; ++a)
        for (int b = 0; b < D; ++b) s[a * D + b] += m * v[a] * v[b];
    }
    return s;
  }
  // |v|^2 at time t of each particle, in the engine's numbering.
  std::vector<double> squared_speeds(double t) const {
    std::vector<double> s(p_.size());
    for (std::size_t i = 0; i < p_.size(); ++i) {
      const Vec<D> v = velocity(p_[i], t);
      for (double x : v) s[i] += x * x;
    }
    return s;
  }
  // Calls f(number in the start, position at time t folded into the box, velocity) for every
  // particle, in the engine's memory order (t >= every particle's last update). Reading does not
  // change the state, so observations never perturb the trajectory.
  // For aggregates, the particles left (each under the number in the start of one of its parts).
  template <class F>
  void for_each_particle(double t, F&& f) const {
    for (std::uint32_t i = 0; i < p_.size(); ++i) {
      if (!present(i)) continue;
      const Particle<D>& q = p_[i];
      Vec<D> x = position_after(q, t - q.t), v = velocity(q, t);
      box_.fold(x, v, t);
      for (int k = 0; k < D; ++k) x[k] = box_.wrap(x[k], k);
      f(grid_.label(i), x, v);
    }
  }
  // Calls f(number in the start, periodic image at time t) for every particle, as
  // for_each_particle visits them: with its position there it says where the particle has gone
  // since the start (position + image x L; a sheared box adds its slide, boundary/sheared.hpp). Only an
  // engine whose effects count images (effects/image_counts.hpp) counts them; else every image is 0.
  template <class F>
  void for_each_image(double t, F&& f) const {
    for (std::uint32_t i = 0; i < p_.size(); ++i) {
      const Particle<D>& q = p_[i];
      Image<D> a = effects_.image(i);
      Vec<D> x = position_after(q, t - q.t), v = velocity(q, t);  // the fold moves v too; only the count is wanted here
      box_.fold(x, v, t, &a);
      for (int k = 0; k < D; ++k) {
        std::int64_t folds;
        box_.wrap(x[k], k, folds);
        a[k] += static_cast<std::int32_t>(folds);
      }
      f(grid_.label(i), a);
    }
  }
  // Calls f(number in the start, mass, radius) for every particle present, as for_each_particle
  // (an engine whose particles have sizes).
  template <class F>
  void for_each_size(F&& f) const {
    for (std::uint32_t i = 0; i < p_.size(); ++i)
      if (present(i)) f(grid_.label(i), effects_.mass(i), effects_.radius(i));
  }
  // The contact policy, for what it tells of the particles (a merging one: those left, and which
  // each start particle is part of).
  const Contact& contact() const { return contact_; }
  // The scene's effects, for the outputs they add (the recorder) and the tests.
  Effects& effects() { return effects_; }
  const Effects& effects() const { return effects_; }
  // The number in the start of the particle the engine numbers i.
  std::uint32_t label(std::uint32_t i) const { return grid_.label(i); }
  // Calls f(number in the start, x) for every x of a per-particle array in the engine's numbering
  // (an effect's: angular velocities, last collision times).
  template <class T, class F>
  void for_each_labelled(const std::vector<T>& a, F&& f) const {
    for (std::uint32_t i = 0; i < a.size(); ++i) f(grid_.label(i), a[i]);
  }

  // --- what the engine offers a contact policy (contact/): a merge removes a particle, changes a
  // size (the sizes effect's) and predicts anew ---

  // The particles in the engine's numbering, those merged away but not yet dropped among them.
  std::size_t slots() const { return p_.size(); }
  // Particle k's record; a policy that changes its course says so (changed_course()).
  Particle<D>& particle(std::uint32_t k) { return p_[k]; }
  // Brings particle k to now; false if the clock has stalled.
  bool bring_to_now(std::uint32_t k) { return advance(p_[k]); }
  // Particle k (at now) has changed course: every event predicted with it is stale.
  void changed_course(std::uint32_t k) { ++p_[k].collisions; }
  void count_collision() { ++collisions_; }
  // Particle k leaves the cells and the calendar (it merged into another); its record stays, with
  // no event, until rebuild() drops it.
  void remove(std::uint32_t k) {
    changed_course(k);
    p_[k].next = PendingEvent{};
    grid_.remove(k);
    calendar_.schedule(k, kNever);
  }
  // Calls f(j, r_i - r_j at now, at the nearest image) for every other particle j whose shell
  // centre lies in the cells around i's position (i at now).
  template <class F>
  void for_each_near(std::uint32_t i, F&& f) const {
    const Particle<D>& a = p_[i];
    grid_.for_each_near(grid_.encode(a.r), [&](std::uint32_t j, const auto&) {
      if (j == i) return;
      const Vec<D> x = position_after(p_[j], now_ - p_[j].t);
      Vec<D> d;
      for (int k = 0; k < D; ++k) d[k] = box_.min_image(a.r[k] - x[k], k);
      f(j, d);
    });
  }
  // Particle i (at now) gets a new shell and its next event.
  void predict_anew(std::uint32_t i) {
    const double stay = give_new_shell(i);
    predict(i, stay);
  }
  // Particle i's shell is centred on it (i moved since the cells were built).
  void centre_shell_on(std::uint32_t i) { grid_.move(i, p_[i].r); }
  // The pair i, j (both at now) collides by the collision rule and both fly on (Bounce).
  GG_ALWAYS_INLINE void bounce(std::uint32_t i, std::uint32_t j) {
    Particle<D>&a = p_[i], &b = p_[j];
    box_.to_touching_image(a.r, b.r, b.v, now_, effects_.image_count(j));
    collide<D>(a, b, i, j, box_.separation(a.r, b.r), now_, restitution_, effects_);
    ++collisions_;
    new_courses(i, j);
  }
  // Squared contact distance of particles i and j: (R_i + R_j)^2, exactly sigma^2 = 1 for two
  // particles of radius 1/2.
  double contact2(std::uint32_t i, std::uint32_t j) const { return effects_.contact2(i, j); }

  // Builds the cells, the calendar and the look-ahead anew for the particles present (those merged
  // away dropped, the others keeping their order; *keep follows its particle), every particle at
  // now with its shell centred on it, for the sizes' radius cap. No event is predicted: the caller
  // finishes its merges, then calls predict_all().
  GG_OFF_HOT_PATH void rebuild(std::uint32_t* keep) {
    std::size_t n = 0;
    std::vector<std::uint32_t> label, kept;
    for (std::size_t k = 0; k < p_.size(); ++k) {
      if (!present(static_cast<std::uint32_t>(k))) continue;
      if (keep && *keep == k) *keep = static_cast<std::uint32_t>(n);
      Particle<D>& q = p_[k];
      const Vec<D> x = position_after(q, now_ - q.t);
      for (int d = 0; d < D; ++d) q.r[d] = box_.wrap_near(x[d], d);
      q.t = now_;
      q.next = PendingEvent{};
      label.push_back(grid_.label(static_cast<std::uint32_t>(k)));
      kept.push_back(static_cast<std::uint32_t>(k));
      p_[n] = q;
      ++n;
    }
    p_.resize(n);
    effects_.compact(kept);
    grid_ = Grid(box_, diameter_cap() + usable_skin(box_, skin_, diameter_cap()), n);
    for (std::uint32_t k = 0; k < n; ++k) grid_.insert(k, p_[k].r, label[k]);
    calendar_ = EventCalendar(n);
    look_ahead_ = LookAhead<D, Fx>(fetches_deeper(n));
    set_reach(skin_);
    set_renumber_period(renumber_every_);
    renumber_at_ = events_ + renumber_period_;
  }

  // Whether a radius cap leaves every box edge room for the two diameters and a shell
  // (usable_skin()) whose centre the fixed-point codes can hold (set_reach()).
  bool fits(double cap) const { return 0.5 * usable_skin(box_, skin_, 2 * cap) >= 100 * grid_.code_error(); }

  // Every particle's next event (all at now) against all within reach; those merged away since
  // the cells were built have none.
  void predict_all() {
    for (std::uint32_t k = 0; k < p_.size(); ++k)
      if (present(k)) predict(k, time_in_shell(k));
  }


 private:
  using Grid = CellGrid<D>;
  using Code = typename Grid::Code;

  // More events of one particle at one clock value than any regular tie produces (a particle
  // touched by each of its few neighbours at a symmetric instant): the clock has stopped.
  static constexpr std::uint32_t kStallLimit = 500;
  // Distance of a new shell's centre ahead of its particle, in units of the shell radius (give_new_shell): as
  // near the shell's edge as the fixed-point centre allows (set_reach()).
  static constexpr double kShellLead = 0.98;

  // Where q is a time dt after its record, not folded into the box (at time t: dt = t - q.t).
  Vec<D> position_after(const Particle<D>& q, double dt) const {
    Vec<D> x;
    for (int k = 0; k < D; ++k) x[k] = motion_.coordinate(q, k, dt);
    return x;
  }
  // q's velocity at time t (its record's if the motion law keeps velocities).
  Vec<D> velocity(const Particle<D>& q, double t) const {
    Vec<D> v;
    for (int k = 0; k < D; ++k) v[k] = motion_.velocity(q, k, t - q.t);
    return v;
  }
  // The same less the mean flow where q is (a sheared box's).
  Vec<D> peculiar_velocity(const Particle<D>& q, double t) const { return box_.peculiar(velocity(q, t), position_after(q, t - q.t)); }

  // Brings q to now; false if q has had too many events at this clock value (collapse).
  bool advance(Particle<D>& q) {
    q.events_at_this_time = q.t == now_ ? q.events_at_this_time + 1 : 0;
    const double dt = now_ - q.t;
    // Between its events a particle moves less than a shell diameter: one fold suffices. Along
    // an axis the boundary folds later (a sheared box's gradient axis), it folds when the particle
    // gets a new shell (give_new_shell()).
    const auto i = static_cast<std::uint32_t>(&q - p_.data());
    for (int k = 0; k < D; ++k) {
      const double x = motion_.coordinate(q, k, dt);
      q.r[k] = Boundary::folds_when_advancing(k) ? effects_.wrap_near(i, k, x, box_) : x;
    }
    if constexpr (!std::is_same_v<Motion, FreeFlight>) q.v = velocity(q, now_);  // after the positions, which read the old one
    q.t = now_;
    return q.events_at_this_time <= kStallLimit;
  }

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
  double give_new_shell(std::uint32_t i) {
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

  // How long a particle moving at `speed` takes to reach the centre of the shell it is given.
  double lead_time(double speed) const { return kShellLead * shell_radius_ / speed; }

  // How long particle i (at now) stays in its present shell, or before it searches again if the
  // boundary wants it sooner (a sheared box's sliding edge).
  double time_in_shell(std::uint32_t i) const {
    const Particle<D>& q = p_[i];
    const double stay = motion_.template time_to_leave_sphere<D>(box_.separation(q.r, grid_.centre(i)), q.v, shell_radius_);
    return box_.stay(grid_, grid_.code(i), stay);
  }

  // Events between renumberings (a huge per_particle means never, within 1e18 events).
  void set_renumber_period(double per_particle) {
    const double events = std::ceil(per_particle * static_cast<double>(p_.size()));
    renumber_period_ = static_cast<std::uint64_t>(std::clamp(events, 1.0, 1e18));
  }

  // Shells of radius skin/2 (no wider than the cells allow), and the reach: two particles can
  // touch before either leaves its shell only if their centres are at most sigma + 2 x radius
  // apart. The reach gets a relative margin of 1e-6 against round-off in positions and exits.
  // Shell centres are kept to a step of L/2^32 (cell_grid.hpp), at most half a step along each
  // axis from where they were asked for: held below a hundredth of the radius, that keeps a new
  // shell's particle (kShellLead = 0.98 of the radius from the centre asked for) inside its shell.
  void set_reach(double skin) {
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

  // Which particles within reach of i's centre a search predicts against: all of them, or (after
  // a shell exit) only those that were not within reach of its old centre, the pairs already
  // predicted being skipped. A compile-time choice: shell exits and collisions come at random, so
  // as a run-time flag it would be a mispredicted branch.
  enum class Among { kAll, kCameIntoReach };

  // Earliest collision of particle i (at now) with any particle among those `Which` names, kept
  // in i's pending event if earlier than what it holds (old_centre: i's centre before a shell
  // exit; unused for Among::kAll).
  template <Among Which>
  void find_collision(std::uint32_t i, const Code& old_centre) {
    if (grid_.far_from_edges(grid_.code(i))) search<false, Which>(i, old_centre);
    else if (!box_.search_near_edges(i, p_, grid_, motion_, now_, [this](std::uint32_t a, std::uint32_t b) {
               return contact2(a, b);
             }))
      search<true, Which>(i, old_centre);
  }

  // Flattened: GCC 12 otherwise stops inlining the visit and the lambdas below at its size
  // limits, and the calls cost more than the branches the branch-free search saves.
  template <bool Periodic, Among Which>
  GG_FLATTEN void search(std::uint32_t i, const Code& old_centre) {
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

  // The time of i's event, the earlier of its predicted collision and leaving its shell `stay`
  // from now, and its filing in the calendar.
  double event_time(std::uint32_t i, double stay) const { return std::min(now_ + stay, p_[i].next.collision_time); }
  void schedule(std::uint32_t i, double stay) { calendar_.schedule(i, event_time(i, stay)); }

  // Particle i's next collision (i already advanced to now), against every particle within reach.
  // With walls (effects/walls.hpp) the search starts from i's meeting with a wall, an event whose
  // partner is i itself.
  void predict_collision(std::uint32_t i) {
    p_[i].next = PendingEvent{};
    if constexpr (Effects::kWalls) p_[i].next = {now_ + effects_.time_to_wall(p_[i]), i, p_[i].collisions};
    find_collision<Among::kAll>(i, {});
  }
  // Next event of particle i, `stay` from leaving its shell.
  void predict(std::uint32_t i, double stay) {
    predict_collision(i);
    schedule(i, stay);
  }

  // Particle i reached the edge of its shell: a new shell ahead of where it is now.
  void leave_shell(std::uint32_t i) {
    const Code old_centre = grid_.code(i);
    const double stay = give_new_shell(i);
    ++shell_exits_;
    const PendingEvent& ev = p_[i].next;
    if (ev.partner != PendingEvent::kNone && p_[ev.partner].collisions != ev.partner_collisions) {
      predict(i, stay);  // the remembered collision is void, and with it what it was the earliest of
      return;
    }
    // Every pair within reach has been predicted by one of its two particles since either last
    // changed course (a particle that changes course predicts against all within reach; one
    // that moves its centre, against all that came into reach), so only the particles that
    // came into reach of i's new centre are new. (A boundary that searches near its edges itself
    // may search all within reach there: a sheared box's pairs through the sliding edge move in
    // and out of reach by themselves.)
    // The event is filed where the kept collision or the exit puts it unless the search finds an
    // earlier collision, so that place is asked for meanwhile (same trajectories).
    calendar_.prefetch_filing(event_time(i, stay));
    find_collision<Among::kCameIntoReach>(i, old_centre);
    schedule(i, stay);
  }

  // Every par.renumber_every events per particle, the particles are renumbered in the order of their
  // cells: the start is sorted in space, but particles drift, and an event reads the records of
  // its neighbours, which should then share cache lines and pages (simulate/PERFORMANCE.md
  // "Renumbering in space"). Observers keep
  // the numbers of the start (the grid's labels move with the particles). The grid holds the new
  // numbers while the arrays move, so a renumbering adds only a bit per particle (permutation.hpp).
  // Particles merged away are in no cell: a merging contact first drops them (rebuild()).
  GG_OFF_HOT_PATH void renumber() {
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

  // Carries out particle i's event; false if the clock has stalled (inelastic collapse).
  bool process(std::uint32_t i) {
    Particle<D>& a = p_[i];
    if (!advance(a)) return false;
    const PendingEvent ev = a.next;
    if (now_ < ev.collision_time) {
      leave_shell(i);
      return true;
    }
    Particle<D>& b = p_[ev.partner];
    if (b.collisions != ev.partner_collisions) {  // the partner changed course: predict anew
      ++stale_events_;
      predict(i, time_in_shell(i));
      return true;
    }
    if constexpr (Effects::kWalls)
      if (ev.partner == i) return meet_wall(i);
    if (!advance(b)) return false;
    return contact_.meet(*this, i, ev.partner);
  }

  // Particles i and j (at now) have changed course: their events predicted before are stale
  // (their counters have moved on), and both get new shells and new predictions.
  GG_ALWAYS_INLINE void new_courses(std::uint32_t i, std::uint32_t j) {
    // New shells where the two go now: a particle that collides often (a cold cluster) then
    // hardly ever reaches the edge of its shell.
    const double stay_a = give_new_shell(i), stay_b = give_new_shell(j);
    // Both searches before either event is filed, and meanwhile the calendar is asked for b's
    // node and for the place a's event goes to: filing reads at random places in the calendar.
    // Same events in the same order (simulate/PERFORMANCE.md "The neighbour search").
    calendar_.prefetch(j);
    predict_collision(i);
    const double t_a = event_time(i, stay_a);
    calendar_.prefetch_filing(t_a);
    predict_collision(j);
    calendar_.schedule(i, t_a);
    schedule(j, stay_b);
  }

  // Particle i (at now) meets a wall: it changes course as after a collision.
  bool meet_wall(std::uint32_t i) {
    effects_.hit_wall(p_[i]);
    ++p_[i].collisions;
    const double stay = give_new_shell(i);
    predict(i, stay);
    return true;
  }

  // --- effects that act at times of their own (effects/effect_set.hpp) ---

  // The act due now: the effect names a pair, which is brought to now, kicked, and predicted
  // anew, as after a collision (O(1) per act; the calendar files the new events where they go,
  // even before the event the loop put off). False if the clock has stalled.
  bool act() {
    return effects_.act_first_due([this](auto& effect) {
      const auto [i, j] = effect.pair();
      if (!advance(p_[i]) || !advance(p_[j])) return false;
      effect.kick(p_[i].v, p_[j].v);
      ++p_[i].collisions;
      ++p_[j].collisions;
      new_courses(i, j);
      return true;
    });
  }

  // Why the loop stops when process() says so: a stalled clock, or what the contact policy found
  // (one particle left, one too large for the box).
  StopReason stall_reason() const { return contact_.stop_reason(); }
  // Whether particle i is still there (one merged away is, for the contact policy, until rebuild() drops it).
  bool present(std::uint32_t i) const { return contact_.present(effects_, i); }

  // The largest contact distance a search allows for: sigma, or twice the radius cap of
  // aggregates or of a mixture (no radius exceeds it; the cells are that plus the skin wide).
  double diameter_cap() const { return effects_.diameter_cap(); }

  Boundary box_;
  Effects effects_;  // before the cells, which are built for the largest contact distance of its sizes
  Grid grid_;
  EventCalendar calendar_;
  Motion motion_;
  double restitution_ = 1;  // e of the scene (the effects may make a collision elastic)
  ParticleArray<Particle<D>> p_;
  std::uint64_t renumber_period_ = 1, renumber_at_ = 0;  // events between renumberings; when next
  double now_;
  double shell_radius_ = 0, reach2_ = 0;
  double exit_path_ = 0;  // how far a particle goes from its new shell's creation to its exit
  std::uint64_t collisions_ = 0, events_ = 0, shell_exits_ = 0, stale_events_ = 0;
  LookAhead<D, Fx> look_ahead_;
  static constexpr std::uint32_t kPollInterval = 65536;
  std::uint32_t poll_countdown_ = kPollInterval;
  // The parameters the cells are built anew with (rebuild()).
  double skin_ = 0, renumber_every_ = 0;
  [[no_unique_address]] Contact contact_;
};

}  // namespace ggsim
