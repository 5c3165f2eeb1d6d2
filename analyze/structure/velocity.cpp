#include "velocity.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <limits>
#include <numbers>

#include "gg/particle_volume.hpp"

#include "correlation.hpp"

namespace gg {

namespace {

// The centre-of-mass velocity V [d].
std::vector<double> mean_velocity(const double* v, const double* mass, std::size_t n, int d) {
  std::vector<double> V(d, 0.0);
  double M = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double m = mass ? mass[i] : 1.0;
    M += m;
    for (int k = 0; k < d; ++k) V[k] += m * v[i * d + k];
  }
  for (double& x : V) x = M > 0 ? x / M : 0.0;
  return V;
}

// w_i = m_i |v_i - V|^2, twice the peculiar kinetic energy of each particle.
std::vector<double> twice_energies(const double* v, const double* mass, std::size_t n, int d) {
  const std::vector<double> V = mean_velocity(v, mass, n, d);
  std::vector<double> w(n);
  for (std::size_t i = 0; i < n; ++i) {
    double s = 0;
    for (int k = 0; k < d; ++k) s += (v[i * d + k] - V[k]) * (v[i * d + k] - V[k]);
    w[i] = (mass ? mass[i] : 1.0) * s;
  }
  return w;
}

}  // namespace

SonineResult sonine_coefficients(const double* velocity, const double* mass, std::size_t n, int d) {
  SonineResult r;
  const std::vector<double> V = mean_velocity(velocity, mass, n, d);
  r.temperature.assign(d, 0.0);
  for (std::size_t i = 0; i < n; ++i)
    for (int k = 0; k < d; ++k) {
      const double dv = velocity[i * d + k] - V[k];
      r.temperature[k] += (mass ? mass[i] : 1.0) * dv * dv;
    }
  for (double& T : r.temperature) T /= static_cast<double>(n);
  for (double T : r.temperature) r.T += T / d;
  if (n < 2 || !(r.T > 0)) {
    r.a2 = r.a2_stderr = r.a3 = r.a3_stderr = kNaN;
    return r;
  }
  // Sample moments mu_p = <w^p>, p = 1..6, of w scaled by <w> (for range).
  const std::vector<double> w = twice_energies(velocity, mass, n, d);
  const double scale = r.T * d;
  std::array<double, 7> mu{};
  for (double x : w) {
    const double y = x / scale;
    double p = 1;
    for (int k = 1; k <= 6; ++k) p *= y, mu[k] += p;
  }
  for (double& m : mu) m /= static_cast<double>(n);
  const double K2 = static_cast<double>(d) / (d + 2), K3 = static_cast<double>(d * d) / ((d + 2) * (d + 4));
  const double m1 = mu[1], m2 = mu[2], m3 = mu[3];
  r.a2 = K2 * m2 / (m1 * m1) - 1;
  r.a3 = 1 + 3 * r.a2 - K3 * m3 / (m1 * m1 * m1);
  // Delta method: var(f) = g^T Cov g / N, Cov_ab = mu_(a+b) - mu_a mu_b over (mu1, mu2, mu3).
  const std::array<double, 3> g2 = {-2 * K2 * m2 / (m1 * m1 * m1), K2 / (m1 * m1), 0.0};
  const std::array<double, 3> g3 = {3 * g2[0] + 3 * K3 * m3 / (m1 * m1 * m1 * m1), 3 * g2[1], -K3 / (m1 * m1 * m1)};
  const auto variance = [&](const std::array<double, 3>& g) {
    double s = 0;
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) s += g[a] * g[b] * (mu[a + b + 2] - mu[a + 1] * mu[b + 1]);
    return s / static_cast<double>(n);
  };
  r.a2_stderr = std::sqrt(std::max(0.0, variance(g2)));
  r.a3_stderr = std::sqrt(std::max(0.0, variance(g3)));
  return r;
}

std::vector<double> speed_bin_edges(double dc, double body_max, int per_decade, double top) {
  std::vector<double> edges;
  const long body = std::lround(body_max / dc);
  for (long b = 0; b <= body; ++b) edges.push_back(b * dc);
  const double ratio = std::pow(10.0, 1.0 / per_decade);
  for (int j = 1; edges.back() < top; ++j) edges.push_back(edges[body] * std::pow(ratio, j));
  return edges;
}

SpeedDistribution speed_distribution(const double* velocity, const double* mass, std::size_t n, int d,
                                     const std::vector<double>& edges, double tail_from, double min_count) {
  SpeedDistribution out;
  const std::size_t B = edges.size() - 1;
  out.f.assign(B, 0.0);
  out.counts.assign(B, 0.0);
  out.tail_A = out.tail_b = out.tail_f0 = kNaN;
  const std::vector<double> w = twice_energies(velocity, mass, n, d);
  double sum = 0;
  for (double x : w) sum += x;
  if (n == 0 || !(sum > 0)) {
    std::fill(out.f.begin(), out.f.end(), kNaN);
    return out;
  }
  const double two_T = 2 * sum / (static_cast<double>(n) * d);  // c^2 = m |v - V|^2 / (2 T)
  for (double x : w) {
    const double c = std::sqrt(x / two_T);
    const auto it = std::upper_bound(edges.begin(), edges.end(), c);
    if (it == edges.begin() || it == edges.end()) continue;  // beyond the last edge
    out.counts[static_cast<std::size_t>(it - edges.begin()) - 1] += 1;
  }
  for (std::size_t b = 0; b < B; ++b)
    out.f[b] = out.counts[b] / (static_cast<double>(n) * (particle_volume(edges[b + 1], d) - particle_volume(edges[b], d)));

  // The bins of the tail fit.
  std::vector<std::size_t> bins;
  for (std::size_t b = 0; b < B; ++b) {
    if (edges[b] < tail_from) continue;
    if (out.counts[b] < min_count) break;
    bins.push_back(b);
  }
  out.tail_bins = static_cast<int>(bins.size());
  if (bins.size() < 3) return out;

  // ln of the model exp(-A c^b) averaged over a bin's c-space volume (8-point Gauss-Legendre in c).
  // What does not depend on (A, b) is computed once per bin: the fit evaluates each bin ~1700 times.
  static constexpr std::array<double, 4> x = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267,
                                               0.9602898564975363};
  static constexpr std::array<double, 4> wt = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745,
                                                0.1012285362903763};
  struct TailBin {
    std::array<double, 8> c, log_weight;  // the nodes, and ln(weight c^(d-1)) at each
    double half, volume, log_f, count;    // half width, hi^d - lo^d, ln f and the particles of the bin
  };
  std::vector<TailBin> tail(bins.size());
  for (std::size_t k = 0; k < bins.size(); ++k) {
    const std::size_t j = bins[k];
    const double lo = edges[j], hi = edges[j + 1], mid = (lo + hi) / 2, half = (hi - lo) / 2;
    TailBin& t = tail[k];
    for (int q = 0; q < 4; ++q)
      for (int side = 0; side < 2; ++side) {
        const double c = mid + (side ? 1 : -1) * half * x[q];
        t.c[2 * q + side] = c;
        t.log_weight[2 * q + side] = std::log(wt[q]) + (d - 1) * std::log(c);
      }
    t.half = half, t.volume = std::pow(hi, d) - std::pow(lo, d);
    t.log_f = std::log(out.f[j]), t.count = out.counts[j];
  }
  const auto log_model = [&](const TailBin& t, double A, double b) {
    // In logarithms, largest term first, so that exp(-A c^b) below the smallest double stays finite.
    std::array<double, 8> lg{};
    for (int p = 0; p < 8; ++p) lg[p] = t.log_weight[p] - A * std::pow(t.c[p], b);
    const double top = *std::max_element(lg.begin(), lg.end());
    double s = 0;
    for (double l : lg) s += std::exp(l - top);
    return top + std::log(s * t.half * d / t.volume);
  };
  // chi2(A, b) with ln f0 at its optimum (the weighted mean residual); returns ln f0 too.
  std::vector<double> res(tail.size());
  const auto chi2 = [&](double A, double b, double* log_f0) {
    double sw = 0, swr = 0;
    for (std::size_t k = 0; k < tail.size(); ++k) {
      res[k] = tail[k].log_f - log_model(tail[k], A, b);
      sw += tail[k].count, swr += tail[k].count * res[k];
    }
    const double mean = swr / sw;
    double s = 0;
    for (std::size_t k = 0; k < tail.size(); ++k) s += tail[k].count * (res[k] - mean) * (res[k] - mean);
    if (log_f0) *log_f0 = mean;
    return s;
  };
  const auto golden = [](double lo, double hi, const auto& f) {
    const double g = (std::sqrt(5.0) - 1) / 2;
    double a = hi - g * (hi - lo), b = lo + g * (hi - lo), fa = f(a), fb = f(b);
    for (int it = 0; it < 60 && hi - lo > 1e-7; ++it) {
      if (fa < fb) hi = b, b = a, fb = fa, a = hi - g * (hi - lo), fa = f(a);
      else lo = a, a = b, fa = fb, b = lo + g * (hi - lo), fb = f(b);
    }
    return (lo + hi) / 2;
  };
  // For each b, the best ln A (A in [e^-6, e^6]); then the best b in [0.2, 5].
  const auto best_log_A = [&](double b) { return golden(-6.0, 6.0, [&](double la) { return chi2(std::exp(la), b, nullptr); }); };
  const double b = golden(0.2, 5.0, [&](double bb) { return chi2(std::exp(best_log_A(bb)), bb, nullptr); });
  const double A = std::exp(best_log_A(b));
  double log_f0 = 0;
  chi2(A, b, &log_f0);
  out.tail_A = A, out.tail_b = b, out.tail_f0 = std::exp(log_f0);
  return out;
}

FlowAnalyzer::FlowAnalyzer(const DensityGrid& shape)
    : dim_(shape.dim()), fft_(shape.cells_per_side()), shells_(real_space_shells(shape.cells_per_side(), shape.spacing())) {
  const auto& n = shape.cells_per_side();
  const auto& h = shape.spacing();
  const std::size_t cells = shape.size();
  direction_.assign(cells * dim_, 0.0);
  std::vector<int> idx(dim_, 0);
  for (std::size_t c = 0; c < cells; ++c) {
    double r2 = 0;
    for (int k = 0; k < dim_; ++k) {
      const double x = (idx[k] <= n[k] / 2 ? idx[k] : idx[k] - n[k]) * h[k];  // minimum image
      direction_[c * dim_ + k] = x;
      r2 += x * x;
    }
    if (r2 > 0)
      for (int k = 0; k < dim_; ++k) direction_[c * dim_ + k] /= std::sqrt(r2);
    for (int k = dim_ - 1; k >= 0; --k) {
      if (++idx[k] < n[k]) break;
      idx[k] = 0;
    }
  }
}

FlowResult FlowAnalyzer::compute(const DensityGrid& grid, const double* position, const double* velocity,
                                 const double* mass, std::size_t n, double a) {
  const int d = dim_;
  const std::size_t cells = grid.size();
  FlowResult out;
  // Per particle: mass and momentum relative to the centre of mass; summed per cell, then per block.
  const std::vector<double> V = mean_velocity(velocity, mass, n, d);
  values_.resize(n * (d + 1));
  double twice_kinetic = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double m = mass ? mass[i] : 1.0;
    values_[i * (d + 1)] = m;
    for (int k = 0; k < d; ++k) {
      const double dv = velocity[i * d + k] - V[k];
      values_[i * (d + 1) + 1 + k] = m * dv;
      twice_kinetic += m * dv * dv;
    }
  }
  grid.cell_sums(position, n, values_.data(), d + 1, cell_sums_);
  grid.block_sums(cell_sums_, d + 1, block_sums_, scratch_);
  const double* cell_mass = cell_sums_.data();
  const std::vector<double>& sums = block_sums_;
  u_.assign(cells * d, 0.0);
  std::size_t empty = 0;
  double twice_flow = 0;
  for (std::size_t c = 0; c < cells; ++c) {
    const double M = sums[c];
    if (!(M > 0)) {
      ++empty;
      continue;
    }
    for (int k = 0; k < d; ++k) {
      const double u = sums[(k + 1) * cells + c] / M;
      u_[c * d + k] = u;
      twice_flow += cell_mass[c] * u * u;
    }
  }
  out.empty_fraction = static_cast<double>(empty) / static_cast<double>(cells);
  out.energy_fraction = twice_kinetic > 0 ? twice_flow / twice_kinetic : kNaN;

  // Correlations C_ij(x) = <u_i(y) u_j(y + x)> of the fluctuations of u (its mean over the cells
  // removed) by FFT; the symmetric part Re(conj(U_i) U_j) suffices, since r_i r_j is even in x.
  const std::size_t half = fft_.half();
  spectra_.resize(d * half);
  for (int k = 0; k < d; ++k) {
    double* real = fft_.real();
    double mean = 0;
    for (std::size_t c = 0; c < cells; ++c) mean += u_[c * d + k];
    mean /= static_cast<double>(cells);
    for (std::size_t c = 0; c < cells; ++c) real[c] = u_[c * d + k] - mean;
    fft_.forward();
    std::copy(fft_.spectrum(), fft_.spectrum() + half, spectra_.begin() + k * half);
  }
  longitudinal_.assign(cells, 0.0), trace_.assign(cells, 0.0);
  const double norm = 1.0 / (static_cast<double>(cells) * static_cast<double>(cells));
  for (int i = 0; i < d; ++i)
    for (int j = i; j < d; ++j) {
      std::complex<double>* s = fft_.spectrum();
      const std::complex<double>* Ui = spectra_.data() + i * half;
      const std::complex<double>* Uj = spectra_.data() + j * half;
      for (std::size_t m = 0; m < half; ++m) s[m] = (std::conj(Ui[m]) * Uj[m]).real();
      fft_.backward();
      const double* C = fft_.real();
      const double twice = i == j ? 1.0 : 2.0;
      for (std::size_t c = 0; c < cells; ++c) {
        const double Cij = C[c] * norm;
        longitudinal_[c] += twice * direction_[c * d + i] * direction_[c * d + j] * Cij;
        if (i == j) trace_[c] += Cij;
      }
    }
  const double zero = trace_[0] / d;  // C_L(0) = C_T(0) = tr C(0) / d
  out.C_L = shells_.average(longitudinal_.data());
  if (d > 1) {
    transverse_.resize(cells);
    for (std::size_t c = 0; c < cells; ++c) transverse_[c] = (trace_[c] - longitudinal_[c]) / (d - 1);
    out.C_T = shells_.average(transverse_.data());
  } else {
    out.C_T.assign(out.C_L.size(), kNaN);
  }
  out.C_L[0] = zero;
  if (d > 1) out.C_T[0] = zero;
  for (auto* C : {&out.C_L, &out.C_T})
    for (double& x : *C) x = zero > 0 ? x / zero : kNaN;
  out.length_L = crossing_length(shells_.radius, out.C_L, a);
  out.length_T = d > 1 ? crossing_length(shells_.radius, out.C_T, a) : kNaN;

  // Vorticity by central differences (periodic), and the enstrophy (1/2) <|omega|^2>.
  const int nw = vorticity_components();
  omega_.assign(cells * nw, 0.0);
  if (nw == 0) {
    out.enstrophy = kNaN;
    return out;
  }
  const auto& nc = grid.cells_per_side();
  const auto& stride = grid.strides();
  const auto& h = grid.spacing();
  std::vector<int> idx(d, 0);
  double sum2 = 0;
  for (std::size_t c = 0; c < cells; ++c) {
    // du_i / dx_k at cell c.
    const auto derivative = [&](int i, int k) {
      const std::size_t up = idx[k] + 1 < nc[k] ? c + stride[k] : c + stride[k] - nc[k] * stride[k];
      const std::size_t down = idx[k] > 0 ? c - stride[k] : c + (nc[k] - 1) * stride[k];
      return (u_[up * d + i] - u_[down * d + i]) / (2 * h[k]);
    };
    if (d == 2) {
      omega_[c] = derivative(1, 0) - derivative(0, 1);
    } else {
      omega_[c * 3 + 0] = derivative(2, 1) - derivative(1, 2);
      omega_[c * 3 + 1] = derivative(0, 2) - derivative(2, 0);
      omega_[c * 3 + 2] = derivative(1, 0) - derivative(0, 1);
    }
    for (int q = 0; q < nw; ++q) sum2 += omega_[c * nw + q] * omega_[c * nw + q];
    for (int k = d - 1; k >= 0; --k) {
      if (++idx[k] < nc[k]) break;
      idx[k] = 0;
    }
  }
  out.enstrophy = 0.5 * sum2 / static_cast<double>(cells);
  return out;
}

namespace {

// The volume of one of `bins` equal slabs of the box along `axis`: their width times the other edges.
double slab_volume(const std::vector<double>& edges, int axis, std::size_t bins) {
  double volume = edges[axis] / static_cast<double>(bins);
  for (std::size_t k = 0; k < edges.size(); ++k)
    if (static_cast<int>(k) != axis) volume *= edges[k];
  return volume;
}

// The slab of each particle.
std::vector<std::size_t> slab_indices(const double* position, std::size_t n, int d, double L, int axis,
                                      std::size_t bins) {
  std::vector<std::size_t> slab(n);
  for (std::size_t i = 0; i < n; ++i)
    // min: a coordinate just below L may round up to the slab past the last.
    slab[i] = std::min(bins - 1, static_cast<std::size_t>(position[i * d + axis] / L * static_cast<double>(bins)));
  return slab;
}

}  // namespace

SlabProfile slab_profile(const double* position, const double* velocity, const double* mass, std::size_t n,
                         const std::vector<double>& edges, int axis, std::size_t bins) {
  const int d = static_cast<int>(edges.size());
  const std::vector<std::size_t> slab = slab_indices(position, n, d, edges[axis], axis, bins);
  SlabProfile out;
  out.count.assign(bins, 0.0);
  std::vector<double> M(bins, 0.0), P(bins * d, 0.0);
  // A row of mass 0 is no particle: an aggregating run's merged start particles (docs/DESIGN.md
  // "Aggregates") keep their rows with mass 0.
  const auto absent = [&](std::size_t i) { return mass && !(mass[i] > 0); };
  for (std::size_t i = 0; i < n; ++i) {
    if (absent(i)) continue;
    const double m = mass ? mass[i] : 1.0;
    out.count[slab[i]] += 1, M[slab[i]] += m;
    for (int k = 0; k < d; ++k) P[slab[i] * d + k] += m * velocity[i * d + k];
  }
  const double volume = slab_volume(edges, axis, bins);
  out.density.resize(bins);
  out.velocity.assign(bins * d, kNaN);
  for (std::size_t b = 0; b < bins; ++b) {
    out.density[b] = out.count[b] / volume;
    for (int k = 0; k < d && out.count[b] > 0; ++k) out.velocity[b * d + k] = P[b * d + k] / M[b];
  }
  // The peculiar velocities v - u themselves (not sum m v^2 - M u^2, which cancels when u >> v - u).
  std::vector<double> twice_E(bins, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    if (absent(i)) continue;
    double s = 0;
    for (int k = 0; k < d; ++k) {
      const double c = velocity[i * d + k] - out.velocity[slab[i] * d + k];
      s += c * c;
    }
    twice_E[slab[i]] += (mass ? mass[i] : 1.0) * s;
  }
  // count - 1, not count: u is the slab's own mean, which takes one degree of freedom per component;
  // sum m |v - u|^2 then averages to d (count - 1) T for any masses, so that a slab of a few particles
  // in equilibrium at T still reads T.
  out.temperature.assign(bins, kNaN);
  for (std::size_t b = 0; b < bins; ++b)
    if (out.count[b] >= 2) out.temperature[b] = twice_E[b] / (d * (out.count[b] - 1));
  return out;
}

void FrameAverage::add(const std::vector<double>& values) {
  if (frames_.empty()) frames_.assign(values.size(), 0.0), mean_.assign(values.size(), 0.0), m2_.assign(values.size(), 0.0);
  for (std::size_t j = 0; j < values.size(); ++j) {
    if (std::isnan(values[j])) continue;
    frames_[j] += 1;
    const double delta = values[j] - mean_[j];
    mean_[j] += delta / frames_[j];
    m2_[j] += delta * (values[j] - mean_[j]);
  }
}

std::vector<double> FrameAverage::mean() const {
  std::vector<double> out(mean_.size());
  for (std::size_t j = 0; j < out.size(); ++j) out[j] = frames_[j] > 0 ? mean_[j] : kNaN;
  return out;
}

std::vector<double> FrameAverage::standard_error() const {
  std::vector<double> out(mean_.size());
  for (std::size_t j = 0; j < out.size(); ++j)
    out[j] = frames_[j] > 1 ? std::sqrt(m2_[j] / (frames_[j] - 1) / frames_[j]) : kNaN;
  return out;
}

}  // namespace gg
