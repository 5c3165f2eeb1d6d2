#include "pair_correlation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "gg/particle_volume.hpp"

namespace gg {

RadialDistribution radial_distribution(const double* positions, std::size_t n, const std::vector<double>& edges,
                                       double r_max, double dr) {
  const int d = static_cast<int>(edges.size());
  double volume = 1;
  for (double L : edges) r_max = std::min(r_max, L / 2), volume *= L;
  const auto B = static_cast<std::size_t>(std::floor(r_max / dr + 1e-9));
  RadialDistribution out;
  out.r.resize(B);
  for (std::size_t b = 0; b < B; ++b) out.r[b] = (b + 0.5) * dr;
  std::vector<double> pairs(B, 0.0);

  // Cells of at least r_max per axis; with fewer than 3 along an axis, every cell of it is a
  // neighbour (each once).
  std::vector<int> nc(d);
  std::vector<std::size_t> stride(d);
  std::size_t cells = 1;
  for (int k = d - 1; k >= 0; --k) {
    nc[k] = std::max(1, static_cast<int>(std::floor(edges[k] / std::max(r_max, 1e-300))));
    stride[k] = cells;
    cells *= static_cast<std::size_t>(nc[k]);
  }
  std::vector<std::size_t> cell(n), start(cells + 1, 0);
  for (std::size_t i = 0; i < n; ++i) {
    std::size_t c = 0;
    for (int k = 0; k < d; ++k) {
      double xi = positions[i * d + k];
      xi -= edges[k] * std::floor(xi / edges[k]);
      c += static_cast<std::size_t>(std::min(nc[k] - 1, static_cast<int>(xi / edges[k] * nc[k]))) * stride[k];
    }
    cell[i] = c;
    ++start[c + 1];
  }
  for (std::size_t c = 0; c < cells; ++c) start[c + 1] += start[c];
  // The wrapped positions sorted by cell, so that a cell's particles lie side by side.
  std::vector<double> x(n * d);
  {
    std::vector<std::size_t> fill(start.begin(), start.end() - 1);
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t q = fill[cell[i]]++;
      for (int k = 0; k < d; ++k) {
        double xi = positions[i * d + k];
        x[q * d + k] = xi - edges[k] * std::floor(xi / edges[k]);
      }
    }
  }
  // The neighbour cells of every cell, each once: offsets -1, 0, 1 per axis with 3 cells or more,
  // else every cell of the axis.
  std::vector<std::vector<int>> offsets(d);
  for (int k = 0; k < d; ++k) {
    if (nc[k] >= 3) offsets[k] = {-1, 0, 1};
    else for (int o = 0; o < nc[k]; ++o) offsets[k].push_back(o);
  }
  std::vector<std::size_t> neighbours;
  std::size_t per_cell = 1;
  for (int k = 0; k < d; ++k) per_cell *= offsets[k].size();
  neighbours.reserve(cells * per_cell);
  for (std::size_t c = 0; c < cells; ++c) {
    std::vector<std::size_t> pick(d, 0);
    for (;;) {
      std::size_t nb = 0;
      for (int k = 0; k < d; ++k) {
        const int ci = static_cast<int>(c / stride[k] % nc[k]), o = offsets[k][pick[k]];
        const int m = nc[k] >= 3 ? ((ci + o) % nc[k] + nc[k]) % nc[k] : o;
        nb += static_cast<std::size_t>(m) * stride[k];
      }
      neighbours.push_back(nb);
      int k = d - 1;
      for (; k >= 0; --k) {
        if (++pick[k] < offsets[k].size()) break;
        pick[k] = 0;
      }
      if (k < 0) break;
    }
  }
  // Every pair once (the later of the two in cell order is the partner), counted for both ends.
  const double r2max = static_cast<double>(B) * dr * static_cast<double>(B) * dr, inv_dr = 1.0 / dr;
  std::vector<double> half(d);
  for (int k = 0; k < d; ++k) half[k] = edges[k] / 2;
  for (std::size_t c = 0; c < cells; ++c) {
    for (std::size_t m = 0; m < per_cell; ++m) {
      const std::size_t nb = neighbours[c * per_cell + m];
      for (std::size_t p = start[c]; p < start[c + 1]; ++p) {
        const double* xp = &x[p * d];
        for (std::size_t q = std::max(start[nb], p + 1); q < start[nb + 1]; ++q) {
          const double* xq = &x[q * d];
          double r2 = 0;
          for (int k = 0; k < d; ++k) {
            double dx = xp[k] - xq[k];  // minimum image (both in [0, L))
            if (dx > half[k]) dx -= edges[k];
            else if (dx < -half[k]) dx += edges[k];
            r2 += dx * dx;
          }
          if (r2 < r2max) {
            const auto b = static_cast<std::size_t>(std::sqrt(r2) * inv_dr);
            if (b < B) pairs[b] += 2;
          }
        }
      }
    }
  }
  out.g.assign(B, std::numeric_limits<double>::quiet_NaN());
  if (n < 2) return out;
  const double density = static_cast<double>(n - 1) / volume;
  for (std::size_t b = 0; b < B; ++b)
    out.g[b] = pairs[b] / (static_cast<double>(n) * density * (particle_volume((b + 1) * dr, d) - particle_volume(b * dr, d)));
  return out;
}

double contact_value(const RadialDistribution& g, double sigma, double width) {
  double s = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t b = 0; b < g.r.size(); ++b) {
    if (g.r[b] <= sigma || g.r[b] > sigma + width) continue;
    if (std::isnan(g.g[b])) return std::numeric_limits<double>::quiet_NaN();
    const double x = g.r[b] - sigma;
    s += 1, sx += x, sy += g.g[b], sxx += x * x, sxy += x * g.g[b];
  }
  if (s < 2) return std::numeric_limits<double>::quiet_NaN();
  const double slope = (s * sxy - sx * sy) / (s * sxx - sx * sx);
  return (sy - slope * sx) / s;
}

}  // namespace gg
