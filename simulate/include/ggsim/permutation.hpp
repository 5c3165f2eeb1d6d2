#pragma once
// Reordering per-particle arrays in place (the engine renumbers particles in space, engine.hpp):
// no second copy of an array is made, and the new numbers are kept in the cell grid's list links
// while the arrays move (cell_grid.hpp), so a renumbering adds one bit per particle, here.
#include <cstddef>
#include <iterator>
#include <utility>
#include <vector>

namespace ggsim {

// a[rank(k)] becomes the old a[k] for every k (rank is a permutation), cycle by cycle. rank(k)
// is asked while a[k] still holds its old element, so the ranks may be stored in a itself.
template <class Array, class Rank>
void permute_by_rank(Array&& a, const Rank& rank) {
  std::vector<bool> done(std::size(a), false);
  for (std::size_t start = 0; start < done.size(); ++start) {
    if (done[start]) continue;
    done[start] = true;
    std::size_t to = rank(start);
    auto carried = std::move(a[start]);
    while (to != start) {
      const std::size_t next = rank(to);
      done[to] = true;
      std::swap(carried, a[to]);
      to = next;
    }
    a[start] = std::move(carried);
  }
}

}  // namespace ggsim
