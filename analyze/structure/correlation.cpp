#include "correlation.hpp"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <new>

namespace gg {

struct Correlator::Plans {
  double* real = nullptr;
  fftw_complex* spectrum = nullptr;
  fftw_plan forward = nullptr;
  fftw_plan backward = nullptr;
  ~Plans() {
    if (forward) fftw_destroy_plan(forward);
    if (backward) fftw_destroy_plan(backward);
    fftw_free(real);
    fftw_free(spectrum);
  }
};

double crossing_length(const std::vector<double>& r, const std::vector<double>& C, double a) {
  for (std::size_t b = 1; b < C.size() && b < r.size(); ++b) {
    if (std::isnan(C[b]) || std::isnan(C[b - 1])) break;
    if (C[b] <= a) {
      const double drop = C[b - 1] - C[b];
      const double f = drop > 0 ? (C[b - 1] - a) / drop : 0.0;
      return r[b - 1] + f * (r[b] - r[b - 1]);
    }
  }
  return std::numeric_limits<double>::quiet_NaN();
}

Correlator::Correlator(const DensityGrid& shape)
    : plans_(std::make_unique<Plans>()), n_(shape.cells_per_side()), cells_(shape.size()) {
  const int d = shape.dim();
  const std::size_t half = cells_ / n_.back() * (n_.back() / 2 + 1);  // r2c output size
  plans_->real = fftw_alloc_real(cells_);
  plans_->spectrum = fftw_alloc_complex(half);
  if (!plans_->real || !plans_->spectrum) throw std::bad_alloc();
  // FFTW_ESTIMATE: no timing measurements, so the plan (and every bit of the result) is reproducible.
  plans_->forward = fftw_plan_dft_r2c(d, n_.data(), plans_->real, plans_->spectrum, FFTW_ESTIMATE);
  plans_->backward = fftw_plan_dft_c2r(d, n_.data(), plans_->spectrum, plans_->real, FFTW_ESTIMATE);
  if (!plans_->forward || !plans_->backward) throw std::bad_alloc();
  field_.assign(cells_, 0.0);

  // Shells: |x| / h rounded to the nearest integer, h the finest spacing; only whole shells.
  const auto& sp = shape.spacing();
  const double h = *std::min_element(sp.begin(), sp.end());
  double half_box = std::numeric_limits<double>::infinity();
  for (int k = 0; k < d; ++k) half_box = std::min(half_box, n_[k] * sp[k] / (2 * h));
  const int last = static_cast<int>(std::floor(half_box + 1e-9));
  radius_.resize(last + 1);
  for (int b = 0; b <= last; ++b) radius_[b] = b * h;
  shell_.assign(cells_, -1);
  std::vector<double> count(last + 1, 0.0);
  std::vector<int> idx(d, 0);
  for (std::size_t c = 0; c < cells_; ++c) {
    double r2 = 0;
    for (int k = 0; k < d; ++k) {
      const double dx = std::min(idx[k], n_[k] - idx[k]) * sp[k];  // minimum image
      r2 += dx * dx;
    }
    const long b = std::lround(std::sqrt(r2) / h);
    if (b <= last) {
      shell_[c] = static_cast<std::int32_t>(b);
      count[b] += 1;
    }
    for (int k = d - 1; k >= 0; --k) {
      if (++idx[k] < n_[k]) break;
      idx[k] = 0;
    }
  }
  inv_shell_count_.resize(count.size());
  for (std::size_t b = 0; b < count.size(); ++b) inv_shell_count_[b] = 1.0 / count[b];
}

Correlator::~Correlator() = default;

const std::vector<double>& Correlator::field(const DensityGrid& grid) {
  const auto& psi = grid.psi();
  double* real = plans_->real;
  long sum = 0;
  for (std::size_t c = 0; c < cells_; ++c) sum += psi[c];
  const double mean = static_cast<double>(sum) / static_cast<double>(cells_);
  for (std::size_t c = 0; c < cells_; ++c) real[c] = psi[c] - mean;

  fftw_execute(plans_->forward);
  const std::size_t half = cells_ / n_.back() * (n_.back() / 2 + 1);
  fftw_complex* s = plans_->spectrum;
  for (std::size_t m = 0; m < half; ++m) {
    s[m][0] = s[m][0] * s[m][0] + s[m][1] * s[m][1];
    s[m][1] = 0;
  }
  fftw_execute(plans_->backward);  // real = cells^2 C_o (unnormalised transforms)

  const double zero = real[0];
  if (zero > 0) {
    const double inv = 1.0 / zero;
    for (std::size_t c = 0; c < cells_; ++c) field_[c] = real[c] * inv;
    field_[0] = 1.0;
  } else {  // uniform psi: C_o = 0 identically
    std::fill(field_.begin(), field_.end(), std::numeric_limits<double>::quiet_NaN());
  }
  return field_;
}

CorrelationResult Correlator::compute(const DensityGrid& grid, double a) {
  const auto& f = field(grid);
  CorrelationResult out;
  out.r = radius_;
  out.C.assign(radius_.size(), 0.0);
  for (std::size_t c = 0; c < cells_; ++c) {
    const std::int32_t b = shell_[c];
    if (b >= 0) out.C[b] += f[c];
  }
  for (std::size_t b = 0; b < out.C.size(); ++b) out.C[b] *= inv_shell_count_[b];
  out.length = crossing_length(out.r, out.C, a);
  return out;
}

}  // namespace gg
