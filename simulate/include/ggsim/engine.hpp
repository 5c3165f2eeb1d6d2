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
//
// The class is here with the loop, what observers and a contact policy may call and how an event is
// carried out; its larger parts have headers of their own in engine/, included at the end: the
// state a checkpoint keeps (state.hpp), what observers read (observers.hpp), the shells
// (shells.hpp), the collision search (search.hpp) and the renumbering (renumbering.hpp).
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
#include "ggsim/engine/state.hpp"
#include "ggsim/event_calendar.hpp"
#include "ggsim/hot_path.hpp"
#include "ggsim/huge_pages.hpp"
#include "ggsim/look_ahead.hpp"
#include "ggsim/motion/free_flight.hpp"
#include "ggsim/motion/position.hpp"
#include "ggsim/particles.hpp"
#include "ggsim/prediction.hpp"
#include "ggsim/stop_reason.hpp"

namespace ggsim {

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
      : Engine(box, par, EffectStart{r.size(), par.t0, nullptr, &start}) {
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
    renumber_at_ = renumber_period_;
    contact_.start(*this);
    for (std::uint32_t i = 0; i < n; ++i) predict(i, time_in_shell(i));
  }

  // Continues from a saved state (same box and parameters as the engine that saved it), taking
  // over its arrays where it can and letting go of the rest as they are used.
  Engine(const gg::Box<D>& box, EngineState<D>&& st, const EngineParameters& par)
      // The effects (the sizes, whose cap the cells were built for, among them) and the boundary take
      // their saved arrays.
      : Engine(box, par, EffectStart{st.particles.size(), st.now, &st.id, &st.effects}) {
    p_ = std::move(st.particles);
    grid_.restore(std::exchange(st.cell_head, {}), std::exchange(st.cell_next, {}), std::exchange(st.centres, {}),
                  std::exchange(st.id, {}));
    collisions_ = st.collisions, events_ = st.events, shell_exits_ = st.shell_exits, stale_events_ = st.stale_events;
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
              box_.save(out);
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
  // At a time t >= every particle's last update (engine/observers.hpp): the kinetic energy per
  // particle (now if t is not given) and the sum of m V_a V_b, V the velocity less the mean flow;
  // |v|^2 of each particle; f(number in the start, position, velocity) and f(number in the start,
  // periodic image) for every particle.
  double kinetic_energy(double t) const;
  double kinetic_energy() const { return kinetic_energy(now_); }
  std::vector<double> velocity_tensor(double t) const;
  std::vector<double> squared_speeds(double t) const;
  template <class F>
  void for_each_particle(double t, F&& f) const;
  template <class F>
  void for_each_image(double t, F&& f) const;
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
  // The observables of the effects, the contact policy (aggregates' N(t)) and the boundary (the
  // walls') at a sample time.
  void observables(const ObservableSink& out, const Sample& at) {
    effects_.observables(out, at);
    if constexpr (requires { contact_.observables(out, at); }) contact_.observables(out, at);
    box_.observables(out);
  }
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
    set_renumber_period(renumber_every_, n);
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

  // What both starts share: the boundary, cells, calendar, effects and motion law for start.n
  // particles whose largest contact distance is `diameter`, the clock at start.t0, the shells and
  // the renumbering period; the effects and the boundary take their arrays from `start`.
  Engine(const gg::Box<D>& box, const EngineParameters& par, const EffectStart& start)
      : box_(box, par, start),
        effects_(par, start),
        grid_(box, effects_.diameter_cap() + usable_skin(box, skin_of(par), effects_.diameter_cap()), start.n),
        calendar_(start.n),
        motion_(par),
        now_(start.t0),
        look_ahead_(par.fetch_deeper.value_or(fetches_deeper(start.n))) {
    set_reach(skin_of(par));
    skin_ = skin_of(par), renumber_every_ = par.renumber_every;
    restitution_ = par.rule.e;
    set_renumber_period(par.renumber_every, start.n);
  }

  // More events of one particle at one clock value than any regular tie produces (a particle
  // touched by each of its few neighbours at a symmetric instant): the clock has stopped.
  static constexpr std::uint32_t kStallLimit = 500;
  // Distance of a new shell's centre ahead of its particle, in units of the shell radius (give_new_shell): as
  // near the shell's edge as the fixed-point centre allows (set_reach()).
  static constexpr double kShellLead = 0.98;

  // Where q is a time dt after its record, not folded into the box (at time t: dt = t - q.t), and
  // its velocity at time t, under the engine's motion law (motion/position.hpp).
  Vec<D> position_after(const Particle<D>& q, double dt) const { return ggsim::position_after<D>(motion_, q, dt); }
  Vec<D> velocity(const Particle<D>& q, double t) const { return velocity_after<D>(motion_, q, t - q.t); }
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
    const Vec<D> x = position_after(q, dt);
    for (int k = 0; k < D; ++k) q.r[k] = Boundary::folds_when_advancing(k) ? effects_.wrap_near(i, k, x[k], box_) : x[k];
    if constexpr (!std::is_same_v<Motion, FreeFlight>) q.v = velocity(q, now_);  // after the positions, which read the old one
    q.t = now_;
    return q.events_at_this_time <= kStallLimit;
  }

  // Gives particle i (at now) a new shell, ahead of it, and returns how long i stays in it
  // (engine/shells.hpp).
  double give_new_shell(std::uint32_t i);

  // How long a particle moving at `speed` takes to reach the centre of the shell it is given.
  double lead_time(double speed) const { return kShellLead * shell_radius_ / speed; }

  // How long particle i (at now) stays in its present shell, or less (engine/shells.hpp).
  double time_in_shell(std::uint32_t i) const;

  // Events between renumberings of n particles (a huge per_particle means never, within 1e18 events).
  void set_renumber_period(double per_particle, std::size_t n) {
    const double events = std::ceil(per_particle * static_cast<double>(n));
    renumber_period_ = static_cast<std::uint64_t>(std::clamp(events, 1.0, 1e18));
  }

  // The shells' radius for the skin, and the reach of a search (engine/shells.hpp).
  void set_reach(double skin);

  // Which particles within reach of i's centre a search predicts against: all of them, or (after
  // a shell exit) only those that were not within reach of its old centre, the pairs already
  // predicted being skipped. A compile-time choice: shell exits and collisions come at random, so
  // as a run-time flag it would be a mispredicted branch.
  enum class Among { kAll, kCameIntoReach };

  // Earliest collision of particle i (at now) among those `Which` names, kept in i's pending event
  // if earlier than what it holds, and the search of the cells it asks unless the boundary
  // searches itself (engine/search.hpp; flattened, as that file says why).
  template <Among Which>
  void find_collision(std::uint32_t i, const Code& old_centre);
  template <bool Periodic, Among Which>
  GG_FLATTEN void search(std::uint32_t i, const Code& old_centre);

  // The time of i's event, the earlier of its predicted collision and leaving its shell `stay`
  // from now, and its filing in the calendar.
  double event_time(std::uint32_t i, double stay) const { return std::min(now_ + stay, p_[i].next.collision_time); }
  void schedule(std::uint32_t i, double stay) { calendar_.schedule(i, event_time(i, stay)); }

  // Particle i's next collision (i already advanced to now), against every particle within reach.
  // The search starts from i's next meeting with the box's edges if the boundary has such events
  // (walls, boundary/walls.hpp).
  void predict_collision(std::uint32_t i) {
    p_[i].next = box_.edge_event(p_[i], i, now_);
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

  // Renumbers the particles in the order of their cells (engine/renumbering.hpp).
  GG_OFF_HOT_PATH void renumber();

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
    if (box_.is_edge_event(ev, i)) return meet_edge(i);
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

  // Particle i (at now) meets the box's edge (a wall): it changes course as after a collision.
  bool meet_edge(std::uint32_t i) {
    box_.meet_edge(p_[i]);
    ++p_[i].collisions;
    predict_anew(i);
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

#include "ggsim/engine/observers.hpp"
#include "ggsim/engine/renumbering.hpp"
#include "ggsim/engine/search.hpp"
#include "ggsim/engine/shells.hpp"
