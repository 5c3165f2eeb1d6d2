#pragma once
// Cells of shell centres.
//
// Each particle is confined to a shell: a sphere of radius skin/2 around a centre fixed when the
// particle last collided or left its shell (just ahead of it, engine.hpp). Two particles can
// touch only if their centres are closer than sigma + skin, so a particle needs to look for
// partners only among the centres in the 3^d cells around its own centre's cell (cells at least
// sigma + skin wide), and of those only at the ones within sigma + skin. The centres are stored
// with the cell links, so that test reads 16 bytes per candidate (2D), not a particle's cache
// line. Centres move only at collisions and shell exits; there are no cell-crossing events.
//
// A centre is kept in fixed point, 2^32 steps across the box in each direction (L/2^32 = 1.2e-7
// sigma at L = 512): an entry (centre, link, label) takes 16 bytes in 2D instead of 24, the
// difference of two centres wraps to the minimum image by itself (arithmetic modulo 2^32), and
// cells follow from integer products. The centre *is* the fixed-point value: every test and
// exit time uses it as decoded, so the dynamics stays exact; it only needs the particle inside
// its shell when the shell is made, which a step of at most 1% of the shell radius leaves intact
// (engine.hpp places the particle 0.98 radii from the centre).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#include <span>
#include <vector>

#include "gg/box.hpp"
#include "ggsim/hot_path.hpp"
#include "ggsim/huge_pages.hpp"
#include "ggsim/particles.hpp"
#include "ggsim/permutation.hpp"
#include "ggsim/prediction.hpp"
#include "ggsim/skin.hpp"
#include "ggsim/z_order.hpp"

namespace ggsim {

// How the cells around a point are visited: every particle once, by its number; or (for the
// engine's search) every particle and up to two empty places per cell, by slot, so that the
// visit of a cell does not end after a count of particles no branch predictor can guess (see
// visit()).
enum class Visit { kParticles, kWithEmptyPlaces };

template <int D>
class CellGrid {
 public:
  // Where a particle's entry is kept: particle p's entry is the (p + 1)-th of the array, after the
  // sentinel that an empty place reads, and its slot is its offset in bytes. The lists link
  // slots, so following a link is one load with no index arithmetic, and the slot of the
  // sentinel is 0. Against links by entry number, which took a copy and a shift per place, and
  // with distance2()'s difference taken the other way round: 12 instead of 15 instructions per
  // place (N = 1e5: 3929 -> 3731 instructions per collision, cachegrind; the time x0.99, see
  // simulate/PERFORMANCE.md). Entry numbers against particle numbers with -1 for the end: 3200 -> 3130.
  using Slot = std::uint32_t;
  static constexpr Slot kEmptySlot = 0;  // what an empty place is reported as (its centre means nothing)
  static std::uint32_t particle(Slot s) { return s / kEntryBytes - 1; }
  static Slot slot(std::uint32_t p) { return (p + 1) * kEntryBytes; }
  // The address of slot s's particle's element in an owner's per-particle array, for a prefetch:
  // one lea when an element is a whole number of entries long (a 2D record is four), instead of
  // undoing the slot (shift, subtraction, shift) after clamping an empty place to particle 0. An
  // empty place (slot 0) gives the address one element before the array, which only a prefetch
  // may use (a prefetch never faults). The look-ahead's fetches by slot, N = 96993, the first 3e5
  // collisions: 3664 -> 3545 instructions per collision, as many branches (cachegrind).
  template <class T>
  static const void* element_address(const T* array, Slot s) {
    static_assert(sizeof(T) % kEntryBytes == 0, "use particle(s) for elements that are not whole entries");
    const std::uintptr_t first = reinterpret_cast<std::uintptr_t>(array);
    return reinterpret_cast<const void*>(first + std::uintptr_t{s} * (sizeof(T) / kEntryBytes) - sizeof(T));
  }
  // Particles a grid can hold: every slot fits in 32 bits (2^28 - 1 in 2D, whose engine would
  // take ~30 GB, and more in 1D: kMaxParticles, particles.hpp; 2.1e8 in 3D).
  static constexpr std::size_t max_particles() { return 0xffffffffu / kEntryBytes; }
  // A shell centre in fixed point: coordinate k is code[k] * L[k] / 2^32.
  using Code = std::array<std::uint32_t, D>;
  static constexpr double kParticlesPerCell = 1.0;  // at least, on average
  // Cells around a point, and the places for_each_near_inner passes on before any loop: the
  // first three of every cell (two in 3D, where three would be 81 places). In a cluster a cell
  // holds a third particle about as often as not, and a loop looking for it mispredicts its end:
  // a clustered gas (N = 2e4 after 2.5e6 collisions, alternating runs, medians of 11) 674 -> 634
  // ns per collision with three places instead of two; the early, dilute gas unchanged (637 vs
  // 636 ns, medians of 15) for 380 more instructions per collision, spent on empty places.
  static constexpr std::size_t kAround = D == 1 ? 3 : D == 2 ? 9 : 27;
  static constexpr int kFixedPlaces = D == 3 ? 2 : 3;
  static constexpr std::size_t kFirstPlaces = kFixedPlaces * kAround;

  // Cells at least `min_width` wide tiling the box; the widest such tiling is used, so the
  // skin (width - sigma) is as large as the box allows. The cells are widened where needed to
  // hold a particle on average, so the list heads cost at most 4 bytes per particle and the cell
  // count follows N, not the volume. At rho = 0.37, skin 0.7 the cells are the reach wide (1.7,
  // 1.07 particles each): against cells holding 1.5 (2.0 wide), 4% less time per collision in
  // the early gas and 10% less in the clustered one (N = 1e5, alternating runs, medians of 5 and
  // 3), fewer third particles in a cell to look for (visit()).
  CellGrid(const gg::Box<D>& box, double min_width, std::size_t n_particles) : entry_(entries_for(n_particles)) {
    entry_[kEmptySlot] = Entry{Code{}, kEmptySlot, 0};  // what an empty place reads
    for (int k = 0; k < D; ++k) step_[k] = std::ldexp(box.L[k], -32), inv_step_[k] = std::ldexp(box.inv_L[k], 32);
#if defined(__SSE2__)
    if constexpr (D == 2) step2_ = _mm_set_pd(step_[1], step_[0]);
#endif
    const double n = static_cast<double>(std::max<std::size_t>(n_particles, 1));
    min_width = std::max(min_width, std::pow(kParticlesPerCell * box.volume() / n, 1.0 / D));
    std::size_t total = 1;
    for (int k = 0; k < D; ++k) {
      n_[k] = std::max<std::int32_t>(1, static_cast<std::int32_t>(std::floor(box.L[k] / min_width)));
      width_[k] = box.L[k] / n_[k];
      inner_count_[k] = static_cast<std::uint32_t>(std::max(n_[k] - 4, 0));
      stride_[k] = static_cast<std::int32_t>(total);
      total *= static_cast<std::size_t>(n_[k]);
    }
    head_.assign(total, kEmptySlot);
    // Offsets of the 3^d cells around an inner cell, in the order for_each_near visits them.
    for (std::size_t m = 0; m < inner_offset_.size(); ++m) {
      std::int32_t off = 0;
      for (int k = 0, rest = static_cast<int>(m); k < D; ++k, rest /= 3) off += (rest % 3 - 1) * stride_[k];
      inner_offset_[m] = off;
    }
  }

  std::int32_t cells_along(int k) const { return n_[k]; }
  double min_cell_width() const {
    double w = width_[0];
    for (int k = 1; k < D; ++k) w = std::min(w, width_[k]);
    return w;
  }

  // Largest distance between a point and its fixed-point code (half a step along each axis).
  double code_error() const {
    double s = 0;
    for (int k = 0; k < D; ++k) s += 0.25 * step_[k] * step_[k];
    return std::sqrt(s);
  }

  // The nearest code to x (x within one box length of [0, L); lrint is one instruction without
  // errno, llround a library call).
  Code encode(const Vec<D>& x) const {
    Code c;
    for (int k = 0; k < D; ++k)
      c[k] = static_cast<std::uint32_t>(static_cast<std::uint64_t>(std::lrint(x[k] * inv_step_[k])));
    return c;
  }
  Vec<D> decode(const Code& c) const {
    Vec<D> x;
    for (int k = 0; k < D; ++k) x[k] = c[k] * step_[k];
    return x;
  }
  // Squared minimum-image distance between two centres.
  double distance2(const Code& a, const Code& b) const {
#if defined(__SSE2__)
    if constexpr (D == 2) {
      // Both axes at once, the same arithmetic as the loop below: the search's inner test in 7
      // instructions instead of 12 (N = 1e5: 3980 -> 3520 instructions per collision). b - a,
      // not a - b: the fresh load of b takes the difference, so a needs no copy; the high half
      // by pshufd, which leaves d as it is (unpckhpd would need a copy too).
      const __m128i ca = _mm_loadl_epi64(reinterpret_cast<const __m128i*>(a.data()));
      const __m128i cb = _mm_loadl_epi64(reinterpret_cast<const __m128i*>(b.data()));
      __m128d d = _mm_mul_pd(_mm_cvtepi32_pd(_mm_sub_epi32(cb, ca)), step2_);
      d = _mm_mul_pd(d, d);
      return _mm_cvtsd_f64(_mm_add_sd(d, _mm_castsi128_pd(_mm_shuffle_epi32(_mm_castpd_si128(d), 0xee))));
    }
#endif
    double s = 0;
    for (int k = 0; k < D; ++k) {
      const double d = static_cast<std::int32_t>(b[k] - a[k]) * step_[k];
      s += d * d;
    }
    return s;
  }

  std::int32_t cell_of(const Code& c) const {
    std::int32_t cell = 0;
    const Index idx = coordinates(c);
    for (int k = 0; k < D; ++k) cell += idx[k] * stride_[k];
    return cell;
  }

  const Code& code(std::uint32_t p) const { return entry(p).centre; }
  const Code& code_in(Slot s) const { return at(s).centre; }
  // Starts fetching particle p's entry (its centre, link and label).
  void prefetch(std::uint32_t p) const { __builtin_prefetch(&entry(p)); }
  Vec<D> centre(std::uint32_t p) const { return decode(entry(p).centre); }
  // A number the owner keeps with particle p (the engine: p's number in the start). It is kept
  // in p's entry (4 of its 16 bytes in 2D), so it moves with p when particles are renumbered.
  std::uint32_t label(std::uint32_t p) const { return entry(p).label; }

  // The lists as they stand (checkpoints), and putting them back: the order within a cell
  // decides which of two exactly equal collision times a particle keeps. Outside the grid a
  // link is a particle number, -1 for the end of a list.
  std::vector<std::int32_t> heads() const {
    std::vector<std::int32_t> v(head_.size());
    for (std::size_t c = 0; c < head_.size(); ++c) v[c] = static_cast<std::int32_t>(particle(head_[c]));
    return v;
  }
  std::vector<std::int32_t> links() const {
    std::vector<std::int32_t> v(size());
    for (std::size_t p = 0; p < size(); ++p) v[p] = static_cast<std::int32_t>(particle(entry(p).next));
    return v;
  }
  void restore(const std::vector<std::int32_t>& heads, const std::vector<std::int32_t>& links,
               const std::vector<Vec<D>>& centres, const std::vector<std::uint32_t>& labels) {
    head_.resize(heads.size());
    for (std::size_t c = 0; c < heads.size(); ++c) head_[c] = slot(static_cast<std::uint32_t>(heads[c]));
    // Centres were saved decoded; encoding gives back the same codes (an error of 2^-52 relative
    // is far below half a step).
    for (std::size_t p = 0; p < centres.size(); ++p) entry(p) = Entry{encode(centres[p]), slot(static_cast<std::uint32_t>(links[p])), labels[p]};
  }

  // Renumbers the particles cell by cell, the cells in Z-order (z_order.hpp), each cell in list
  // order. The new numbers (ranks, old -> new) are kept in the entries' links meanwhile, since
  // the lists are rebuilt afterwards anyway, so no per-particle array is added. reorder(rank),
  // with rank(k) the new number of old particle k, lets the owner move its own arrays (the grid
  // is still in the old numbering then); the entries follow, and the lists are rebuilt.
  template <class F>
  void renumber_in_cell_order(F&& reorder) {
    std::uint32_t rank = 0;
    for_each_cell_in_z_order([&](std::int32_t cell) {
      for (Slot s = head_[cell]; s != kEmptySlot;) {
        const Slot next = at(s).next;
        at(s).next = rank++;
        s = next;
      }
    });
    const auto rank_of = [this](std::size_t k) { return entry(k).next; };
    reorder(rank_of);
    permute_by_rank(particle_entries(), rank_of);
    head_.assign(head_.size(), kEmptySlot);
    for (std::size_t p = size(); p-- > 0;) link(static_cast<std::uint32_t>(p), cell_of(entry(p).centre));
  }

  // Particle p (not yet in the grid) with its shell centred at x.
  void insert(std::uint32_t p, const Vec<D>& x, std::uint32_t label = 0) {
    entry(p).centre = encode(x);
    entry(p).label = label;
    link(p, cell_of(entry(p).centre));
  }

  // Particle p's shell is now centred at x; its lists change only if the cell does.
  void move(std::uint32_t p, const Vec<D>& x) {
    const Code c = encode(x);
    const std::int32_t from = cell_of(entry(p).centre), to = cell_of(c);
    entry(p).centre = c;
    if (from == to) return;
    unlink(p, from);
    link(p, to);
  }

  // Particle p leaves the grid (it merged into another, contact/aggregate.hpp); its entry stays unused.
  void remove(std::uint32_t p) { unlink(p, cell_of(entry(p).centre)); }

  // For a search around particle p's centre that tests nothing but distances: until unhide(p),
  // p itself and the empty places (the sentinel entry) are reported at the point of the box
  // farthest from p's centre (half a box away along every axis), out of any reach shorter than
  // sqrt(hidden_distance2()). Saves the search two tests per candidate (N = 1e5: 420 of 4400
  // instructions per collision).
  void hide_for_search(std::uint32_t p) {
    hidden_centre_ = entry(p).centre;
    Code far = hidden_centre_;
    for (int k = 0; k < D; ++k) far[k] += 0x80000000u;
    entry_[kEmptySlot].centre = entry(p).centre = far;
  }
  void unhide(std::uint32_t p) { entry(p).centre = hidden_centre_; }
  double hidden_distance2() const {
    double s = 0;
    for (int k = 0; k < D; ++k) {
      const double half_box = std::ldexp(step_[k], 31);  // 2^31 steps: L/2
      s += half_box * half_box;
    }
    return s;
  }

  // True if the cells around x and their own neighbours lie away from the box edges: particles
  // there are no more than a shell radius from their centres, so none of them has wrapped and
  // separations need no minimum image.
  bool far_from_edges(const Code& x) const { return away_from_edges(coordinates(x)); }

  // Fetching for a search around x soon (the engine's look-ahead), in steps: the list heads of
  // the cells around x, which returns the cell holding x (-1 near the box edges, where nothing is
  // fetched); then, with the heads at hand, the entries in the given place of every list of that
  // cell's neighbourhood (place 1 the first entries, 2, with those at hand, the second ones),
  // each of whose slots (kEmptySlot where a list is shorter) goes to f. Always inlined
  // (hot_path.hpp).
  GG_ALWAYS_INLINE std::int32_t prefetch_heads_around(const Code& x) const {
    const std::int32_t c = inner_cell(x);
    if (c < 0) return c;
    // The cells of a row along axis 0 are adjacent in memory: the line of the middle one is the
    // line of one of its neighbours.
    for (std::size_t m = 0; m < kAround; m += 3) {
      __builtin_prefetch(&head_[c + inner_offset_[m]]);
      __builtin_prefetch(&head_[c + inner_offset_[m + 2]]);
    }
    return c;
  }
  template <int Place, class F>
  GG_ALWAYS_INLINE void prefetch_entries_around(std::int32_t cell, F&& f) const {
    static_assert(Place >= 1);
    if (cell < 0) return;
    for (std::size_t m = 0; m < kAround; ++m) {
      Slot s = head_[cell + inner_offset_[m]];
      for (int k = 1; k < Place; ++k) s = at(s).next;
      __builtin_prefetch(&at(s));
      f(s);
    }
  }

  // Calls f(j, code of j's centre) for every particle j whose centre lies in the cells around the
  // one holding x (each cell once). With Visit::kWithEmptyPlaces (the engine's search) f(slot,
  // code) instead, for every particle's slot and for empty places (kEmptySlot).
  template <Visit V = Visit::kParticles, class F>
  void for_each_near(const Code& x, F&& f) const {
    const Around around = cells_around(coordinates(x));
    std::array<int, D> m{};
    for (;;) {
      std::int32_t cell = 0;
      for (int k = 0; k < D; ++k) cell += around.offset[k][m[k]];
      visit<V>(cell, f);
      if (!next_combination(m, around)) break;
    }
  }

  // Lees-Edwards images (boundary/sheared.hpp): whether x lies in a cell of the first or
  // the last row along the gradient axis (axis 1), the only cells a pair through the sliding
  // boundary can have its centres in (cells are at least a reach wide).
  bool in_sheared_row(const Code& x) const {
    const std::int32_t row = coordinates(x)[1];
    return row == 0 || row == n_[1] - 1;
  }
  // For a search around x in a sheared box: f(slot, code) for the cells around x that do not lie
  // across the gradient axis's edge, as for_each_near<kWithEmptyPlaces> visits them, and, if x's cell
  // is in a sheared row, across(slot, code) for the cells of the row across that edge (its other
  // axes' neighbours) that overlap [from, from + width) along axis 0, a range that wraps (every cell
  // of the row once if it spans the box). Needs 3 rows or more.
  template <class F, class Across>
  void for_each_near_sheared(const Code& x, double from, double width, F&& f, Across&& across) const {
    const Index c = coordinates(x);
    const std::int32_t across_row = c[1] == 0 ? n_[1] - 1 : c[1] == n_[1] - 1 ? 0 : -1;
    const Around around = cells_around(c);
    // The cells along axis 0: first, and how many (cell i + k wrapped).
    const auto first = static_cast<std::int64_t>(std::floor(from / width_[0]));
    const auto last = static_cast<std::int64_t>(std::floor((from + width) / width_[0]));
    const std::int32_t count = static_cast<std::int32_t>(std::min<std::int64_t>(last - first + 1, n_[0]));
    const auto start = static_cast<std::int32_t>(((first % n_[0]) + n_[0]) % n_[0]);
    std::array<int, D> m{};
    for (;;) {
      if (around.index[1][m[1]] != across_row) {
        std::int32_t cell = 0;
        for (int k = 0; k < D; ++k) cell += around.offset[k][m[k]];
        visit<Visit::kWithEmptyPlaces>(cell, f);
      } else if (m[0] == 0) {  // the range along axis 0, once per choice of the other axes
        std::int32_t rest = 0;
        for (int k = 1; k < D; ++k) rest += around.offset[k][m[k]];
        for (std::int32_t k = 0, i = start; k < count; ++k, i = i + 1 == n_[0] ? 0 : i + 1)
          visit<Visit::kWithEmptyPlaces>(rest + i * stride_[0], across);
      }
      if (!next_combination(m, around)) break;
    }
  }
  // Minimum-image distance along axis 0 between two codes.
  double distance_along_0(const Code& a, const Code& b) const {
    return std::abs(static_cast<double>(static_cast<std::int32_t>(b[0] - a[0])) * step_[0]);
  }
  // Squared minimum-image distance between two centres over every axis but axis 0 (the sliding one).
  double distance2_across(const Code& a, const Code& b) const {
    double s = 0;
    for (int k = 1; k < D; ++k) {
      const double d = static_cast<std::int32_t>(b[k] - a[k]) * step_[k];
      s += d * d;
    }
    return s;
  }

  // The engine's search for x with far_from_edges(x): the same as for_each_near<kWithEmptyPlaces>
  // in another order, with fixed offsets and no wrapping (loops unrolled: the end of a loop of
  // 3^d cells is mispredicted once per search). The cells are visited level by level, every
  // cell's first place, then every second place, and so on to kFixedPlaces, then the rest: the
  // reads of the 3^d lists then overlap instead of following one list after the other.
  // `f(slot, centre)` is called for the first kFixedPlaces places of every cell (kFirstPlaces
  // calls: a caller collecting them needs no room check), `rest(slot, centre)` for the particles
  // of a cell after them.
  template <class F, class Rest>
  void for_each_near_inner(const Code& x, F&& f, Rest&& rest) const {
    const std::int32_t c = cell_of(x);
    std::array<Slot, kAround> place;
    GG_UNROLL_CELLS
    for (std::size_t m = 0; m < kAround; ++m) place[m] = head_[c + inner_offset_[m]];
    for (int level = 0; level < kFixedPlaces; ++level) {
      GG_UNROLL_CELLS
      for (std::size_t m = 0; m < kAround; ++m) {
        const Entry& e = at(place[m]);
        f(place[m], e.centre);
        place[m] = e.next;
      }
    }
    GG_UNROLL_CELLS
    for (std::size_t m = 0; m < kAround; ++m)
      for (Slot s = place[m]; s != kEmptySlot; s = at(s).next) rest(s, at(s).centre);
  }

 private:
  using Index = std::array<std::int32_t, D>;

  // The cells around a cell, per dimension: `count` of them (3, or fewer in a grid of fewer than
  // 3 cells, so that no cell is visited twice), their indices and offsets into the flat array.
  struct Around {
    std::array<std::array<std::int32_t, 3>, D> index, offset;
    std::array<int, D> count;
  };

  // Cell coordinates of a code: floor(code n / 2^32), exact.
  Index coordinates(const Code& c) const {
    Index idx;
    for (int k = 0; k < D; ++k) idx[k] = static_cast<std::int32_t>((std::uint64_t{c[k]} * static_cast<std::uint64_t>(n_[k])) >> 32);
    return idx;
  }

  // 2 <= c[k] <= n - 3 along every axis, as one unsigned comparison per axis and no branch
  // between them (the branches of the two-sided test were mispredicted 0.7 times per collision
  // in a cooling gas: cachegrind, N = 96993, the first 8.5e6 collisions).
  bool away_from_edges(const Index& c) const {
    bool away = true;
    for (int k = 0; k < D; ++k) away &= static_cast<std::uint32_t>(c[k] - 2) < inner_count_[k];
    return away;
  }

  // The cell holding x if far_from_edges(x), else -1 (the cell coordinates computed once).
  std::int32_t inner_cell(const Code& x) const {
    const Index c = coordinates(x);
    if (!away_from_edges(c)) return -1;
    std::int32_t cell = 0;
    for (int k = 0; k < D; ++k) cell += c[k] * stride_[k];
    return cell;
  }

  Around cells_around(const Index& c) const {
    Around a;
    for (int k = 0; k < D; ++k) {
      const bool wide = n_[k] >= 3;
      a.count[k] = wide ? 3 : n_[k];
      for (int m = 0; m < a.count[k]; ++m) {
        std::int32_t i = wide ? c[k] - 1 + m : m;
        if (i < 0) i += n_[k]; else if (i >= n_[k]) i -= n_[k];
        a.index[k][m] = i;
        a.offset[k][m] = i * stride_[k];
      }
    }
    return a;
  }

  // Odometer over the per-dimension choices; false after the last combination.
  static bool next_combination(std::array<int, D>& m, const Around& a) {
    int k = 0;
    while (k < D && ++m[k] == a.count[k]) m[k] = 0, ++k;
    return k < D;
  }

  // Calls take(cell) for every cell in Z-order: blocks of 2^d cells, then of 4^d, ..., walked
  // recursively, the parts of a block in the order of their Z codes (axis 0 varying fastest),
  // whatever lies outside the grid skipped whole. (Decoding every code of the curve instead cost
  // ~300 instructions per cell at L = 512: 2.9e7 per renumbering, up to 190 per collision in a
  // window with one.) A much longer box is walked row by row.
  template <class F>
  void for_each_cell_in_z_order(F&& take) const {
    int bits = 0;
    while ((std::int64_t{1} << bits) < *std::max_element(n_.begin(), n_.end())) ++bits;
    if ((std::uint64_t{1} << (bits * D)) > (std::uint64_t{1} << D) * head_.size()) {
      for (std::size_t cell = 0; cell < head_.size(); ++cell) take(static_cast<std::int32_t>(cell));
      return;
    }
    walk_z_block(Index{}, std::int32_t{1} << bits, take);
  }

  // The cells of the block of `size`^d cells at `corner` (in cell coordinates), in Z-order.
  template <class F>
  GG_OFF_HOT_PATH void walk_z_block(const Index& corner, std::int32_t size, F& take) const {
    for (int k = 0; k < D; ++k)
      if (corner[k] >= n_[k]) return;
    if (size == 1) {
      std::int32_t cell = 0;
      for (int k = 0; k < D; ++k) cell += corner[k] * stride_[k];
      take(cell);
      return;
    }
    const std::int32_t half = size / 2;
    for (int part = 0; part < (1 << D); ++part) {
      Index c = corner;
      for (int k = 0; k < D; ++k) c[k] += (part >> k & 1) * half;
      walk_z_block(c, half, take);
    }
  }

  void link(std::uint32_t p, std::int32_t cell) {
    entry(p).next = head_[cell];
    head_[cell] = slot(p);
  }
  void unlink(std::uint32_t p, std::int32_t cell) {
    Slot* l = &head_[cell];
    while (*l != slot(p)) l = &at(*l).next;
    *l = entry(p).next;
  }

  // The particles of one cell. With empty places, the first two places of the list are passed
  // on whether they hold a particle or not (an empty one reads the sentinel entry, whose next is
  // empty again), and only a third particle and beyond is looked for in a loop: a cell holds
  // 0, 1, 2 or more particles at random (about 1 on average), and a loop over exactly its particles
  // mispredicts its end about once per cell. N = 1e5, rho = 0.37: 28 fewer mispredicted branches
  // per collision (24 -> 15 million over 3e5 collisions, cachegrind), 25% less time per
  // collision (alternating runs).
  template <Visit V, class F>
  void visit(std::int32_t cell, F& f) const {
    const auto report = [&](Slot s) {
      if constexpr (V == Visit::kWithEmptyPlaces) f(s, at(s).centre);
      else f(particle(s), at(s).centre);
    };
    Slot s = head_[cell];
    if constexpr (V == Visit::kWithEmptyPlaces) {
      const Slot second = at(s).next;
      report(s);
      report(second);
      s = at(second).next;
    }
    for (; s != kEmptySlot; s = at(s).next) report(s);
  }

  // A particle's shell centre and the next particle in its cell's list, side by side, and its
  // label.
  struct Entry {
    Code centre;
    Slot next;
    std::uint32_t label;
  };

  static constexpr std::uint32_t kEntryBytes = sizeof(Entry);
  // Entries for n particles and the sentinel, refused before anything is allocated beyond what
  // the engine holds (particles.hpp) or, in 3D, beyond what the slots reach.
  static std::size_t entries_for(std::size_t n) {
    require_engine_holds(n, std::min<std::uint64_t>(kMaxParticles, max_particles()));
    return n + 1;
  }
  // The entry in slot s, and particle j's entry.
  Entry& at(Slot s) { return *reinterpret_cast<Entry*>(reinterpret_cast<char*>(entry_.data()) + s); }
  const Entry& at(Slot s) const {
    return *reinterpret_cast<const Entry*>(reinterpret_cast<const char*>(entry_.data()) + s);
  }
  Entry& entry(std::size_t j) { return entry_[j + 1]; }
  const Entry& entry(std::size_t j) const { return entry_[j + 1]; }
  std::size_t size() const { return entry_.size() - 1; }
  std::span<Entry> particle_entries() { return std::span<Entry>(entry_).subspan(1); }

  std::array<std::int32_t, D> n_{}, stride_{};
  std::array<std::uint32_t, D> inner_count_{};  // cells along each axis that are away from its edges: n - 4
  std::array<std::int32_t, kAround> inner_offset_{};
  std::array<double, D> width_{};
  std::array<double, D> step_{}, inv_step_{};  // L / 2^32 and its inverse: one step of a code
#if defined(__SSE2__)
  __m128d step2_ = _mm_setzero_pd();  // step_ in a vector (2D)
#endif
  Code hidden_centre_{};  // the centre of the particle hidden for a search
  ParticleArray<Slot> head_;
  ParticleArray<Entry> entry_;  // the sentinel, then one entry per particle
};

}  // namespace ggsim
