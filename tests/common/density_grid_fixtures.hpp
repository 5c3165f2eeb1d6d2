#pragma once
// Configurations with hand-known structure on a density grid, for the tests of the grid and of the
// structural analyses built on it.
#include <cmath>
#include <cstdint>
#include <functional>
#include <random>
#include <vector>

#include "gg/density_grid.hpp"

namespace gg::test {

using Cell = std::vector<int>;  // multi-index, axis 0 first (row-major: axis 0 slowest)

// `per_cell(cell)` particles in every cell of a box with `n` cells of spacing `h` per side, placed on
// the cell's diagonal strictly inside it (never on an edge, so the owning cell is unambiguous).
inline std::vector<double> fill_cells(const std::vector<int>& n, const std::vector<double>& h,
                                      const std::function<int(const Cell&)>& per_cell) {
  const int d = static_cast<int>(n.size());
  std::vector<double> x;
  Cell idx(d, 0);
  std::size_t cells = 1;
  for (int v : n) cells *= static_cast<std::size_t>(v);
  for (std::size_t c = 0; c < cells; ++c) {
    const int k = per_cell(idx);
    for (int j = 0; j < k; ++j)
      for (int a = 0; a < d; ++a) x.push_back((idx[a] + (j + 1.0) / (k + 1.0)) * h[a]);
    for (int a = d - 1; a >= 0; --a) {
      if (++idx[a] < n[a]) break;
      idx[a] = 0;
    }
  }
  return x;
}

// A square box of side L (d dimensions) with unit-spacing cells; returns the grid after assign().
inline DensityGrid make_grid(int d, double L, const CoarseGrain& p, const std::function<int(const Cell&)>& per_cell) {
  DensityGrid g(std::vector<double>(d, L), p);
  const auto x = fill_cells(g.cells_per_side(), g.spacing(), per_cell);
  g.assign(x.data(), x.size() / d);
  return g;
}

// Uniform random positions (fixed seed).
inline std::vector<double> random_positions(int d, double L, std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, L);
  std::vector<double> x(n * d);
  for (auto& v : x) v = u(rng);
  return x;
}

// A 2D box of side L at density rho with particles at uniform random places (fixed seed), binned on
// the default grid: a homogeneous gas, whose rich cells are fluctuations only.
inline DensityGrid random_grid_2d(double L, double rho, std::uint64_t seed) {
  const auto n = static_cast<std::size_t>(std::lround(rho * L * L));
  DensityGrid g({L, L}, {});
  const auto x = random_positions(2, L, n, seed);
  g.assign(x.data(), n);
  return g;
}

// Periodic distance between i and j on a ring of n.
inline int ring_distance(int i, int j, int n) {
  int d = ((i - j) % n + n) % n;
  return d < n - d ? d : n - d;
}

}  // namespace gg::test
