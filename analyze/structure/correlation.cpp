#include "correlation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace gg {


double crossing_length(const std::vector<double>& r, const std::vector<double>& C, double a) {
  for (std::size_t b = 1; b < C.size() && b < r.size(); ++b) {
    if (std::isnan(C[b]) || std::isnan(C[b - 1])) break;
    if (C[b] <= a) {
      const double drop = C[b - 1] - C[b];
      const double f = drop > 0 ? (C[b - 1] - a) / drop : 0.0;
      return r[b - 1] + f * (r[b] - r[b - 1]);
    }
  }
  return kNaN;
}

Correlator::Correlator(const DensityGrid& shape)
    : fft_(shape.cells_per_side()),
      real_(real_space_shells(shape.cells_per_side(), shape.spacing())),
      waves_(wave_vector_shells(shape.cells_per_side(), shape.spacing())) {
  field_.assign(fft_.cells(), 0.0);
  power_.assign(fft_.half(), 0.0);
}

const std::vector<double>& Correlator::field(const DensityGrid& grid) {
  const auto& psi = grid.psi();
  const std::size_t cells = fft_.cells();
  double* real = fft_.real();
  long sum = 0;
  for (std::size_t c = 0; c < cells; ++c) sum += psi[c];
  const double mean = static_cast<double>(sum) / static_cast<double>(cells);
  for (std::size_t c = 0; c < cells; ++c) real[c] = psi[c] - mean;

  fft_.forward();
  std::complex<double>* s = fft_.spectrum();
  const double inv_cells = 1.0 / static_cast<double>(cells);
  for (std::size_t m = 0; m < fft_.half(); ++m) {
    s[m] = std::norm(s[m]);
    power_[m] = s[m].real() * inv_cells;
  }
  fft_.backward();  // real = cells^2 C_o (unnormalised transforms)

  const double zero = real[0];
  uniform_ = !(zero > 0);
  if (!uniform_) {
    const double inv = 1.0 / zero;
    for (std::size_t c = 0; c < cells; ++c) field_[c] = real[c] * inv;
    field_[0] = 1.0;
  } else {  // uniform psi: C_o = 0 identically
    std::fill(field_.begin(), field_.end(), kNaN);
  }
  return field_;
}

CorrelationResult Correlator::compute(const DensityGrid& grid, double a) {
  const auto& f = field(grid);
  CorrelationResult out;
  out.r = real_.radius;
  out.C = real_.average(f.data());
  out.length = crossing_length(out.r, out.C, a);
  out.S = waves_.average(power_.data());
  double moment = 0, norm = 0;
  for (std::size_t b = 1; b < out.S.size(); ++b) moment += waves_.radius[b] * out.S[b], norm += out.S[b];
  out.k1 = uniform_ ? kNaN : moment / norm;
  if (uniform_) std::fill(out.S.begin(), out.S.end(), kNaN);
  return out;
}

std::vector<double> Correlator::density_structure_factor(const DensityGrid& grid) {
  const auto& n = grid.counts();
  double* real = fft_.real();
  for (std::size_t c = 0; c < fft_.cells(); ++c) real[c] = n[c];
  fft_.forward();
  const std::complex<double>* s = fft_.spectrum();
  const double inv_n = 1.0 / static_cast<double>(grid.n_particles());
  std::vector<double> power(fft_.half());
  for (std::size_t m = 0; m < fft_.half(); ++m) power[m] = std::norm(s[m]) * inv_n;
  std::vector<double> out = waves_.average(power.data());
  out[0] = kNaN;
  if (grid.n_particles() == 0) std::fill(out.begin(), out.end(), kNaN);
  return out;
}

}  // namespace gg
