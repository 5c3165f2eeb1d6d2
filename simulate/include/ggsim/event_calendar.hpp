#pragma once
// Event calendar: one pending event per particle, O(1) insertion and removal.
//
// A calendar queue (Brown, CACM 31, 1220 (1988); as in Smallenburg's EDMD): a window of B
// buckets of width w starting at t0; events beyond the window wait in an overflow list, events
// that will never happen in a list of their own. Within the current bucket the earliest event
// is found by a scan (it holds a few events). When the window is used up, a new one starts where
// it ended and w is chosen anew from the pending events (w = kSpan x median delay / B), so the
// calendar follows the cooling: as collisions grow rarer the buckets widen, and the cost per
// event stays flat for any N and any time.
#include <algorithm>
#include <cstdint>
#include <span>
#include <vector>

#include "ggsim/hot_path.hpp"
#include "ggsim/huge_pages.hpp"
#include "ggsim/permutation.hpp"

namespace ggsim {

class EventCalendar {
 public:
  explicit EventCalendar(std::size_t n_particles);

  // (Re)schedules particle i's event at time t (>= the time of the last popped event).
  void schedule(std::uint32_t i, double t);
  // Particle with the earliest event, or kNone if no event will ever happen. soon(j) is called
  // for every event the search looks at: the events of the current bucket, the next few to
  // happen, whose data the owner can start fetching.
  template <class Soon>
  std::uint32_t earliest(Soon&& soon);
  double time(std::uint32_t i) const { return node_[i].time; }
  // Ask memory for what schedule() reads at random places: particle i's node (unlinking it then
  // writes to its neighbours), and the node in front of the bucket an event at time t goes to
  // (linking reads it; at N = 1e6 the 2^18 buckets' nodes take 4 MB).
  GG_ALWAYS_INLINE void prefetch(std::uint32_t i) const { __builtin_prefetch(&node_[i]); }
  void prefetch_filing(double t) const;
  // Reports, one per call, the events a few buckets after the current one, so that their owner
  // can fetch what each will read long before it happens (at N = 1e6 every read of an event
  // misses the caches otherwise, and each waits for the one before). A cursor walks the buckets
  // from kSkip to kLead after the current one, one event per call, and calls ahead(j) for the
  // event it reaches (for the one before again while it waits kLead buckets ahead). It reads
  // only what it fetched one call before, so the walk never waits on memory. It reports no event
  // filed after it has passed, and it drops behind when it meets an event filed elsewhere since;
  // when the current bucket catches up with it, it starts again kSkip buckets ahead.
  template <class Ahead>
  void look_ahead(Ahead&& ahead);
  // The particles are renumbered (old particle k becomes rank(k)): every event is filed anew.
  template <class Rank>
  void renumber(const Rank& rank) {
    permute_by_rank(particle_nodes(), rank);
    refile();
  }

  static constexpr std::uint32_t kNone = 0xffffffffu;

 private:
  static constexpr std::int32_t kUnlinked = -1;  // prev of a node in no list
  static constexpr std::size_t kSample = 4096;    // delays sampled to choose w
  static constexpr double kSpan = 2;              // window length in median delays
  void link(std::uint32_t i, std::int32_t list);
  void unlink(std::uint32_t i);
  // The node in front of list `list` (its next is the list's first node), and the node every
  // list ends in.
  std::int32_t head(std::int32_t list) const { return n_particles_ + list; }
  std::int32_t end() const { return n_particles_ + never_ + 1; }
  std::int32_t bucket_for(double t) const;
  void start_new_window();
  void refile();

  // The walk of look_ahead(): the bucket it is in, the event it reports next (end() when the
  // bucket is done), and the event it reported last.
  struct Cursor {
    std::int32_t list = -1, node = 0;
    std::uint32_t last = 0;
  };
  static constexpr std::int32_t kSkip = 3, kLead = 6;  // buckets after the current one
  void restart_cursor();

  std::int32_t n_particles_;
  std::int32_t n_buckets_;     // B
  std::int32_t overflow_;      // list index B
  std::int32_t never_;         // list index B + 1
  double t0_ = 0, width_ = 0, inv_width_ = 0;
  std::int32_t current_ = 0;   // index of the current bucket
  std::uint32_t cached_min_ = kNone;  // earliest event of the current bucket, if known

  // One 16-byte record per particle (four to a cache line), then one in front of each of the
  // B + 2 lists and one that ends them all: every linked node has a node before and after it,
  // so linking and unlinking take no branch (N = 1e5: 4 fewer mispredicted branches per
  // collision than with list heads of 4 bytes, for 4 more bytes per particle). A node's list is
  // not stored: it is bucket_for(time), which stays the same while the node is linked (a
  // window's buckets are emptied in order before the next window relinks everything).
  struct Node {
    double time = 0;
    std::int32_t next = 0, prev = kUnlinked;
  };
  ParticleArray<Node> node_;
  std::span<Node> particle_nodes() { return std::span<Node>(node_).first(static_cast<std::size_t>(n_particles_)); }
  std::vector<double> scratch_;     // a sample of the delays, for choosing w
  Cursor cursor_;
};

template <class Ahead>
void EventCalendar::look_ahead(Ahead&& ahead) {
  Cursor& c = cursor_;
  if (c.list <= current_) restart_cursor();
  const std::int32_t last = std::min(current_ + kLead, n_buckets_ - 1);
  while (c.node == end() && c.list < last) {
    ++c.list;
    c.node = node_[head(c.list)].next;  // fetched when the cursor entered the bucket before
    __builtin_prefetch(&node_[node_[head(c.list + 1)].next]);
  }
  const bool waiting = c.node == end();
  const std::uint32_t j = waiting ? c.last : static_cast<std::uint32_t>(c.node);
  c.node = waiting ? end() : node_[j].next;
  __builtin_prefetch(&node_[c.node]);
  c.last = j;
  ahead(j);
}

template <class Soon>
std::uint32_t EventCalendar::earliest(Soon&& soon) {
  if (cached_min_ != kNone) return cached_min_;
  for (;;) {
    if (current_ < n_buckets_) {
      if (node_[head(current_)].next != end()) break;
      ++current_;
      continue;
    }
    if (node_[head(overflow_)].next == end()) return kNone;  // only "never" events remain
    start_new_window();
  }
  // Scan the current bucket; ties go to the lower index so the order never depends on
  // insertion history beyond the event times themselves.
  std::uint32_t best = static_cast<std::uint32_t>(node_[head(current_)].next);
  soon(best);
  for (std::int32_t j = node_[best].next; j != end(); j = node_[j].next) {
    const auto u = static_cast<std::uint32_t>(j);
    soon(u);
    if (node_[u].time < node_[best].time || (node_[u].time == node_[best].time && u < best)) best = u;
  }
  cached_min_ = best;
  return best;
}

}  // namespace ggsim
