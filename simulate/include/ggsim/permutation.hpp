#pragma once
// Reordering per-particle arrays in place (the engine renumbers particles in space, engine.hpp):
// no second copy of an array is made, so a renumbering needs only its order (and the engine's
// inverse of it), 8 bytes per particle, plus one bit per particle here.
#include <cstdint>
#include <utility>
#include <vector>

namespace ggsim {

// a[k] becomes the old a[order[k]] for every k (order is a permutation), cycle by cycle.
template <class T, class Alloc>
void permute_in_place(std::vector<T, Alloc>& a, const std::vector<std::uint32_t>& order) {
  std::vector<bool> done(a.size(), false);
  for (std::size_t start = 0; start < a.size(); ++start) {
    if (done[start]) continue;
    T carried = std::move(a[start]);
    std::size_t k = start;
    for (;;) {
      done[k] = true;
      const std::size_t from = order[k];
      if (from == start) break;
      a[k] = std::move(a[from]);
      k = from;
    }
    a[k] = std::move(carried);
  }
}

}  // namespace ggsim
