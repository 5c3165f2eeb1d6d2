#pragma once
// The velocity analyses of gg-velocity (docs/DESIGN.md "Velocities"), as plain functions of the
// particles (velocities relative to the centre-of-mass velocity V = sum m v / sum m):
//   - temperature per component and the Sonine coefficients a2, a3 of the distribution of
//     c = v / v_T (v_T = sqrt(2 T / m)), with standard errors by the delta method on the sample
//     moments (particles taken as independent);
//   - the distribution f(c) per unit volume of c-space (a Maxwellian is pi^(-d/2) exp(-c^2)) on
//     linear bins for the body and log-spaced ones for the tail, and a fit ln f = ln f0 - A c^b of
//     its tail;
//   - the coarse-grained flow field u (momentum over mass in the (2w+1)^d block of each cell of the
//     DensityGrid: the block of rho_loc), the fraction of the kinetic energy it carries, its
//     longitudinal and transverse correlation functions and lengths, its vorticity and enstrophy;
//   - the hydrodynamic profiles along one axis: number density, mean velocity and temperature of
//     the particles in equal slabs of the box, and their mean and standard error over frames.
#include <complex>
#include <cstddef>
#include <vector>

#include "gg/density_grid.hpp"
#include "grid_fft.hpp"

namespace gg {

struct SonineResult {
  std::vector<double> temperature;  // T_k = sum m (v_k - V_k)^2 / N per component [d]
  double T = 0;                     // their mean
  double a2 = 0, a2_stderr = 0;     // a2 = d/(d+2) <w^2>/<w>^2 - 1, w = m |v - V|^2
  double a3 = 0, a3_stderr = 0;     // a3 = 1 + 3 a2 - d^2/((d+2)(d+4)) <w^3>/<w>^3
};

// `velocity` [N][d]; `mass` [N] or nullptr (every mass 1). NaN results for fewer than 2 particles
// or T = 0.
SonineResult sonine_coefficients(const double* velocity, const double* mass, std::size_t n, int d);

// Bin edges of c: linear from 0 to `body_max` in steps of `dc`, then log-spaced, `per_decade` bins a
// decade, up to the first edge >= `top`.
std::vector<double> speed_bin_edges(double dc, double body_max, int per_decade, double top);

struct SpeedDistribution {
  std::vector<double> f;       // particles per bin / (N * c-space volume of the bin) [B]
  std::vector<double> counts;  // particles per bin [B]
  double tail_A = 0, tail_b = 0, tail_f0 = 0;  // ln f = ln f0 - A c^b; NaN if fewer than 3 bins to fit
  int tail_bins = 0;                           // bins the fit used
};

// f(c) of c = |v - V| / sqrt(2 T / m) on `edges`, and the tail fit over the bins that lie wholly at
// c >= `tail_from`, up to (not including) the first of them with fewer than `min_count` particles.
// The fit compares each bin's f with the model averaged over the bin (weights: the counts, the
// inverse variance of ln f), so that wide log bins do not bias A and b.
SpeedDistribution speed_distribution(const double* velocity, const double* mass, std::size_t n, int d,
                                     const std::vector<double>& edges, double tail_from, double min_count = 10);

struct FlowResult {
  double energy_fraction = 0;  // sum_cells M_c |u_c|^2 / sum_i m_i |v_i - V|^2
  double empty_fraction = 0;   // cells whose block holds no particle (u = 0 there)
  std::vector<double> C_L, C_T;  // shell averages over r (FlowAnalyzer::radii), normalised by tr C(0) / d
  double length_L = 0, length_T = 0;  // first r where C_L (C_T) falls to a; NaN if never
  double enstrophy = 0;               // (1/2) <|curl u|^2> over the cells (NaN in 1D)
};

// Holds the FFT plans and fields for one grid shape: create once, compute() every frame (its buffers,
// megabytes at L = 512, are reused: allocated afresh, their page faults cost more than the analysis).
class FlowAnalyzer {
 public:
  explicit FlowAnalyzer(const DensityGrid& shape);

  // `grid` gives the cells and the block (its content is not read); positions and velocities [N][d],
  // masses [N] or nullptr; `a` the threshold of the correlation lengths. C_T, length_T and the
  // enstrophy are NaN in 1D, and C_L, C_T are NaN when u is uniform.
  FlowResult compute(const DensityGrid& grid, const double* position, const double* velocity, const double* mass,
                     std::size_t n, double a);

  const std::vector<double>& radii() const { return shells_.radius; }
  // The last flow field u, [cells][d], row-major like the grid.
  const std::vector<double>& flow() const { return u_; }
  // The last vorticity by central differences, [cells][k], k = 1 in 2D (the z component), 3 in 3D,
  // 0 in 1D.
  const std::vector<double>& vorticity() const { return omega_; }
  int vorticity_components() const { return dim_ == 2 ? 1 : dim_ == 3 ? 3 : 0; }

 private:
  int dim_;
  GridFft fft_;
  Shells shells_;
  std::vector<double> direction_;  // unit vector of the minimum-image separation of each cell [cells][d]
  std::vector<double> u_, omega_;
  // Per frame: mass and momentum per particle [N][d+1], summed per cell and per block [d+1][cells].
  std::vector<double> values_, cell_sums_, block_sums_, scratch_;
  std::vector<std::complex<double>> spectra_;                // U_k of each component [d][half]
  std::vector<double> longitudinal_, trace_, transverse_;  // r_i r_j C_ij and tr C per cell
};

// The particles of one frame in `bins` equal slabs of the box edge `edges[axis]` (positions in
// [0, L), as every reader gives them).
struct SlabProfile {
  std::vector<double> count;        // particles in each slab [B]
  std::vector<double> density;      // count / slab volume (width x the other edges) [B]
  std::vector<double> velocity;     // u = sum m v / sum m of the slab's particles [B][d]; NaN if empty
  std::vector<double> temperature;  // sum m |v - u|^2 / (d (count - 1)) [B]; NaN below 2 particles
};

// `position`, `velocity` [N][d]; `mass` [N] or nullptr (every mass 1); rows of mass 0 are left out.
SlabProfile slab_profile(const double* position, const double* velocity, const double* mass, std::size_t n,
                         const std::vector<double>& edges, int axis, std::size_t bins);

// Mean and standard error (sample standard deviation / sqrt(frames)) over frames of each element of
// a per-frame vector, skipping the NaN ones (a slab too empty that frame to define the value).
class FrameAverage {
 public:
  void add(const std::vector<double>& values);
  std::vector<double> mean() const;            // NaN where no frame had a value
  std::vector<double> standard_error() const;  // NaN where fewer than 2 frames had one
  const std::vector<double>& frames() const { return frames_; }  // frames with a value, each element

 private:
  std::vector<double> frames_, mean_, m2_;  // Welford's running mean and sum of squared deviations
};

}  // namespace gg
