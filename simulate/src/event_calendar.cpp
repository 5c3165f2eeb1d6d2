#include "ggsim/event_calendar.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace ggsim {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
}

EventCalendar::EventCalendar(std::size_t n) : n_particles_(static_cast<std::int32_t>(n)) {
  std::int32_t b = 16;
  // One bucket per four particles: as fast as one per particle (cachegrind, N = 1e5), a quarter
  // of the memory.
  while (static_cast<std::size_t>(b) < n / 4) b *= 2;
  n_buckets_ = b;
  overflow_ = b;
  never_ = b + 1;
  node_.resize(n + static_cast<std::size_t>(b) + 3);
  for (std::int32_t l = 0; l <= never_; ++l) node_[head(l)].next = end();
  current_ = b;  // no window yet: everything waits in the overflow list until the first pop
}

void EventCalendar::unlink(std::uint32_t i) {
  Node& n = node_[i];
  if (n.prev == kUnlinked) return;
  node_[n.prev].next = n.next;
  node_[n.next].prev = n.prev;
  n.prev = kUnlinked;
}

void EventCalendar::insert_in_order(std::int32_t i, std::int32_t after_node) {
  std::int32_t at = after_node;
  while (node_[at].next != end() && precedes(node_[at].next, i)) at = node_[at].next;
  link_after(static_cast<std::uint32_t>(i), at);
}

std::int32_t EventCalendar::bucket_for(double t) const {
  if (!(t < kInf)) return never_;
  if (current_ == n_buckets_) return overflow_;
  // Events before the current bucket (a collision "now" scheduled late in the bucket's span)
  // belong to the current one; events beyond the window wait in the overflow list, which is
  // list B. Clamped without a branch: whether an event falls beyond the window is random.
  // Clamped before it is rounded, so the rounding is a truncation (k >= 0): std::floor without
  // SSE4.1 is a dozen instructions and a branch.
  const double k = (t - t0_) * inv_width_;
#if defined(__SSE2__)
  // GCC 12 turns std::min here into a branch.
  const __m128d clamped = _mm_min_sd(_mm_max_sd(_mm_set_sd(k), _mm_set_sd(current_)), _mm_set_sd(overflow_));
  return _mm_cvttsd_si32(clamped);
#else
  return static_cast<std::int32_t>(std::min(std::max(k, static_cast<double>(current_)), static_cast<double>(overflow_)));
#endif
}

void EventCalendar::schedule(std::uint32_t i, double t) {
  unlink(i);
  node_[i].time = t;
  const std::int32_t b = bucket_for(t);
  if (b == sorted_) insert_in_order(static_cast<std::int32_t>(i), head(b));
  else link(i, b);
}

void EventCalendar::prefetch_filing(double t) const { __builtin_prefetch(&node_[head(bucket_for(t))]); }

void EventCalendar::restart_cursor() {
  cursor_.list = current_ + kSkip;
  cursor_.node = cursor_.list < n_buckets_ ? node_[head(cursor_.list)].next : end();
}

void EventCalendar::refile() {
  for (std::int32_t l = 0; l <= never_; ++l) node_[head(l)].next = end();
  sorted_ = -1;
  // Same window: every event goes back to the list it was in (bucket_for(time)).
  for (std::size_t i = 0; i < static_cast<std::size_t>(n_particles_); ++i) {
    if (node_[i].prev == kUnlinked) continue;
    link(static_cast<std::uint32_t>(i), bucket_for(node_[i].time));
  }
  restart_cursor();
}

void EventCalendar::start_new_window() {
  // The window is used up: every pending event waits in the overflow list (or never happens).
  // The nodes are read in memory order, not along the list, so both passes stream.
  const auto waiting = [](const Node& n) { return n.prev != kUnlinked && n.time < kInf; };
  t0_ += width_ * n_buckets_;
  double t_min = kInf;
  scratch_.clear();
  const auto n = static_cast<std::size_t>(n_particles_);
  const std::size_t stride = std::max<std::size_t>(1, n / kSample);
  for (std::size_t i = 0; i < n; ++i) {
    if (!waiting(node_[i])) continue;
    t_min = std::min(t_min, node_[i].time);
    if (i % stride == 0) scratch_.push_back(node_[i].time);
  }
  // Skip empty stretches of time (a cold gas): start at the earliest pending event.
  t0_ = std::max(t0_, t_min);
  if (scratch_.empty()) scratch_.push_back(t_min);
  for (double& t : scratch_) t -= t0_;
  auto mid = scratch_.begin() + static_cast<std::ptrdiff_t>(scratch_.size() / 2);
  std::nth_element(scratch_.begin(), mid, scratch_.end());
  double median = *mid;
  if (!(median > 0)) median = std::max(t0_, 1.0) * 1e-12;  // all events at the same instant
  width_ = kSpan * median / n_buckets_;
  if (!(t0_ + width_ > t0_)) width_ = std::max(std::abs(t0_), 1.0) * 1e-15;  // beyond double resolution
  inv_width_ = 1 / width_;
  current_ = 0;
  sorted_ = -1;
  node_[head(overflow_)].next = end();
  for (std::size_t i = 0; i < n; ++i)
    if (waiting(node_[i])) link(static_cast<std::uint32_t>(i), bucket_for(node_[i].time));
  restart_cursor();
}

}  // namespace ggsim
