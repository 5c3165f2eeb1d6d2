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

  // True if the cells around x and their own neighbours lie away from the box edges: particles
  // there are no more than a shell radius from their centres, so none of them has wrapped and
  // separations need no minimum image.
  bool far_from_edges(const Vec<D>& x) const {
    const Index c = coordinates(x);
    for (int k = 0; k < D; ++k)
      if (c[k] < 2 || c[k] > n_[k] - 3) return false;
    return true;
  }

  // Calls f(j) for every particle whose centre lies in the cells around the one holding x
  // (each cell once).
  template <class F>
  void for_each_near(const Vec<D>& x, F&& f) const {
    const Around around = cells_around(coordinates(x));
    std::array<int, D> m{};
    for (;;) {
      std::int32_t cell = 0;
      for (int k = 0; k < D; ++k) cell += around.offset[k][m[k]];
      visit(cell, f);
      if (!next_combination(m, around)) break;
    }
  }

  // The same, but only for the cells around new_x that were not around old_x: what a particle
  // whose centre moved from old_x to new_x has not yet looked at.
  template <class F>
  void for_each_newly_near(const Vec<D>& old_x, const Vec<D>& new_x, F&& f) const {
    const Index from = coordinates(old_x), to = coordinates(new_x);
    if (from == to) return;
    const Around around = cells_around(to);
    std::array<std::array<bool, 3>, D> seen;
    for (int k = 0; k < D; ++k)
      for (int m = 0; m < around.count[k]; ++m) {
        std::int32_t d = around.index[k][m] - from[k];
        if (d < 0) d = -d;
        seen[k][m] = n_[k] < 3 || d <= 1 || d == n_[k] - 1;  // periodic distance <= 1
      }
    std::array<int, D> m{};
    for (;;) {
      bool old_cell = true;
      std::int32_t cell = 0;
      for (int k = 0; k < D; ++k) old_cell = old_cell && seen[k][m[k]], cell += around.offset[k][m[k]];
      if (!old_cell) visit(cell, f);
      if (!next_combination(m, around)) break;
    }
  }

 private:
  using Index = std::array<std::int32_t, D>;

  // The cells around a cell, per dimension: `count` of them (3, or fewer in a grid of fewer than
  // 3 cells, so that no cell is visited twice), their indices and offsets into the flat array.
  struct Around {
    std::array<std::array<std::int32_t, 3>, D> index, offset;
    std::array<int, D> count;
  };

  Index coordinates(const Vec<D>& x) const {
    Index idx;
    for (int k = 0; k < D; ++k) {
      idx[k] = static_cast<std::int32_t>(x[k] * inv_width_[k]);
      if (idx[k] >= n_[k]) idx[k] = n_[k] - 1;
    }
    return idx;
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

  template <class F>
  void visit(std::int32_t cell, F& f) const {
    for (std::int32_t j = head_[cell]; j != kNil; j = next_[j]) f(static_cast<std::uint32_t>(j));
  }

  std::array<std::int32_t, D> n_{}, stride_{};
  std::array<double, D> width_{}, inv_width_{};
  std::vector<std::int32_t> head_, next_;
};

}  // namespace ggsim
