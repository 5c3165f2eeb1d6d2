#pragma once
// Two-point correlation of the order parameter (docs/DESIGN.md; paper eq. 8, Figs. 4-5):
//   C_o(x) = <psi(y) psi(y+x)> - <psi>^2,  C(x) = C_o(x) / C_o(0),
// computed on the periodic grid by FFT (Wiener-Khinchin: C_o = IFFT |FFT(psi - <psi>)|^2 / cells),
// then averaged over shells: shell b holds the separations with |x| / h in [b - 1/2, b + 1/2), h the
// grid spacing, and is reported at r_b = b h, for b = 0 .. floor(L_min / (2h)) (the shells that fit
// inside the box whole). l_C = first r where C falls to `a`, interpolated linearly between shells.
#include <cstddef>
#include <memory>
#include <vector>

#include "gg/density_grid.hpp"

namespace gg {

struct CorrelationResult {
  std::vector<double> r;  // shell radii b h, [R]
  std::vector<double> C;  // shell averages, C[0] = 1 [R]
  double length = 0;      // l_C; NaN if C never falls to a within the shells
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
  ~Correlator();
  Correlator(const Correlator&) = delete;
  Correlator& operator=(const Correlator&) = delete;

  // The full periodic field C(x), row-major like the grid, C = 1 at x = 0. If psi is uniform,
  // C_o vanishes identically and C is NaN everywhere (0/0: no structure to correlate).
  const std::vector<double>& field(const DensityGrid& grid);
  // Shell-averaged C(r) and l_C for threshold `a`.
  CorrelationResult compute(const DensityGrid& grid, double a);

  const std::vector<double>& radii() const { return radius_; }

 private:
  struct Plans;
  std::unique_ptr<Plans> plans_;
  std::vector<int> n_;
  std::size_t cells_ = 0;
  std::vector<double> field_;
  std::vector<double> radius_;            // r_b
  std::vector<std::int32_t> shell_;       // shell of each cell, -1 beyond the last shell
  std::vector<double> inv_shell_count_;   // 1 / cells in shell b
};

}  // namespace gg
