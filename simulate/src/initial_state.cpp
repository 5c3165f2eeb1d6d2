#include "ggsim/initial_state.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <string>

#include "gg/errors.hpp"
#include "ggsim/cell_grid.hpp"
#include "ggsim/z_order.hpp"

namespace ggsim {

namespace {

// Particles near each other in space are put near each other in memory (Z-order of cells two
// diameters wide): the engine then finds a particle's neighbours in the same cache lines.
// A mixture's sizes follow their particles.
template <int D>
void sort_in_space(const gg::Box<D>& box, std::vector<Vec<D>>& r, Sizes* sizes) {
  std::vector<std::uint64_t> key(r.size());
  for (std::size_t i = 0; i < r.size(); ++i) {
    std::array<std::uint64_t, D> cell;
    for (int k = 0; k < D; ++k) cell[k] = static_cast<std::uint64_t>(r[i][k] / 2.0);
    key[i] = z_order_key<D>(cell);
  }
  std::vector<std::size_t> order(r.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return key[a] < key[b]; });
  std::vector<Vec<D>> sorted(r.size());
  for (std::size_t i = 0; i < r.size(); ++i) sorted[i] = r[order[i]];
  r.swap(sorted);
  if (sizes) sizes->permute(order);
  (void)box;
}

}  // namespace

template <int D>
std::vector<Vec<D>> random_positions(const gg::Box<D>& box, std::size_t n, Random& rng, Sizes* sizes) {
  // Cells one largest diameter wide: an overlap can only come from the 3^d around.
  const double diameter = sizes ? 2 * *std::max_element(sizes->radius.begin(), sizes->radius.end()) : 1.0;
  CellGrid<D> cells(box, diameter, n);
  std::vector<Vec<D>> r;
  r.reserve(n);
  // Random sequential addition jams at phi ~ 0.384 (3D), 0.547 (2D) and 0.7476 (1D); long before that the
  // number of tries per disk explodes, so give up after a generous budget.
  const std::uint64_t budget = 2000 * static_cast<std::uint64_t>(n) + 100000;
  std::uint64_t tries = 0;
  while (r.size() < n) {
    if (++tries > budget)
      throw gg::UsageError("random insertion placed only " + std::to_string(r.size()) + " of " +
                           std::to_string(n) + " disks: the density is beyond what it can reach; lower "
                           "--rho" + (sizes ? " or the radii" : " or use --init lattice"));
    Vec<D> x;
    for (int k = 0; k < D; ++k) x[k] = box.L[k] * rng.uniform();
    bool free = true;
    const std::size_t i = r.size();
    cells.for_each_near(cells.encode(x), [&](std::uint32_t j, const auto&) {
      Vec<D> d;
      for (int k = 0; k < D; ++k) d[k] = box.min_image(x[k] - r[j][k], k);
      const double contact = sizes ? sizes->radius[i] + sizes->radius[j] : 1.0;
      if (dot<D>(d, d) < contact * contact) free = false;
    });
    if (!free) continue;
    cells.insert(static_cast<std::uint32_t>(r.size()), x);
    r.push_back(x);
  }
  sort_in_space<D>(box, r, sizes);
  return r;
}

namespace {

// Neighbours on a lattice start are at least this much more than a diameter apart: disks that
// touch at t = 0 (a spacing of exactly 1) collide again and again at the same instant, and the
// engine stops as if the gas had collapsed.
constexpr double kLatticeGap = 1e-3;

// Sites of the 2D lattice for n disks: nx x ny, and the nearest-neighbour distance (0 if none fits).
struct TriangularFit {
  std::size_t nx = 0, ny = 0;
  double spacing = 0;
};

TriangularFit triangular_fit(const gg::Box<2>& box, std::size_t n) {
  // Triangular lattice of nx x ny sites (ny even, so rows shifted by half a spacing close
  // periodically), stretched to fill the box; the (nx, ny) with the widest nearest-neighbour
  // distance wins.
  TriangularFit best;
  for (std::size_t nx = 1; nx <= 2 * n + 2; ++nx) {
    std::size_t ny = (n + nx - 1) / nx;
    ny += ny % 2;
    const double ax = box.L[0] / static_cast<double>(nx), ay = box.L[1] / static_cast<double>(ny);
    const double gap = std::min({ax, std::hypot(ax / 2, ay), ny > 2 ? 2 * ay : box.L[1]});
    if (gap > best.spacing) best = {nx, ny, gap};
    if (ax < 0.5) break;
  }
  return best;
}

bool lattice_fits(const gg::Box<1>& box, std::size_t n) { return box.L[0] / static_cast<double>(n) >= 1 + kLatticeGap; }
bool lattice_fits(const gg::Box<2>& box, std::size_t n) { return triangular_fit(box, n).spacing >= 1 + kLatticeGap; }

// Refuses n disks that the lattice cannot hold with a gap, naming the most it holds in this box.
template <int D>
void require_lattice_fits(const gg::Box<D>& box, std::size_t n) {
  if (lattice_fits(box, n)) return;
  std::size_t most = 0, above = n;  // lattice_fits(most) (or most = 0), !lattice_fits(above)
  while (above - most > 1) {
    const std::size_t mid = most + (above - most) / 2;
    (lattice_fits(box, mid) ? most : above) = mid;
  }
  double volume = 1;
  for (int k = 0; k < D; ++k) volume *= box.L[k];
  char rho[32];
  std::snprintf(rho, sizeof rho, "%.6g", static_cast<double>(most) / volume);
  throw gg::UsageError("a lattice of " + std::to_string(n) + (D == 1 ? " rods" : " disks") +
                       " leaves no gap between neighbours in this box; the lattice start holds at most N = " +
                       std::to_string(most) + " here (--rho " + rho + "); lower --N or --rho");
}

}  // namespace

template <>
std::vector<Vec<1>> lattice_positions<1>(const gg::Box<1>& box, std::size_t n) {
  require_lattice_fits<1>(box, n);
  const double a = box.L[0] / static_cast<double>(n);
  std::vector<Vec<1>> r(n);
  for (std::size_t i = 0; i < n; ++i) r[i][0] = (static_cast<double>(i) + 0.5) * a;
  return r;
}

template <>
std::vector<Vec<2>> lattice_positions<2>(const gg::Box<2>& box, std::size_t n) {
  require_lattice_fits<2>(box, n);
  const TriangularFit fit = triangular_fit(box, n);
  const std::size_t bx = fit.nx, by = fit.ny;
  std::vector<Vec<2>> r;
  r.reserve(n);
  const double ax = box.L[0] / static_cast<double>(bx), ay = box.L[1] / static_cast<double>(by);
  for (std::size_t j = 0; j < by && r.size() < n; ++j)
    for (std::size_t i = 0; i < bx && r.size() < n; ++i)
      r.push_back({(static_cast<double>(i) + 0.25 + 0.5 * static_cast<double>(j % 2)) * ax,
                   (static_cast<double>(j) + 0.5) * ay});
  return r;
}

template <>
std::vector<Vec<3>> lattice_positions<3>(const gg::Box<3>& box, std::size_t n) {
  // Face-centred cubic lattice of m^3 cubic cells of 4 sites each (the densest packing, eta up to
  // pi / (3 sqrt 2) = 0.7405), stretched to fill the box; the m with 4 m^3 >= N.
  std::size_t m = 1;
  while (4 * m * m * m < n) ++m;
  std::array<double, 3> a;
  for (int k = 0; k < 3; ++k) a[k] = box.L[k] / static_cast<double>(m);
  // Nearest neighbours are half a face diagonal apart; they keep the same gap as the 1D and 2D lattices.
  const double spacing = std::min({std::hypot(a[0], a[1]), std::hypot(a[0], a[2]), std::hypot(a[1], a[2])}) / 2;
  if (spacing < 1 + kLatticeGap)
    throw gg::UsageError("a lattice of " + std::to_string(n) + " spheres leaves no gap between neighbours in this "
                         "box (the face-centred cubic lattice holds up to packing fraction 0.7405); lower --N or --rho");
  constexpr double kBasis[4][3] = {{0, 0, 0}, {0.5, 0.5, 0}, {0.5, 0, 0.5}, {0, 0.5, 0.5}};
  std::vector<Vec<3>> r;
  r.reserve(n);
  for (std::size_t i = 0; i < m && r.size() < n; ++i)
    for (std::size_t j = 0; j < m && r.size() < n; ++j)
      for (std::size_t k = 0; k < m && r.size() < n; ++k)
        for (const auto& b : kBasis) {
          if (r.size() == n) break;
          r.push_back({(static_cast<double>(i) + b[0] + 0.25) * a[0], (static_cast<double>(j) + b[1] + 0.25) * a[1],
                       (static_cast<double>(k) + b[2] + 0.25) * a[2]});
        }
  return r;
}

template <int D>
void set_temperature(std::vector<Vec<D>>& v, double T0) {
  Vec<D> mean{};
  for (const auto& u : v)
    for (int k = 0; k < D; ++k) mean[k] += u[k];
  for (int k = 0; k < D; ++k) mean[k] /= static_cast<double>(v.size());
  double sum2 = 0;
  for (auto& u : v)
    for (int k = 0; k < D; ++k) u[k] -= mean[k], sum2 += u[k] * u[k];
  if (sum2 == 0) return;  // a single particle, or all at rest: nothing to scale
  const double scale = std::sqrt(T0 * D * static_cast<double>(v.size()) / sum2);
  for (auto& u : v)
    for (int k = 0; k < D; ++k) u[k] *= scale;
}

template <int D>
std::vector<Vec<D>> maxwellian_velocities(std::size_t n, double T0, Random& rng) {
  std::vector<Vec<D>> v(n);
  for (auto& u : v)
    for (int k = 0; k < D; ++k) u[k] = rng.normal();
  set_temperature<D>(v, T0);
  return v;
}

template <int D>
void set_temperature(std::vector<Vec<D>>& v, double T0, const std::vector<double>& mass) {
  Vec<D> momentum{};
  double total = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    total += mass[i];
    for (int k = 0; k < D; ++k) momentum[k] += mass[i] * v[i][k];
  }
  double sum2 = 0;
  for (std::size_t i = 0; i < v.size(); ++i)
    for (int k = 0; k < D; ++k) v[i][k] -= momentum[k] / total, sum2 += mass[i] * v[i][k] * v[i][k];
  if (sum2 == 0) return;
  const double scale = std::sqrt(T0 * D * static_cast<double>(v.size()) / sum2);
  for (auto& u : v)
    for (int k = 0; k < D; ++k) u[k] *= scale;
}

template <int D>
std::vector<Vec<D>> maxwellian_velocities(const std::vector<double>& mass, double T0, Random& rng) {
  std::vector<Vec<D>> v(mass.size());
  for (std::size_t i = 0; i < v.size(); ++i)
    for (int k = 0; k < D; ++k) v[i][k] = rng.normal() / std::sqrt(mass[i]);
  set_temperature<D>(v, T0, mass);
  return v;
}

template std::vector<Vec<1>> random_positions<1>(const gg::Box<1>&, std::size_t, Random&, Sizes*);
template std::vector<Vec<2>> random_positions<2>(const gg::Box<2>&, std::size_t, Random&, Sizes*);
template std::vector<Vec<3>> random_positions<3>(const gg::Box<3>&, std::size_t, Random&, Sizes*);  // engine tests in 3D
template std::vector<Vec<1>> maxwellian_velocities<1>(std::size_t, double, Random&);
template std::vector<Vec<2>> maxwellian_velocities<2>(std::size_t, double, Random&);
template std::vector<Vec<3>> maxwellian_velocities<3>(std::size_t, double, Random&);
template void set_temperature<1>(std::vector<Vec<1>>&, double);
template void set_temperature<2>(std::vector<Vec<2>>&, double);
template void set_temperature<3>(std::vector<Vec<3>>&, double);
template std::vector<Vec<1>> maxwellian_velocities<1>(const std::vector<double>&, double, Random&);
template std::vector<Vec<2>> maxwellian_velocities<2>(const std::vector<double>&, double, Random&);
template std::vector<Vec<3>> maxwellian_velocities<3>(const std::vector<double>&, double, Random&);
template void set_temperature<1>(std::vector<Vec<1>>&, double, const std::vector<double>&);
template void set_temperature<2>(std::vector<Vec<2>>&, double, const std::vector<double>&);
template void set_temperature<3>(std::vector<Vec<3>>&, double, const std::vector<double>&);

}  // namespace ggsim
