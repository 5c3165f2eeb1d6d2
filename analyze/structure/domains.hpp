#pragma once
// Domain lengths (docs/DESIGN.md "Domains"; paper eq. 10): along every grid line parallel to each axis
// (rows and columns in 2D), l_d = distance between successive interfaces, an interface being a sign
// change of psi between neighbouring cells (periodic). A line without an interface holds no domain
// and contributes nothing. P(l_d) = histogram in bins of one grid spacing h centred on the lengths
// (edges (j - 1/2) h, j = 1, 2, ...), normalised as a density: sum_j P_j h = 1.
// l = first moment of P = mean domain length.
#include <cstdint>
#include <string>
#include <vector>

#include "gg/density_grid.hpp"

namespace gg {

enum class Phase { both, rich, poor };  // which domains count: psi = +1, -1, or both
Phase parse_phase(const std::string& text);  // "both" | "rich" | "poor"; throws UsageError
const char* to_string(Phase phase);

struct DomainResult {
  std::vector<double> bin_edges;  // [B + 1], (j - 1/2) h
  std::vector<double> histogram;  // P [B]; all zero if there is no domain
  double length = 0;              // l; NaN if there is no domain
  std::int64_t count = 0;         // number of domains counted
};

// Bin edges for `grid`'s shape: one bin per possible domain length (1 .. max_k n_k - 1 cells).
std::vector<double> domain_bin_edges(const DensityGrid& grid);

DomainResult measure_domains(const DensityGrid& grid, Phase phase);

}  // namespace gg
