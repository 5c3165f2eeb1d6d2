#pragma once
// Two-point correlation of the order parameter (docs/DESIGN.md; paper eq. 8, Figs. 4-5):
//   C_o(x) = <psi(y) psi(y+x)> - <psi>^2,  C(x) = C_o(x) / C_o(0),
// computed on the periodic grid by FFT (Wiener-Khinchin: C_o = IFFT |FFT(psi - <psi>)|^2 / cells),
// then averaged over shells: shell b holds the separations with |x| / h in [b - 1/2, b + 1/2), h the
// grid spacing, and is reported at r_b = b h, for b = 0 .. floor(L_min / (2h)) (the shells that fit
// inside the box whole). l_C = first r where C falls to `a`, interpolated linearly between shells.
// The same transform gives the structure factor of psi, S(k) = |FFT(psi - <psi>)|^2 / cells averaged
// over the shells of wave_vector_shells (grid_fft.hpp), and its first moment
// k1 = sum_{b >= 1} k_b S_b / sum_{b >= 1} S_b; and, from the particles counted per cell, the density
// structure factor S_rho(k) = |sum_x n(x) exp(-i k.x)|^2 / N (docs/DESIGN.md "Correlation").
#include <cstddef>
#include <memory>
#include <vector>

#include "gg/density_grid.hpp"
#include "grid_fft.hpp"

namespace gg {

struct CorrelationResult {
  std::vector<double> r;  // shell radii b h, [R]
  std::vector<double> C;  // shell averages, C[0] = 1 [R]
  double length = 0;      // l_C; NaN if C never falls to a within the shells
  std::vector<double> S;  // structure factor of psi per wave-vector shell [K]; NaN when psi is uniform
  double k1 = 0;          // its first moment; NaN when psi is uniform
};

// l_C: the first r where C(r) <= a, linearly interpolated between the shell before and that shell.
// NaN if C stays above a, or if C is NaN (uniform psi).
double crossing_length(const std::vector<double>& r, const std::vector<double>& C, double a);

// Holds the FFTW plans and buffers for one grid shape: create once, then compute() every frame
// (FFTW_ESTIMATE plans, so the numbers do not depend on timing measurements: deterministic).
class Correlator {
 public:
  // Takes the shape (cells per side, spacing) of `shape`; its content is not read.
  explicit Correlator(const DensityGrid& shape);

  // The full periodic field C(x), row-major like the grid, C = 1 at x = 0. If psi is uniform,
  // C_o vanishes identically and C is NaN everywhere (0/0: no structure to correlate).
  const std::vector<double>& field(const DensityGrid& grid);
  // Shell-averaged C(r), l_C for threshold `a`, S(k) and k1.
  CorrelationResult compute(const DensityGrid& grid, double a);
  // S_rho(k) of the particles counted per cell, per wave-vector shell; NaN at k = 0 (the count
  // squared) and when the grid holds no particle.
  std::vector<double> density_structure_factor(const DensityGrid& grid);

  const std::vector<double>& radii() const { return real_.radius; }
  const std::vector<double>& wave_numbers() const { return waves_.radius; }

 private:
  GridFft fft_;
  Shells real_, waves_;
  std::vector<double> field_;
  std::vector<double> power_;  // |psi_k|^2 / cells of the last field(), per half-spectrum entry
  bool uniform_ = false;
};

}  // namespace gg
