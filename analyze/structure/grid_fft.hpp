#pragma once
// The periodic grid FFT that every spectral analysis shares (C(r,t) and S(k,t) of gg-correlate, the
// velocity correlations of gg-velocity), and the shells over which they average.
//   - GridFft: FFTW plans (real to half-complex and back, unnormalised, FFTW_ESTIMATE so that every
//     bit of a result is reproducible) and their buffers for one grid shape, row-major, last axis
//     fastest (the layout of DensityGrid).
//   - Shells: an index per entry (a cell of the grid, or an entry of the half spectrum), a radius per
//     shell and the weight of each entry; shell averages are sum(weight * value) / sum(weight).
#include <complex>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

namespace gg {

// The value of a result that does not exist (a uniform field, too few particles).
inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

class GridFft {
 public:
  // `n` cells per axis (1 to 3 axes).
  explicit GridFft(const std::vector<int>& n);
  ~GridFft();
  GridFft(const GridFft&) = delete;
  GridFft& operator=(const GridFft&) = delete;

  double* real();                    // [cells]: the input of forward(), the output of backward()
  std::complex<double>* spectrum();  // [half]: the output of forward(), the input of backward()
  std::size_t cells() const { return cells_; }
  std::size_t half() const { return half_; }  // cells / n_last * (n_last / 2 + 1)
  void forward();                             // real -> spectrum
  void backward();                            // spectrum -> real, times cells (unnormalised)

 private:
  struct Plans;
  std::unique_ptr<Plans> plans_;
  std::size_t cells_ = 0, half_ = 0;
};

struct Shells {
  std::vector<double> radius;       // r_b (or k_b) [B]
  std::vector<std::int32_t> shell;  // shell of each entry, -1 beyond the last shell
  std::vector<double> weight;       // weight of each entry (1 in real space; 1 or 2 in the half spectrum)
  std::vector<double> inv_weight;   // 1 / (sum of the weights in shell b) [B]

  // Shell averages of `values` (one per entry).
  std::vector<double> average(const double* values) const;
};

// Real space: the cells of a grid of `n` cells of `spacing` per axis, shell b holding the minimum-image
// separations |x| / h in [b - 1/2, b + 1/2), h the finest spacing, r_b = b h, b = 0 .. floor(L_min / (2h))
// (the shells that fit inside the box whole).
Shells real_space_shells(const std::vector<int>& n, const std::vector<double>& spacing);

// Reciprocal space: the entries of GridFft's half spectrum, wave vector k_j = 2 pi q_j / L_j
// (q_j = index, less n_j above n_j / 2), shell b holding |k| / dk in [b - 1/2, b + 1/2),
// dk = 2 pi / L_max, k_b = b dk, b = 0 .. floor(k_Nyquist / dk) with k_Nyquist = min_j pi n_j / L_j
// (whole shells only). An entry stands for itself and its mirror -k (weight 2) unless it is its own
// mirror (last index 0 or n_last / 2: weight 1), so averages are over the full spectrum.
Shells wave_vector_shells(const std::vector<int>& n, const std::vector<double>& spacing);

}  // namespace gg
