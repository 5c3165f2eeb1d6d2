// The event calendar (event_calendar.hpp) against the plainest priority queue there is: an ordered
// set of (time, particle). Whatever is scheduled, rescheduled or renumbered, the calendar must
// name the same earliest event, ties going to the lower particle number, through windows that
// widen as the delays grow (a cooling gas), events "now" filed late in a bucket's span, events
// beyond the window, and events that never happen. Its look-ahead (which the engine uses to
// fetch memory early) must name only particles that exist, change no order, and name most
// events before they happen.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "ggsim/event_calendar.hpp"

namespace {

using ggsim::EventCalendar;
constexpr double kNever = std::numeric_limits<double>::infinity();

// The calendar and the reference side by side.
class Both {
 public:
  explicit Both(std::size_t n) : cal_(n), time_(n, kNever), reported_(n, false) {}

  void schedule(std::uint32_t i, double t) {
    reported_[i] = false;
    if (time_[i] < kNever) ref_.erase({time_[i], i});
    time_[i] = t;
    if (t < kNever) ref_.insert({t, i});
    cal_.schedule(i, t);
  }

  // The earliest event by both (kNone if none); checks they agree and that the calendar named
  // only particles that exist.
  std::uint32_t earliest() {
    std::vector<std::uint32_t> named;
    const std::uint32_t i = cal_.earliest([&](std::uint32_t j) { named.push_back(j); });
    for (std::uint32_t j : named) EXPECT_LT(j, time_.size());
    const std::uint32_t expected = ref_.empty() ? EventCalendar::kNone : ref_.begin()->second;
    EXPECT_EQ(i, expected);
    if (i != EventCalendar::kNone) {
      EXPECT_EQ(cal_.time(i), time_[i]);
    }
    return expected;
  }

  // One step of the calendar's look-ahead, as the engine takes before each event.
  void look_ahead() {
    cal_.look_ahead([&](std::uint32_t j) {
      EXPECT_LT(j, time_.size());
      if (j < reported_.size()) reported_[j] = true;
    });
  }
  // Whether the look-ahead named particle i since its event was last filed.
  bool reported(std::uint32_t i) const { return reported_[i]; }

  // Old particle k becomes rank[k].
  void renumber(const std::vector<std::uint32_t>& rank) {
    cal_.renumber([&](std::size_t k) { return rank[k]; });
    std::vector<double> moved(time_.size());
    for (std::size_t k = 0; k < time_.size(); ++k) moved[rank[k]] = time_[k];
    time_ = moved;
    reported_.assign(time_.size(), false);
    ref_.clear();
    for (std::uint32_t i = 0; i < time_.size(); ++i)
      if (time_[i] < kNever) ref_.insert({time_[i], i});
  }

  double time(std::uint32_t i) const { return time_[i]; }
  std::size_t size() const { return time_.size(); }

 private:
  EventCalendar cal_;
  std::vector<double> time_;
  std::set<std::pair<double, std::uint32_t>> ref_;
  std::vector<bool> reported_;
};

// Pops `steps` events as the engine does: the particle popped gets a new event (a delay from a
// distribution that widens by `growth` per step, now and then exactly now, a tie with another
// event, or never), and so does a random partner, before or after it; every `renumber_every` steps the particles
// are shuffled. Returns the fraction of the events popped that the look-ahead had named.
double exercise(std::size_t n, std::uint64_t seed, int steps, double growth, int renumber_every) {
  Both both(n);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  std::uniform_int_distribution<std::uint32_t> pick(0, static_cast<std::uint32_t>(n - 1));
  for (std::uint32_t i = 0; i < n; ++i) both.schedule(i, u(rng) < 0.05 ? kNever : u(rng));
  double scale = 1, now = 0;
  const auto next_time = [&] {
    const double r = u(rng);
    if (r < 0.02) return now;                             // a collision at once (overlap by round-off)
    if (r < 0.04) return kNever;                          // at rest, alone
    if (r < 0.06) return std::max(now, both.time(pick(rng)));  // an exact tie (never stays never)
    return now + scale * -std::log(1 - u(rng)) * (u(rng) < 0.1 ? 50.0 : 1.0);  // some beyond the window
  };
  double popped = 0, named = 0;
  for (int step = 0; step < steps; ++step) {
    both.look_ahead();
    const std::uint32_t i = both.earliest();
    if (::testing::Test::HasFailure()) return 0;  // one disagreement says it; the rest would repeat it
    if (i == EventCalendar::kNone) {              // everything at rest: wake a few
      for (int k = 0; k < 3; ++k) both.schedule(pick(rng), now + scale * u(rng));
      continue;
    }
    now = both.time(i);
    popped += 1;
    named += both.reported(i);
    // Half the time the partner first, while the calendar still holds i as the earliest: an
    // event filed at once (or tied) must then take its place.
    const std::uint32_t partner = pick(rng);
    const bool partner_first = u(rng) < 0.5;
    if (partner_first) {
      both.schedule(partner, next_time());
      both.earliest();
    }
    both.schedule(i, next_time());
    if (!partner_first) both.schedule(partner, next_time());
    scale *= growth;
    if (renumber_every > 0 && step % renumber_every == renumber_every - 1) {
      std::vector<std::uint32_t> rank(n);
      std::iota(rank.begin(), rank.end(), 0u);
      std::shuffle(rank.begin(), rank.end(), rng);
      both.renumber(rank);
    }
  }
  return named / std::max(popped, 1.0);
}

TEST(EventCalendar, SameOrderAsAnOrderedSet) { exercise(1000, 1, 200000, 1.0, 0); }

TEST(EventCalendar, FollowsDelaysGrowingAMillionFold) { exercise(1000, 2, 200000, 1.00007, 0); }

TEST(EventCalendar, KeepsTheOrderThroughRenumberings) { exercise(500, 3, 100000, 1.00002, 7919); }

TEST(EventCalendar, SmallerThanOneBucketPerParticle) {
  for (std::size_t n : {1u, 2u, 3u, 17u}) exercise(n, 4 + n, 20000, 1.0001, 0);
}

// One event is popped per look-ahead step, as in the engine, so the walk must keep ahead of the
// events it names.
TEST(EventCalendar, LookAheadNamesMostEventsBeforeTheyHappen) {
  EXPECT_GT(exercise(100000, 5, 300000, 1.0, 0), 0.9);
  EXPECT_GT(exercise(100000, 6, 300000, 1.00002, 0), 0.9);
}

TEST(EventCalendar, NothingLeftWhenEveryEventIsNever) {
  Both both(10);
  for (std::uint32_t i = 0; i < 10; ++i) both.schedule(i, kNever);
  EXPECT_EQ(both.earliest(), EventCalendar::kNone);
  both.schedule(7, 3.5);
  EXPECT_EQ(both.earliest(), 7u);
}

}  // namespace
