#pragma once
// Z-order (Morton order) of cells: interleaving the bits of the cell coordinates gives a curve
// that visits space block by block, so cells close in space are mostly close along it. Particles
// numbered along it are close in memory when they are close in space (initial_state.cpp sorts
// the start so; the engine renumbers along it as particles drift, CellGrid::for_each_cell_in_z_order).
#include <array>
#include <cstdint>

namespace ggsim {

inline constexpr int kZOrderBits = 60;  // bits of a key; D coordinates of 60 / D bits each

template <int D>
std::uint64_t z_order_key(const std::array<std::uint64_t, D>& c) {
  std::uint64_t z = 0;
  for (int k = 0; k < D; ++k)
    for (int b = 0; b < kZOrderBits / D; ++b) z |= ((c[k] >> b) & 1u) << (b * D + k);
  return z;
}

}  // namespace ggsim
