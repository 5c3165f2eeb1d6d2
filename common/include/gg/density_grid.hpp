#pragma once
// The one coarse-graining shared by every structural analysis (docs/DESIGN.md "Units and definitions"):
//   - a periodic grid of n_k = max(1, round(L_k / grid)) cells along axis k, so the cells tile the box
//     exactly with spacing h_k = L_k / n_k;
//   - each particle belongs to the cell holding its centre;
//   - rho_loc of a cell = particles in the (2w+1)^d block of cells centred on it / the block's volume
//     (w = --coarse; periodic; 2w+1 <= n_k on every axis, since a wider block would wrap onto itself
//     and count cells twice); with weights (each particle's area or volume, for a file with radii)
//     the summed weights instead: the local packing fraction;
//   - order parameter psi = sgn(rho_loc - rho_c), with the tie rho_loc == rho_c counted as particle-poor:
//     psi = +1 only if rho_loc > rho_c, otherwise -1 (psi is never 0, so every cell is in one phase).
// Written for any dimension d (1, 2, 3); cells are stored row-major, the last axis fastest.
// Construct once per box (the shape is fixed), then assign() each frame: buffers are reused.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace gg {

// Coarse-graining parameters (the --grid, --coarse, --rho-c flags of every structural tool).
struct CoarseGrain {
  double grid = 1.0;   // target cell spacing (sigma units)
  int coarse = 1;      // w: the block is (2w+1)^d cells
  double rho_c = 0.5;  // threshold density of the order parameter
};

// Most cells a grid may have: the grid, its blocks and an analysis's FFT of it take ~40 bytes a
// cell, so 2^26 cells already ask ~3 GB. A larger box needs a larger --grid.
inline constexpr double kMaxCells = 1 << 26;

// Throws UsageError (one line naming the flag and the fix) if grid <= 0 or not finite, grid larger
// than any box edge, more than kMaxCells cells, coarse < 0, a block of 2*coarse+1 cells wider than
// the grid along any axis, rho_c <= 0 or not finite.
// `edges` = box edge per dimension (empty: only the box-independent checks).
void validate(const CoarseGrain& p, const std::vector<double>& edges);

class DensityGrid {
 public:
  // `edges` = box edge per dimension (1 <= d <= 3). Calls validate().
  DensityGrid(const std::vector<double>& edges, const CoarseGrain& p);

  // Bins `n_particles` positions ([N][d], row-major; wrapped into the box if outside) and computes
  // counts, block counts and psi. With `weights` ([N]), rho_loc and psi come from the weights
  // summed over each block instead of the particles counted (counts() still counts particles).
  void assign(const double* positions, std::size_t n_particles, const double* weights = nullptr);

  // Sums `m` per-particle values (`values` [N][m], row-major) into the cells that assign() would put
  // `positions` ([N][d]) in: `out` [m][cells], component-major (a field per component).
  void cell_sums(const double* positions, std::size_t n_particles, const double* values, int m,
                 std::vector<double>& out) const;
  // Sums each of the `m` per-cell fields in `fields` ([m][cells], as cell_sums writes them) over the
  // (2w+1)^d block around every cell, the block of rho_loc, into `out` ([m][cells]). `out` and
  // `scratch` are resized as needed: a caller that keeps them across frames allocates them once.
  void block_sums(const std::vector<double>& fields, int m, std::vector<double>& out,
                  std::vector<double>& scratch) const;

  // The row-major index of the cell assign() puts a particle at `position` ([d]) in.
  std::size_t cell_of(const double* position) const;

  int dim() const { return static_cast<int>(n_.size()); }
  const CoarseGrain& params() const { return params_; }
  const std::vector<double>& edges() const { return edges_; }
  const std::vector<int>& cells_per_side() const { return n_; }      // n_k
  const std::vector<double>& spacing() const { return h_; }          // h_k = L_k / n_k
  const std::vector<std::size_t>& strides() const { return stride_; }  // row-major, last axis 1
  std::size_t size() const { return count_.size(); }                 // total cells
  std::size_t n_particles() const { return n_particles_; }
  double cell_volume() const { return cell_volume_; }
  double block_volume() const { return block_volume_; }  // (2w+1)^d cell volumes

  const std::vector<std::int32_t>& counts() const { return count_; }        // particles per cell
  const std::vector<std::int32_t>& block_counts() const { return block_; }  // particles per block
  const std::vector<std::int8_t>& psi() const { return psi_; }              // +1 rich, -1 poor
  double rho_loc(std::size_t cell) const { return (weighted_ ? block_weight_[cell] : block_[cell]) / block_volume_; }

 private:
  CoarseGrain params_;
  std::vector<double> edges_, h_, inv_h_;
  std::vector<int> n_;
  std::vector<std::size_t> stride_;
  double cell_volume_ = 1, block_volume_ = 1;
  std::size_t n_particles_ = 0;
  std::int32_t rich_count_ = 0;  // psi = +1 iff block count >= this
  std::vector<std::int32_t> count_, block_, scratch_;
  bool weighted_ = false;  // the last assign() had weights
  std::vector<double> weight_, block_weight_, weight_scratch_;
  std::vector<std::int8_t> psi_;
};

}  // namespace gg
