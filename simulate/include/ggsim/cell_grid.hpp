#pragma once
// Cells of shell centres.
//
// Each particle is confined to a shell: a sphere of radius skin/2 around a centre fixed when the
// particle last left its shell. Two particles can touch only if their centres are closer than
// sigma + skin, so a particle needs to look for partners only among the centres in the 3^d cells
// around its own centre's cell (cells at least sigma + skin wide). Centres move only when a
// particle leaves its shell; there are no cell-crossing events, and in a cold dense cluster,
// where particles collide often but hardly move, the grid is not touched at all.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "gg/box.hpp"
#include "ggsim/prediction.hpp"

namespace ggsim {

template <int D>
class CellGrid {
 public:
  static constexpr std::int32_t kNil = -1;

  // Cells at least `min_width` wide tiling the box; the widest such tiling is used, so the
  // skin (width - sigma) is as large as the box allows. In a dilute gas the cells are widened
  // to hold about two particles each, so the cell count follows N, not the volume.
  CellGrid(const gg::Box<D>& box, double min_width, std::size_t n_particles) : next_(n_particles, kNil) {
    const double per_two = std::pow(box.volume() / (2.0 * static_cast<double>(std::max<std::size_t>(n_particles, 1))),
                                    1.0 / D);
    min_width = std::max(min_width, per_two);
    std::size_t total = 1;
    for (int k = 0; k < D; ++k) {
      n_[k] = std::max<std::int32_t>(1, static_cast<std::int32_t>(std::floor(box.L[k] / min_width)));
      width_[k] = box.L[k] / n_[k];
      inv_width_[k] = 1.0 / width_[k];
      stride_[k] = static_cast<std::int32_t>(total);
      total *= static_cast<std::size_t>(n_[k]);
    }
    head_.assign(total, kNil);
    build_neighbourhood();
  }

  double min_cell_width() const {
    double w = width_[0];
    for (int k = 1; k < D; ++k) w = std::min(w, width_[k]);
    return w;
  }

  std::int32_t cell_of(const Vec<D>& x) const {
    std::int32_t c = 0;
    for (int k = 0; k < D; ++k) {
      auto i = static_cast<std::int32_t>(x[k] * inv_width_[k]);
      if (i >= n_[k]) i = n_[k] - 1;  // x just below L rounds up
      c += i * stride_[k];
    }
    return c;
  }

  // The lists as they stand (checkpoints), and putting them back.
  const std::vector<std::int32_t>& heads() const { return head_; }
  const std::vector<std::int32_t>& links() const { return next_; }
  void restore(const std::vector<std::int32_t>& heads, const std::vector<std::int32_t>& links) {
    head_ = heads;
    next_ = links;
  }

  void insert(std::uint32_t p, std::int32_t cell) {
    next_[p] = head_[cell];
    head_[cell] = static_cast<std::int32_t>(p);
  }

  void remove(std::uint32_t p, std::int32_t cell) {
    std::int32_t* link = &head_[cell];
    while (*link != static_cast<std::int32_t>(p)) link = &next_[*link];
    *link = next_[p];
  }

  // Calls f(j) for every particle whose centre lies in the cells around the one holding x
  // (each cell once).
  template <class F>
  void for_each_near(const Vec<D>& x, F&& f) const {
    const auto idx = coordinates(x);
    for (const auto& off : offsets_) visit(neighbour(idx, off), f);
  }

  // The same, but only for the cells around new_x that were not around old_x: what a particle
  // whose centre moved from old_x to new_x has not yet looked at.
  template <class F>
  void for_each_newly_near(const Vec<D>& old_x, const Vec<D>& new_x, F&& f) const {
    const auto from = coordinates(old_x), to = coordinates(new_x);
    if (from == to) return;
    for (const auto& off : offsets_) {
      const auto c = neighbour(to, off);
      bool seen = true;
      for (int k = 0; k < D && seen; ++k) {
        std::int32_t d = c[k] - from[k];
        if (d < 0) d = -d;
        seen = n_[k] < 3 || d <= 1 || d == n_[k] - 1;  // periodic distance <= 1
      }
      if (!seen) visit(c, f);
    }
  }

 private:
  using Index = std::array<std::int32_t, D>;

  Index coordinates(const Vec<D>& x) const {
    Index idx;
    for (int k = 0; k < D; ++k) {
      idx[k] = static_cast<std::int32_t>(x[k] * inv_width_[k]);
      if (idx[k] >= n_[k]) idx[k] = n_[k] - 1;
    }
    return idx;
  }

  Index neighbour(const Index& idx, const Index& off) const {
    Index c;
    for (int k = 0; k < D; ++k) {
      std::int32_t i = idx[k] + off[k];
      if (i < 0) i += n_[k]; else if (i >= n_[k]) i -= n_[k];
      c[k] = i;
    }
    return c;
  }

  template <class F>
  void visit(const Index& c, F& f) const {
    std::int32_t cell = 0;
    for (int k = 0; k < D; ++k) cell += c[k] * stride_[k];
    for (std::int32_t j = head_[cell]; j != kNil; j = next_[j]) f(static_cast<std::uint32_t>(j));
  }

  // Offsets -1, 0, +1 per dimension, fewer where the grid has fewer than 3 cells, so that no
  // cell is visited twice in a small box.
  void build_neighbourhood() {
    offsets_.clear();
    std::array<std::int32_t, D> off{};
    std::array<std::int32_t, D> lo, hi;
    for (int k = 0; k < D; ++k) {
      lo[k] = n_[k] >= 3 ? -1 : 0;
      hi[k] = n_[k] >= 3 ? 1 : n_[k] - 1;
      off[k] = lo[k];
    }
    for (;;) {
      offsets_.push_back(off);
      int k = 0;
      while (k < D && ++off[k] > hi[k]) off[k] = lo[k], ++k;
      if (k == D) break;
    }
  }

  std::array<std::int32_t, D> n_{}, stride_{};
  std::array<double, D> width_{}, inv_width_{};
  std::vector<std::int32_t> head_, next_;
  std::vector<std::array<std::int32_t, D>> offsets_;
};

}  // namespace ggsim
