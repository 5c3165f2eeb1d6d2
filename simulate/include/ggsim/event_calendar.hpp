#pragma once
// Event calendar: one pending event per particle, O(1) insertion and removal.
//
// A calendar queue (Brown, CACM 31, 1220 (1988); as in Smallenburg's EDMD): a window of B
// buckets of width w starting at t0; events beyond the window wait in an overflow list, events
// that will never happen in a list of their own. The current bucket (a few events) is sorted
// when it is reached and kept in order, so its first event is the earliest. When the window is
// used up, a new one starts where it ended and w is chosen anew from the pending events
// (w = kSpan x median delay / B), so the calendar follows the cooling: as collisions grow rarer
// the buckets widen, and the cost per event stays flat for any N and any time.
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
  // Links i in front of list `list` (one of its events, in no order) or right after node `at`.
  void link(std::uint32_t i, std::int32_t list) { link_after(i, head(list)); }
  void link_after(std::uint32_t i, std::int32_t at) {
    const std::int32_t after = node_[at].next;
    node_[i].prev = at;
    node_[i].next = after;
    node_[after].prev = static_cast<std::int32_t>(i);  // the end node's prev means nothing
    node_[at].next = static_cast<std::int32_t>(i);
  }
  void unlink(std::uint32_t i);
  // Whether event a comes before event b: the earlier time, and of equal times the lower index,
  // so the order never depends on insertion history beyond the event times themselves.
  bool precedes(std::int32_t a, std::int32_t b) const {
    return node_[a].time < node_[b].time || (node_[a].time == node_[b].time && a < b);
  }
  // Links i into the list that starts after node `after_node` (a list's head node), at its place
  // in event order.
  void insert_in_order(std::int32_t i, std::int32_t after_node);
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
  // Where the walk of look_ahead() runs, in buckets after the current one. A bucket holds a few
  // events (a window of two median delays over a bucket per four particles), so kSkip = 3 buckets
  // put the reported event ~10 events ahead: far enough that the look-ahead's steps, one event
  // apart, have fetched its data before it comes, even when each step waits on main memory.
  // kLead = 6 stops the walk while what it fetched is still in the first-level cache (~20 lines
  // an event, ~20 events: ~25 KB of 48 KB). Reaching 9 buckets, or walking 4-8, changes nothing
  // measurable (simulate/PERFORMANCE.md "Dead ends").
  static constexpr std::int32_t kSkip = 3, kLead = 6;
  void restart_cursor();

  std::int32_t n_particles_;
  std::int32_t n_buckets_;     // B
  std::int32_t overflow_;      // list index B
  std::int32_t never_;         // list index B + 1
  double t0_ = 0, width_ = 0, inv_width_ = 0;
  std::int32_t current_ = 0;   // index of the current bucket
  // The bucket whose list is in event order: the current one once earliest() has sorted it, -1
  // before. Events filed into it later go to their place in that order (insert_in_order()).
  std::int32_t sorted_ = -1;

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
  for (;;) {
    if (current_ < n_buckets_) {
      if (node_[head(current_)].next != end()) break;
      ++current_;
      continue;
    }
    if (node_[head(overflow_)].next == end()) return kNone;  // only "never" events remain
    start_new_window();
  }
  // The current bucket is put in event order once, when it is reached (insertion sort: it holds
  // a few events), and kept so; its first event is then the earliest. Against a scan for the
  // earliest at every pop (2.8 events per scan at N = 96993, each a comparison at random):
  // cachegrind, N = 1e5 early, +32 instructions and 1.27 fewer mispredicts per collision;
  // alternating runs, N = 96993 early x0.956 (8 of 9 pairs below 1), 1e4 after 1.2e6 collisions
  // x0.968 (7 of 9), 96993 after 8e6 x0.988, 1e6 x1.003, 1e7 x0.984. Same event order.
  const std::int32_t h = head(current_);
  if (sorted_ != current_) {
    std::int32_t j = node_[h].next;
    node_[h].next = end();
    while (j != end()) {
      const std::int32_t next = node_[j].next;
      soon(static_cast<std::uint32_t>(j));
      insert_in_order(j, h);
      j = next;
    }
    sorted_ = current_;
  }
  return static_cast<std::uint32_t>(node_[h].next);
}

}  // namespace ggsim
