#pragma once
// The event-driven engine: exact ballistic motion between instantaneous binary collisions of
// hard spheres (disks in 2D, rods in 1D) in a periodic box, one pending event per particle.
//
// The loop (run()) reads like the algorithm: take the earliest event, let due observations see
// the state before it, set the clock, then either leave a shell (a new one ahead, look at what
// came into reach), or collide (if the partner has not collided since the prediction), give both
// new shells and predict both again.
#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <stdexcept>
#include <utility>
#include <vector>

#include "gg/box.hpp"
#include "gg/errors.hpp"
#include "ggsim/cell_grid.hpp"
#include "ggsim/collision_rule.hpp"
#include "ggsim/event_calendar.hpp"
#include "ggsim/hot_path.hpp"
#include "ggsim/huge_pages.hpp"
#include "ggsim/particles.hpp"
#include "ggsim/permutation.hpp"
#include "ggsim/prediction.hpp"

namespace ggsim {

enum class StopReason { kTimeReached, kCollisionBudget, kInterrupted, kCollapse, kNothingLeft };

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
  std::vector<double> last_collision;  // TC model only
  double now = 0, virial = 0;
  std::uint64_t collisions = 0, events = 0, shell_exits = 0, stale_events = 0;
};

// The same state read in place, without a copy (a copy would double the memory of a run while a
// checkpoint is written); valid until the engine runs again.
template <int D>
struct EngineView {
  std::span<const Particle<D>> particles;
  const CellGrid<D>& grid;         // centres, start numbers (labels) and cell lists
  const EventCalendar& calendar;   // event times
  std::span<const double> last_collision;
  double now, virial;
  std::uint64_t collisions, events, shell_exits, stale_events;
};

struct EngineParameters {
  RuleParameters rule;
  double skin = kDefaultSkin;  // sigma units; shells have radius skin/2 (see cell_grid.hpp)
  double t0 = 0;      // clock at start
  std::uint64_t collisions0 = 0;  // collisions counted before the start (a run continued from a file)
  // Particles are renumbered in space after this many events per particle (see renumber()).
  double renumber_every = 16;
  // Whether the look-ahead takes its extra steps (fetch_ahead()); unset: by the number of
  // particles (fetches_deeper()). Either way the same trajectory.
  std::optional<bool> fetch_deeper;
};

template <int D, class Fx>
class Engine {
 public:
  static constexpr double kSigma = 1;  // disk diameter, the unit of length

  // positions in [0, L) (wrapped here), no pair closer than sigma beyond round-off.
  Engine(const gg::Box<D>& box, const std::vector<Vec<D>>& r, const std::vector<Vec<D>>& v,
         const EngineParameters& par)
      : box_(box),
        grid_(box, kSigma + usable_skin(box, par.skin), r.size()),
        calendar_(r.size()),
        now_(par.t0),
        fetch_deeper_(par.fetch_deeper.value_or(fetches_deeper(r.size()))) {
    set_reach(par.skin);
    rule_.p = par.rule;
    collisions_ = par.collisions0;
    if constexpr (Fx::kTc) rule_.last_collision.assign(r.size(), -std::numeric_limits<double>::infinity());
    const std::size_t n = r.size();
    p_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      Particle<D>& q = p_[i];
      for (int k = 0; k < D; ++k) q.r[k] = box_.wrap(r[i][k], k);
      q.v = v[i];
      q.t = now_;
      q.collisions = 0;
      q.events_at_this_time = 0;
      grid_.insert(static_cast<std::uint32_t>(i), q.r, static_cast<std::uint32_t>(i));
    }
    set_renumber_period(par.renumber_every);
    renumber_at_ = renumber_period_;
    for (std::uint32_t i = 0; i < n; ++i) predict(i, time_in_shell(i));
  }

  // Continues from a saved state (same box and parameters as the engine that saved it), taking
  // over its arrays where it can and letting go of the rest as they are used.
  Engine(const gg::Box<D>& box, EngineState<D>&& st, const EngineParameters& par)
      : box_(box),
        grid_(box, kSigma + usable_skin(box, par.skin), st.particles.size()),
        calendar_(st.particles.size()),
        now_(st.now),
        fetch_deeper_(par.fetch_deeper.value_or(fetches_deeper(st.particles.size()))) {
    set_reach(par.skin);
    rule_.p = par.rule;
    rule_.last_collision = std::move(st.last_collision);
    p_ = std::move(st.particles);
    grid_.restore(std::exchange(st.cell_head, {}), std::exchange(st.cell_next, {}), std::exchange(st.centres, {}),
                  std::exchange(st.id, {}));
    virial_ = st.virial;
    collisions_ = st.collisions, events_ = st.events, shell_exits_ = st.shell_exits, stale_events_ = st.stale_events;
    set_renumber_period(par.renumber_every);
    renumber_at_ = (events_ / renumber_period_ + 1) * renumber_period_;
    for (std::size_t i = 0; i < p_.size(); ++i) calendar_.schedule(static_cast<std::uint32_t>(i), st.event_time[i]);
  }

  EngineView<D> view() const {
    return {p_, grid_, calendar_, rule_.last_collision, now_, virial_, collisions_, events_, shell_exits_, stale_events_};
  }

  // Largest skin that keeps the minimum image unique for every pair that can touch before it
  // is predicted again: relative positions change by at most 2 skin between predictions, so
  // L > 2 (sigma + 2 skin) is needed.
  static double usable_skin(const gg::Box<D>& box, double wanted) {
    double L = box.L[0];
    for (int k = 1; k < D; ++k) L = std::min(L, box.L[k]);
    return std::min(wanted, 0.9 * (L - 2 * kSigma) / 4);
  }

  // Runs until the clock would pass t_end, the collision budget is spent, the observer asks to
  // stop (polled every 65536 events), or the dynamics stalls (inelastic collapse).
  template <class Observer>
  StopReason run(double t_end, std::uint64_t max_collisions, Observer& obs) {
    for (;;) {
      if (events_ >= renumber_at_) renumber();
      fetch_ahead();
      // The other events of the calendar's current bucket come next: their records and shell
      // centres are fetched meanwhile (N = 1e6: 2.11 -> 1.89 us per collision; N = 1e5: 0.83 -> 0.78;
      // alternating runs, medians of 5). Since fetch_ahead() this matters only for the events filed
      // after the look-ahead passed their bucket; dropping it saved no time.
      const std::uint32_t i = calendar_.earliest([this](std::uint32_t j) {
        __builtin_prefetch(&p_[j]);
        grid_.prefetch(j);
      });
      const double t = i == EventCalendar::kNone ? kNever : calendar_.time(i);
      const double horizon = std::min(t, t_end);
      for (double to = obs.next_time(); to <= horizon && to < kNever; to = obs.next_time()) obs.observe(*this, to);
      if (t > t_end) {
        now_ = t_end;
        return StopReason::kTimeReached;
      }
      if (i == EventCalendar::kNone) return StopReason::kNothingLeft;
      if (collisions_ >= max_collisions) return StopReason::kCollisionBudget;
      if (--poll_countdown_ == 0) {
        poll_countdown_ = kPollInterval;
        if (obs.poll(*this)) return StopReason::kInterrupted;  // between events: a clean state
      }
      ++events_;
      now_ = t;
      if (!process(i)) return StopReason::kCollapse;
    }
  }

  // --- read-only views for observers ---
  double now() const { return now_; }
  std::size_t size() const { return p_.size(); }
  const gg::Box<D>& box() const { return box_; }
  std::uint64_t collisions() const { return collisions_; }
  std::uint64_t events() const { return events_; }
  std::uint64_t shell_exits() const { return shell_exits_; }
  std::uint64_t stale_events() const { return stale_events_; }
  double shell_radius() const { return shell_radius_; }
  // Kinetic energy per particle (mass 1), summed afresh: no drift from incremental updates.
  double kinetic_energy() const {
    double s = 0;
    for (const auto& q : p_) s += dot<D>(q.v, q.v);
    return 0.5 * s / static_cast<double>(p_.size());
  }
  // Calls f(number in the start, position at time t wrapped into the box, velocity) for every
  // particle, in the engine's memory order (t >= every particle's last update). Reading does not
  // change the state, so observations never perturb the trajectory.
  template <class F>
  void for_each_particle(double t, F&& f) const {
    for (std::uint32_t i = 0; i < p_.size(); ++i) {
      const Particle<D>& q = p_[i];
      Vec<D> x;
      for (int k = 0; k < D; ++k) x[k] = box_.wrap(q.r[k] + q.v[k] * (t - q.t), k);
      f(grid_.label(i), x, q.v);
    }
  }
  // Sum of r_ij . Delta p_i since the last call (only with the Virial effect).
  double take_virial() {
    const double s = virial_;
    virial_ = 0;
    return s;
  }

 private:
  using Grid = CellGrid<D>;
  using Code = typename Grid::Code;

  // More events of one particle at one clock value than any regular tie produces (a particle
  // touched by each of its few neighbours at a symmetric instant): the clock has stopped.
  static constexpr std::uint32_t kStallLimit = 500;
  // Distance of a new shell's centre ahead of its particle, in shell radii (give_new_shell): as
  // near the shell's edge as the fixed-point centre allows (set_reach()).
  static constexpr double kShellLead = 0.98;

  // Brings q to now; false if q has had too many events at this clock value (collapse).
  bool advance(Particle<D>& q) {
    q.events_at_this_time = q.t == now_ ? q.events_at_this_time + 1 : 0;
    const double dt = now_ - q.t;
    // Between its events a particle moves less than a shell diameter: one fold suffices.
    for (int k = 0; k < D; ++k) q.r[k] = box_.wrap_near(q.r[k] + q.v[k] * dt, k);
    q.t = now_;
    return q.events_at_this_time <= kStallLimit;
  }

  // Gives particle i (at now) a new shell and returns how long i stays in it. The shell goes not
  // on i but ahead of it along its velocity, 0.98 radii away (inside, with room for round-off),
  // so that i crosses nearly the shell's whole diameter before it leaves: a third of the shell
  // exits of a shell centred on i, with as many centres within reach (N = 1e5, rho = 0.37, 0.9
  // radii ahead: 0.53 instead of 1.51 exits and 1.68 instead of 2.61 events per collision). Only
  // the chord i flies along matters, and the diameter is the longest: 0.98 radii ahead instead of
  // 0.9, N = 96993 leaves 0.855 instead of 0.911 shell exits per collision early and 1.148
  // instead of 1.238 after 8e6 collisions. Any centre keeps the dynamics exact. Moving straight
  // through the centre, i leaves a radius past it, (1 + 0.98) R / |v| from now, less the time to
  // cross the distance between the centre and its stored code (exit_path_): i is inside its shell
  // until the event (an early exit only costs an event), and no exit quadratic is solved for a
  // new shell. A particle at (nearly) rest gets its shell centred on it.
  double give_new_shell(std::uint32_t i) {
    const Particle<D>& q = p_[i];
    const double v2 = dot<D>(q.v, q.v);
    if (v2 < kTinySpeed2) {
      grid_.move(i, q.r);
      return time_in_shell(i);
    }
    const double speed = std::sqrt(v2);
    const double lead = lead_time(speed);
    Vec<D> c;
    for (int k = 0; k < D; ++k) c[k] = box_.wrap_near(q.r[k] + lead * q.v[k], k);
    grid_.move(i, c);
    return exit_path_ / speed;
  }

  // How long a particle moving at `speed` takes to reach the centre of the shell it is given.
  double lead_time(double speed) const { return kShellLead * shell_radius_ / speed; }

  // How long particle i (at now) stays in its present shell.
  double time_in_shell(std::uint32_t i) const {
    const Particle<D>& q = p_[i];
    return time_to_leave<D>(separation(q.r, grid_.centre(i)), q.v, shell_radius_);
  }

  Vec<D> separation(const Vec<D>& a, const Vec<D>& b) const {
    Vec<D> d;
    for (int k = 0; k < D; ++k) d[k] = box_.min_image_near(a[k] - b[k], k);
    return d;
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
  // shell's particle (kShellLead = 0.98 radii from the centre asked for) inside its shell.
  void set_reach(double skin) {
    const double room = usable_skin(box_, skin);
    shell_radius_ = 0.5 * std::min(grid_.min_cell_width() - kSigma, room);
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
    const double reach = (kSigma + 2 * shell_radius_) * (1 + 1e-6);
    reach2_ = reach * reach;
    // Holds for every box with room for a shell (L > 2 sigma, usable_skin); the search needs it.
    if (!(reach2_ < grid_.hidden_distance2())) throw std::logic_error("box too small for the neighbour search");
  }

  // Which particles within reach of i's centre a search predicts against: all of them, or (after
  // a shell exit) only those that were not within reach of its old centre, the pairs already
  // predicted being skipped. A compile-time choice: as a run-time flag it was a branch
  // mispredicted 1.2 times per collision in a cooling gas (cachegrind, N = 96993, the first
  // 8.5e6 collisions), shell exits and collisions coming at random.
  enum class Among { kAll, kCameIntoReach };

  // Earliest collision of particle i (at now) with any particle among those `Which` names, kept
  // in i's pending event if earlier than what it holds (old_centre: i's centre before a shell
  // exit; unused for Among::kAll).
  template <Among Which>
  void find_collision(std::uint32_t i, const Code& old_centre) {
    if (grid_.far_from_edges(grid_.code(i))) search<false, Which>(i, old_centre);
    else search<true, Which>(i, old_centre);
  }

  // Flattened: GCC 12 otherwise stops inlining the visit and the lambdas below at its size
  // limits, and the calls cost more than the branches the branch-free search saves.
  template <bool Periodic, Among Which>
  GG_FLATTEN void search(std::uint32_t i, const Code& old_centre) {
    Particle<D>& q = p_[i];
    PendingEvent& ev = q.next;
    const Code centre = grid_.code(i);
    const auto separation_at_now = [&](const Particle<D>& o, int k) {
      const double d = q.r[k] - (o.r[k] + o.v[k] * (now_ - o.t));
      if constexpr (Periodic) return box_.min_image_near(d, k);
      return d;
    };
    // The pairs in two passes: the invariants b = r.v, c = r.r - sigma^2, a = v.v of each, keeping
    // without a branch the pairs that approach and do not pass by (half of them or fewer, at
    // random); then the contact times of those kept, the earliest kept without a branch. A branch
    // per pair on each of the three tests mispredicted ~12 times per collision in a clustered gas:
    // N = 96993 after 1.2e7 collisions 14% less time per collision (median ratio of 5 alternating
    // pairs), N = 1e4 after 1.2e6 19% less, the early gas at N = 1e5 3.5% less, N = 1e6 the same;
    // cachegrind, N = 1e5: 3626 -> 3817 instructions, 22.4 -> 17.8 mispredicts per collision. Same
    // contact times and the same choice among equal ones, so the same trajectories.
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
        double b = 0, c = -kSigma * kSigma, a = 0;
        for (int k = 0; k < D; ++k) {
          const double r = separation_at_now(o, k);
          const double v = q.v[k] - o.v[k];
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
        double tc;
        if (x.a < kTinySpeed2) [[unlikely]] {  // speeds near underflow (end of a collapse)
          Vec<D> r, v;
          for (int d = 0; d < D; ++d) r[d] = separation_at_now(p_[x.j], d), v[d] = q.v[d] - p_[x.j].v[d];
          tc = now_ + time_to_contact<D>(r, v, kSigma * kSigma);
        } else {
          tc = now_ + time_to_contact(x.b, x.c, x.a);
        }
        // The earlier of the two kept without a branch (GCC 12 made the two selects one branch,
        // mispredicted 0.6 times per collision in the same run): std::min(t_best, tc) is
        // tc < t_best ? tc : t_best, a minsd.
        const std::uint32_t earlier = 0u - static_cast<std::uint32_t>(tc < t_best);  // all ones if so
        j_best ^= (j_best ^ x.j) & earlier;
        t_best = std::min(t_best, tc);
      }
      ev.collision_time = t_best;
      ev.partner = j_best;
    };
    // Two passes: the centres first, then the particles within reach, in the order of the cells.
    // (A pass between them that only fetched the records of those within reach saved 6-9% at
    // N = 1e6 before the look-ahead fetched every cell's first particle; since then it saves
    // nothing at 1e6-1e7, and its loop over a random count cost 4% at N = 1e4: PERFORMANCE.md.)
    // A quarter of the centres visited are within reach, at random: they are kept without a
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
    // places after them need a room check (N = 1e5: 3380 -> 3200 instructions and 27 -> 23
    // mispredicted branches per collision, cachegrind).
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
  void predict_collision(std::uint32_t i) {
    p_[i].next = PendingEvent{};
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
    // came into reach of i's new centre are new.
    // The event is filed where the kept collision or the exit puts it unless the search finds an
    // earlier collision, so that place is asked for meanwhile (same trajectories; alternating runs,
    // median paired ratios of 11 pairs: N = 1e6 x0.94, x1.01, x0.97; 1e5 x0.97; 1e4 x0.99 of 7).
    calendar_.prefetch_filing(event_time(i, stay));
    find_collision<Among::kCameIntoReach>(i, old_centre);
    schedule(i, stay);
  }

  // Every par.renumber_every events per particle, the particles are renumbered in the order of their
  // cells: the start is sorted in space, but particles drift, and an event reads the records of
  // its neighbours, which should then share cache lines and pages (at N = 1e6 a shuffled
  // numbering costs 1.37x a sorted one per collision, 1.15x with renumbering). Observers keep
  // the numbers of the start (the grid's labels move with the particles). The grid holds the new
  // numbers while the arrays move, so a renumbering adds only a bit per particle (permutation.hpp).
  GG_OFF_HOT_PATH void renumber() {
    renumber_at_ += renumber_period_;
    grid_.renumber_in_cell_order([&](const auto& rank) {
      for (Particle<D>& q : p_)
        if (q.next.partner != PendingEvent::kNone) q.next.partner = rank(q.next.partner);
      permute_by_rank(p_, rank);
      calendar_.renumber(rank);
      if constexpr (Fx::kTc) permute_by_rank(rule_.last_collision, rank);
    });
  }

  // Fetches what the events a few buckets ahead will read, in three steps one event apart, each
  // reading only what the step before fetched: the particle's record and shell centre (and the
  // calendar's node, by its walk); the list heads of the cells around where its search will be
  // (search_centre_ahead()), and the partner's record; the first entry of each of those cells
  // and its particle's record. An event that misses every cache otherwise waits for each of
  // these reads in turn. The second and third steps against the first alone (gg-bench-sim
  // --single N K 0.7 1e6, alternating runs, median ratios of 7-9 pairs, 3 at 1e7): N = 1e4 +1.6%
  // time per collision (all in cache; 320 more instructions), 1e5 -11%, 1e6 -18%, 1e7 -15%.
  // With fetch_deeper_, the third step also fetches the heads around a collision partner's
  // position at the collision, and a fourth the second entry of every cell around the event's
  // search and the first entries around the partner, with their records.
  void fetch_ahead() {
    if (p_.empty()) return;
    const std::uint32_t step2 = (calls_ - 1) % kAheadSteps, step3 = (calls_ - 2) % kAheadSteps;
    const auto fetch_record = [this](typename Grid::Slot s) GG_ALWAYS_INLINE_LAMBDA {
      __builtin_prefetch(Grid::element_address(p_.data(), s));
    };
    if (fetch_deeper_) {
      const std::uint32_t step4 = (calls_ - 3) % kAheadSteps;
      grid_.template prefetch_entries_around<2>(ahead_cell_[step4], fetch_record);
      grid_.template prefetch_entries_around<1>(partner_cell_[step4], fetch_record);
      partner_cell_[step3] = grid_.prefetch_heads_around(partner_position_ahead(ahead_[step3]));
    }
    grid_.template prefetch_entries_around<1>(ahead_cell_[step3], fetch_record);
    const std::uint32_t j1 = ahead_[step2];
    ahead_cell_[step2] = grid_.prefetch_heads_around(search_centre_ahead(j1));
    // The partner's record; without a partner (kNone) the last particle's, a harmless fetch
    // chosen without a branch (a select on kNone was a branch, mispredicted 0.7 times per
    // collision in the cooling run named at find_collision()).
    const auto partner = static_cast<std::uint32_t>(std::min<std::size_t>(p_[j1].next.partner, p_.size() - 1));
    __builtin_prefetch(&p_[partner]);
    // What the collision rule will read of the two: with the TC model their last collision times
    // (an array read at random places), nothing otherwise. Same trajectory with and without, the
    // paper's system with t_c = 1e-4, medians of paired rounds over one start copied for each:
    // e = 0.9, first 2.5e6 collisions x0.922 (9 of 9 below 1); e = 0.5 first 5e6 x0.943 and x0.981,
    // after 3.2e7 x0.989 (6 of 7).
    rule_.prefetch(j1);
    rule_.prefetch(partner);
    calendar_.look_ahead([this](std::uint32_t j) {
      __builtin_prefetch(&p_[j]);
      grid_.prefetch(j);
      ahead_[calls_ % kAheadSteps] = j;
    });
    ++calls_;
  }

  // Whether fetch_ahead() goes the extra steps for n particles: where the arrays (~110 bytes per
  // particle) outgrow the caches but an event's reads still come back fast enough that more of
  // them in flight pays. Alternating runs of the same build with and without them (gg-bench-sim
  // --single N K 0.7 WARM, median paired ratios): N = 3e5 x0.903 (9 pairs), 1e6 x0.881 and
  // x0.878 (9 each, 17 of 18 below 1), 3e6 x0.892 (5, all below 1); but 1e7 x1.058 and x1.237
  // (4 pairs each: from main memory, the extra reads crowd out the ones an event waits for),
  // 1e4 x1.10 and x1.076 (all in cache, where only the instructions count), 5e4 x1.006. Near
  // 1e5 (10 MB) it depends on the share of the last-level cache other jobs leave: in a quiet hour
  // (session 14) 1e5 x1.036 and x1.020, 96993 x1.046; in a busy one (session 20, a dependent read
  // within 4 MB 18-130 ns against 4-18 quiet) 1e5 x0.914, and the paper's system, N = 96993, x0.876
  // over the bench's first 1e7 collisions, x0.923 over 5e6, x0.890 after 1e7 (24 of 28 pairs
  // below 1). Other jobs share the cache on this machine most hours, as on a cluster's nodes, so
  // from 2^16 on. Each step alone at 1e6: the second entries x0.945, the partner's cells x1.062.
  static bool fetches_deeper(std::size_t n) { return n >= (std::size_t{1} << 16) && n <= (std::size_t{1} << 22); }

  // Where particle j's event will search, as far as j's record tells: its position at the event,
  // and for a shell exit the new shell's centre (give_new_shell). Its present shell centre, used
  // before, lies up to 1.98 shell radii from there, often in another cell. A collision's search is
  // around its new shell, up to 0.98 radii from the contact point, which is as near as j's record
  // alone allows. Alternating runs against the present centre, median paired ratios: N = 1e6
  // x0.955, x0.972, x0.957 (7, 21 and 11 pairs), 1e7 x0.959 and x1.015 (3 and 5 pairs, ratios
  // 0.77-1.37: noise), 1e5 early x0.986 (9), 1e4 x1.01-1.02 (36 more instructions per collision).
  // For shell exits alone: 1e6 x0.955, 1e7 x0.876 (3). A collision partner's cells are fetched
  // one step later, and only for mid-sized N (fetches_deeper()): at 1e4 they cost x1.06.
  Code search_centre_ahead(std::uint32_t j) const {
    const Particle<D>& q = p_[j];
    const double t = calendar_.time(j);
    const double v2 = dot<D>(q.v, q.v);
    // The lead goes in by a product, not a branch (exits and collisions come at random: a branch
    // mispredicted 1.1 times per collision in the cooling run named at find_collision()); the
    // speed is bounded below so that the lead is finite even when it is not taken.
    const bool exits = (t < q.next.collision_time) & (v2 >= kTinySpeed2);
    const double lead = lead_time(std::sqrt(std::max(v2, kTinySpeed2)));
    return code_ahead(q, t - q.t + lead * static_cast<double>(exits));
  }

  // Where the partner of particle j's collision will be at its time, as far as the partner's
  // record tells (its new shell is within 0.98 radii of there); j's own position then if j's event
  // is a shell exit or j has no partner.
  Code partner_position_ahead(std::uint32_t j) const {
    const Particle<D>& q = p_[j];
    const double t = calendar_.time(j);
    const bool collides = t >= q.next.collision_time && q.next.partner != PendingEvent::kNone;
    const Particle<D>& o = p_[collides ? q.next.partner : j];
    return code_ahead(o, t - o.t);
  }

  // The grid code of where q is `ahead` after its record's time. The code wraps into the box by
  // itself (arithmetic modulo 2^32, cell_grid.hpp). A particle without an event (t = kNever; only
  // ahead_'s first entries can name one) gets a meaningless code, which only sends one fetch astray.
  Code code_ahead(const Particle<D>& q, double ahead) const {
    Vec<D> x;
    for (int k = 0; k < D; ++k) x[k] = q.r[k] + q.v[k] * ahead;
    return grid_.encode(x);
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
    if (!advance(b)) return false;
    const double w = rule_.apply(a, b, i, ev.partner, separation(a.r, b.r), now_);
    if constexpr (Fx::kVirial) virial_ += w;
    else (void)w;
    ++collisions_;
    // New shells where the two go now: a particle that collides often (a cold cluster) then
    // hardly ever reaches the edge of its shell.
    const double stay_a = give_new_shell(i), stay_b = give_new_shell(ev.partner);
    // Both searches before either event is filed, and meanwhile the calendar is asked for b's
    // node and for the place a's event goes to: filing reads at random places in the calendar.
    // Same events in the same order. Alternating runs (`gg-bench-sim --single 1e6 1e6 0.7 1e6`,
    // median paired ratios of 5-11 pairs, six runs): x0.88-0.98 time per collision at N = 1e6;
    // the searches reordered without the two fetches x0.93; fetching b's filing place as well
    // x1.02-1.03 (two runs). N = 1e4 and 1e5 x0.96-0.99, clustered x0.99, 1e7 x1.01.
    calendar_.prefetch(ev.partner);
    predict_collision(i);
    const double t_a = event_time(i, stay_a);
    calendar_.prefetch_filing(t_a);
    predict_collision(ev.partner);
    calendar_.schedule(i, t_a);
    schedule(ev.partner, stay_b);
    return true;
  }

  gg::Box<D> box_;
  Grid grid_;
  EventCalendar calendar_;
  CollisionRule<D, Fx> rule_;
  ParticleArray<Particle<D>> p_;
  std::uint64_t renumber_period_ = 1, renumber_at_ = 0;  // events between renumberings; when next
  double now_;
  double shell_radius_ = 0, reach2_ = 0;
  double exit_path_ = 0;  // how far a particle goes from its new shell's creation to its exit
  double virial_ = 0;
  std::uint64_t collisions_ = 0, events_ = 0, shell_exits_ = 0, stale_events_ = 0;
  // The particles whose events fetch_ahead() reported in its last calls (a particle is reported
  // again while the calendar waits, so every step has one to work on), and how often it ran.
  static constexpr std::uint32_t kAheadSteps = 4;
  std::array<std::uint32_t, kAheadSteps> ahead_{};
  // Their cells, once found (-1: none; a 0 left by a shorter initializer would be read as a cell).
  std::array<std::int32_t, kAheadSteps> ahead_cell_ = [] {
    std::array<std::int32_t, kAheadSteps> none;
    none.fill(-1);
    return none;
  }();
  // The cells around the collision partners of those events (fetch_deeper_ only), as ahead_cell_.
  std::array<std::int32_t, kAheadSteps> partner_cell_ = ahead_cell_;
  bool fetch_deeper_ = false;  // EngineParameters::fetch_deeper
  std::uint32_t calls_ = 0;
  static constexpr std::uint32_t kPollInterval = 65536;
  std::uint32_t poll_countdown_ = kPollInterval;
};

}  // namespace ggsim
