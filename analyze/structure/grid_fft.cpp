#include "grid_fft.hpp"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <new>
#include <numbers>

namespace gg {

struct GridFft::Plans {
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

GridFft::GridFft(const std::vector<int>& n) : plans_(std::make_unique<Plans>()) {
  cells_ = 1;
  for (int m : n) cells_ *= static_cast<std::size_t>(m);
  half_ = cells_ / n.back() * (n.back() / 2 + 1);
  plans_->real = fftw_alloc_real(cells_);
  plans_->spectrum = fftw_alloc_complex(half_);
  if (!plans_->real || !plans_->spectrum) throw std::bad_alloc();
  const int d = static_cast<int>(n.size());
  // FFTW_ESTIMATE: no timing measurements, so the plan (and every bit of the result) is reproducible.
  plans_->forward = fftw_plan_dft_r2c(d, n.data(), plans_->real, plans_->spectrum, FFTW_ESTIMATE);
  plans_->backward = fftw_plan_dft_c2r(d, n.data(), plans_->spectrum, plans_->real, FFTW_ESTIMATE);
  if (!plans_->forward || !plans_->backward) throw std::bad_alloc();
}

GridFft::~GridFft() = default;

double* GridFft::real() { return plans_->real; }
std::complex<double>* GridFft::spectrum() { return reinterpret_cast<std::complex<double>*>(plans_->spectrum); }
void GridFft::forward() { fftw_execute(plans_->forward); }
void GridFft::backward() { fftw_execute(plans_->backward); }

std::vector<double> Shells::average(const double* values) const {
  std::vector<double> out(radius.size(), 0.0);
  for (std::size_t c = 0; c < shell.size(); ++c)
    if (shell[c] >= 0) out[shell[c]] += weight[c] * values[c];
  for (std::size_t b = 0; b < out.size(); ++b) out[b] *= inv_weight[b];
  return out;
}

namespace {

// Shells of width `step` of the lengths |x| of the entries of an array of `extent` entries per
// axis, x_j = index_j * unit_j folded by `fold` (minimum image or the wave vector's sign); entry
// weights from `weight_of`; shells 0 .. floor(limit / step).
template <class Fold, class WeightOf>
Shells make_shells(const std::vector<int>& extent, const std::vector<double>& unit, double step, double limit,
                   Fold fold, WeightOf weight_of) {
  const int d = static_cast<int>(extent.size());
  Shells s;
  const int last = static_cast<int>(std::floor(limit / step + 1e-9));
  s.radius.resize(last + 1);
  for (int b = 0; b <= last; ++b) s.radius[b] = b * step;
  std::size_t entries = 1;
  for (int m : extent) entries *= static_cast<std::size_t>(m);
  s.shell.assign(entries, -1);
  s.weight.assign(entries, 0.0);
  std::vector<double> total(last + 1, 0.0);
  std::vector<int> idx(d, 0);
  for (std::size_t c = 0; c < entries; ++c) {
    double r2 = 0;
    for (int k = 0; k < d; ++k) {
      const double x = fold(idx[k], k) * unit[k];
      r2 += x * x;
    }
    const long b = std::lround(std::sqrt(r2) / step);
    s.weight[c] = weight_of(idx);
    if (b <= last) {
      s.shell[c] = static_cast<std::int32_t>(b);
      total[b] += s.weight[c];
    }
    for (int k = d - 1; k >= 0; --k) {
      if (++idx[k] < extent[k]) break;
      idx[k] = 0;
    }
  }
  s.inv_weight.resize(total.size());
  for (std::size_t b = 0; b < total.size(); ++b) s.inv_weight[b] = 1.0 / total[b];
  return s;
}

}  // namespace

Shells real_space_shells(const std::vector<int>& n, const std::vector<double>& spacing) {
  const int d = static_cast<int>(n.size());
  const double h = *std::min_element(spacing.begin(), spacing.end());
  double half_box = std::numeric_limits<double>::infinity();
  for (int k = 0; k < d; ++k) half_box = std::min(half_box, n[k] * spacing[k] / 2);
  return make_shells(
      n, spacing, h, half_box, [&](int i, int k) { return std::min(i, n[k] - i); },  // minimum image
      [](const std::vector<int>&) { return 1.0; });
}

Shells wave_vector_shells(const std::vector<int>& n, const std::vector<double>& spacing) {
  const int d = static_cast<int>(n.size());
  std::vector<int> extent = n;
  extent.back() = n.back() / 2 + 1;
  std::vector<double> unit(d);
  double longest = 0, nyquist = std::numeric_limits<double>::infinity();
  for (int k = 0; k < d; ++k) {
    const double L = n[k] * spacing[k];
    unit[k] = 2 * std::numbers::pi / L;
    longest = std::max(longest, L);
    nyquist = std::min(nyquist, std::numbers::pi * n[k] / L);
  }
  const int nl = n.back();
  return make_shells(
      extent, unit, 2 * std::numbers::pi / longest, nyquist,
      [&](int i, int k) { return k == d - 1 ? i : (i <= n[k] / 2 ? i : i - n[k]); },
      [&](const std::vector<int>& idx) {
        const int q = idx[d - 1];
        return q == 0 || (nl % 2 == 0 && q == nl / 2) ? 1.0 : 2.0;
      });
}

}  // namespace gg
