#include "gg/density_grid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

#include "gg/errors.hpp"
#include "gg/fmt.hpp"

namespace gg {

namespace {

// Periodic sliding-window sum of width 2w+1 along one axis of a row-major array viewed as
// [outer][n][inner]: out[o][i][:] = sum_{j=-w..w} in[o][(i+j) mod n][:]. The inner loop runs over
// contiguous memory (vectorisable); the window slides, so the cost does not grow with w.
// Indices stay within one period of the row (-n < i - w - 1, i + w < 2n, as 2w + 1 <= n), so one
// comparison wraps them: along the last axis (inner = 1) a division per index cost more than the sums.
template <class T>
void block_sum_axis(const T* in, T* out, std::size_t outer, int n, std::size_t inner, int w) {
  auto wrap = [n](long i) { return static_cast<std::size_t>(i < 0 ? i + n : i >= n ? i - n : i); };
  for (std::size_t o = 0; o < outer; ++o) {
    const T* src = in + o * n * inner;
    T* dst = out + o * n * inner;
    std::fill(dst, dst + inner, T{0});
    for (long j = -w; j <= w; ++j) {
      const T* row = src + wrap(j) * inner;
      for (std::size_t m = 0; m < inner; ++m) dst[m] += row[m];
    }
    for (int i = 1; i < n; ++i) {
      const T* prev = dst + (i - 1) * inner;
      const T* enter = src + wrap(long{i} + w) * inner;
      const T* leave = src + wrap(long{i} - w - 1) * inner;
      T* cur = dst + i * inner;
      for (std::size_t m = 0; m < inner; ++m) cur[m] = prev[m] + enter[m] - leave[m];
    }
  }
}

// Block sum of every cell: separable, one periodic window per axis, ping-pong between `result` and
// `scratch` (the first target chosen so that the last axis lands in `result`).
template <class T>
void block_sum(const T* cells, T* result, T* scratch, const std::vector<int>& n, const std::vector<std::size_t>& stride,
               int w) {
  const int d = static_cast<int>(n.size());
  const T* src = cells;
  T* bufs[2] = {result, scratch};
  int target = (d % 2 == 1) ? 0 : 1;
  for (int k = 0; k < d; ++k) {
    std::size_t outer = 1;
    for (int j = 0; j < k; ++j) outer *= static_cast<std::size_t>(n[j]);
    block_sum_axis(src, bufs[target], outer, n[k], stride[k], w);
    src = bufs[target];
    target ^= 1;
  }
}

// The cell holding a particle at `position` ([D]).
template <int D>
std::size_t cell_of(const double* position, const std::vector<double>& edges, const std::vector<double>& inv_h,
                    const std::vector<int>& n, const std::vector<std::size_t>& stride) {
  std::size_t cell = 0;
  for (int k = 0; k < D; ++k) {
    double x = position[k];
    const double L = edges[k];
    if (x < 0 || x >= L) [[unlikely]] {  // wrap (positions in [-L/2, L/2) or slightly outside)
      x -= L * std::floor(x / L);
      if (x >= L) x -= L;
    }
    // x < L, but x * n / L may round up to n for x within an ulp of L.
    const int c = std::min(n[k] - 1, static_cast<int>(x * inv_h[k]));
    cell += static_cast<std::size_t>(c) * stride[k];
  }
  return cell;
}

// Cell of every particle; the dimension is a template parameter so the per-particle loop is unrolled.
template <int D>
void bin_particles(const double* positions, std::size_t n_particles, const std::vector<double>& edges,
                   const std::vector<double>& inv_h, const std::vector<int>& n, const std::vector<std::size_t>& stride,
                   std::int32_t* count, const double* weights, double* weight) {
  for (std::size_t i = 0; i < n_particles; ++i) {
    const std::size_t cell = cell_of<D>(positions + i * D, edges, inv_h, n, stride);
    ++count[cell];
    if (weights) weight[cell] += weights[i];
  }
}

template <int D>
void sum_particles(const double* positions, std::size_t n_particles, const std::vector<double>& edges,
                   const std::vector<double>& inv_h, const std::vector<int>& n, const std::vector<std::size_t>& stride,
                   const double* values, int m, double* out, std::size_t cells) {
  for (std::size_t i = 0; i < n_particles; ++i) {
    const std::size_t cell = cell_of<D>(positions + i * D, edges, inv_h, n, stride);
    for (int j = 0; j < m; ++j) out[j * cells + cell] += values[i * m + j];
  }
}

}  // namespace

void validate(const CoarseGrain& p, const std::vector<double>& edges) {
  if (!(std::isfinite(p.grid) && p.grid > 0))
    throw UsageError("--grid " + fmt(p.grid) + " must be a positive number (cell spacing; default 1)");
  double cells = 1;  // a double: round(L/grid) of an absurd box fits no integer
  double fewest = std::numeric_limits<double>::infinity();  // cells along the narrowest axis
  std::string box;
  for (double L : edges) {
    if (p.grid > L)
      throw UsageError("--grid " + fmt(p.grid) + " is larger than the box (L = " + fmt(L) +
                       "); choose --grid <= " + fmt(L));
    const double n = std::max(1.0, std::round(L / p.grid));
    cells *= n;
    fewest = std::min(fewest, n);
    box += (box.empty() ? "" : " x ") + fmt(L);
  }
  if (cells > kMaxCells) {
    // n_k = round(L_k/grid) shrinks as 1/grid along each of the d axes; 1% more for the rounding.
    const double enough = p.grid * std::pow(cells / kMaxCells, 1.0 / static_cast<double>(edges.size())) * 1.01;
    throw UsageError("--grid " + fmt(p.grid) + " gives " + fmt(cells) + " cells for the box " + box +
                     ", more than " + std::to_string(static_cast<std::int64_t>(kMaxCells)) + "; choose --grid >= " +
                     fmt(std::ceil(enough * 100) / 100));
  }
  if (p.coarse < 0)
    throw UsageError("--coarse " + std::to_string(p.coarse) +
                     " must be >= 0 (half-width of the averaging block in cells; default 1)");
  // A block of 2w+1 cells wider than the n cells of an axis wraps onto itself and counts cells twice
  // (it is no longer "the cells around" its centre): 2w+1 <= n on every axis, so w <= (n-1)/2.
  // Without a box (edges empty) there is nothing to compare with yet; with one, fewest <= kMaxCells.
  if (!edges.empty()) {
    const auto n = static_cast<std::int64_t>(fewest), widest = (n - 1) / 2;
    if (p.coarse > widest)
      throw UsageError("--coarse " + std::to_string(p.coarse) + " makes blocks of " +
                       std::to_string(2 * std::int64_t{p.coarse} + 1) + " cells per side, more than the " +
                       std::to_string(n) + " cells per side of the grid (box " + box + ", --grid " + fmt(p.grid) +
                       "), so cells would count twice; choose --coarse <= " + std::to_string(widest) +
                       " (or a smaller --grid)");
  }
  if (!(std::isfinite(p.rho_c) && p.rho_c > 0))
    throw UsageError("--rho-c " + fmt(p.rho_c) + " must be a positive density (default 0.5)");
}

DensityGrid::DensityGrid(const std::vector<double>& edges, const CoarseGrain& p) : params_(p), edges_(edges) {
  const int d = static_cast<int>(edges.size());
  if (d < 1 || d > 3) throw RuntimeError("density grid: dimension " + std::to_string(d) + " not in 1..3");
  for (double L : edges)
    if (!(std::isfinite(L) && L > 0)) throw RuntimeError("density grid: box edge " + fmt(L) + " is not positive");
  validate(p, edges);
  n_.resize(d);
  h_.resize(d);
  inv_h_.resize(d);
  stride_.resize(d);
  std::size_t cells = 1;
  for (int k = 0; k < d; ++k) {
    n_[k] = static_cast<int>(std::max(1.0, std::round(edges[k] / p.grid)));  // <= kMaxCells (validate)
    h_[k] = edges[k] / n_[k];
    inv_h_[k] = n_[k] / edges[k];
    cell_volume_ *= h_[k];
    cells *= static_cast<std::size_t>(n_[k]);
  }
  for (int k = d - 1, s = 1; k >= 0; --k) {
    stride_[k] = static_cast<std::size_t>(s);
    s *= n_[k];
  }
  block_volume_ = cell_volume_ * std::pow(2.0 * p.coarse + 1.0, d);
  // Smallest block count k with k / block_volume > rho_c, found with that very expression so that
  // psi agrees bit for bit with rho_loc() > rho_c.
  const double guess = std::floor(p.rho_c * block_volume_);
  rich_count_ = guess > 2e9 ? std::numeric_limits<std::int32_t>::max() : static_cast<std::int32_t>(std::max(0.0, guess - 2));
  while (rich_count_ < std::numeric_limits<std::int32_t>::max() && !(rich_count_ / block_volume_ > p.rho_c)) ++rich_count_;
  count_.assign(cells, 0);
  block_.assign(cells, 0);
  scratch_.assign(cells, 0);
  psi_.assign(cells, -1);
}

std::size_t DensityGrid::cell_of(const double* position) const {
  switch (dim()) {
    case 1: return gg::cell_of<1>(position, edges_, inv_h_, n_, stride_);
    case 2: return gg::cell_of<2>(position, edges_, inv_h_, n_, stride_);
    default: return gg::cell_of<3>(position, edges_, inv_h_, n_, stride_);
  }
}

void DensityGrid::cell_sums(const double* positions, std::size_t n_particles, const double* values, int m,
                            std::vector<double>& out) const {
  const std::size_t cells = count_.size();
  out.assign(static_cast<std::size_t>(m) * cells, 0.0);
  const auto sum = [&](auto d) {
    sum_particles<decltype(d)::value>(positions, n_particles, edges_, inv_h_, n_, stride_, values, m, out.data(), cells);
  };
  switch (dim()) {
    case 1: sum(std::integral_constant<int, 1>()); break;
    case 2: sum(std::integral_constant<int, 2>()); break;
    default: sum(std::integral_constant<int, 3>()); break;
  }
}

void DensityGrid::block_sums(const std::vector<double>& fields, int m, std::vector<double>& out,
                             std::vector<double>& scratch) const {
  const std::size_t cells = count_.size();
  out.resize(static_cast<std::size_t>(m) * cells);
  scratch.resize(cells);
  for (int j = 0; j < m; ++j)
    block_sum(fields.data() + j * cells, out.data() + j * cells, scratch.data(), n_, stride_, params_.coarse);
}

void DensityGrid::assign(const double* positions, std::size_t n_particles, const double* weights) {
  n_particles_ = n_particles;
  weighted_ = weights != nullptr;
  std::fill(count_.begin(), count_.end(), 0);
  if (weighted_) {
    weight_.assign(count_.size(), 0.0);
    block_weight_.resize(count_.size());
    weight_scratch_.resize(count_.size());
  }
  double* weight = weighted_ ? weight_.data() : nullptr;
  const auto bin = [&](auto d) {
    bin_particles<decltype(d)::value>(positions, n_particles, edges_, inv_h_, n_, stride_, count_.data(), weights, weight);
  };
  switch (dim()) {
    case 1: bin(std::integral_constant<int, 1>()); break;
    case 2: bin(std::integral_constant<int, 2>()); break;
    default: bin(std::integral_constant<int, 3>()); break;
  }
  block_sum(count_.data(), block_.data(), scratch_.data(), n_, stride_, params_.coarse);
  if (weighted_) {
    block_sum(weight_.data(), block_weight_.data(), weight_scratch_.data(), n_, stride_, params_.coarse);
    for (std::size_t c = 0; c < block_.size(); ++c) psi_[c] = rho_loc(c) > params_.rho_c ? 1 : -1;
    return;
  }
  // psi = +1 only if rho_loc > rho_c (the tie rho_loc == rho_c is particle-poor), as an integer
  // comparison against rich_count_ (same result as rho_loc(c) > rho_c, see the constructor).
  for (std::size_t c = 0; c < block_.size(); ++c) psi_[c] = block_[c] >= rich_count_ ? 1 : -1;
}

}  // namespace gg
