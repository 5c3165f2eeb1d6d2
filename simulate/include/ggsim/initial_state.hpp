#pragma once
// Initial conditions: random homogeneous positions (random sequential addition) or a lattice,
// Maxwellian velocities with zero total momentum and temperature exactly T0.
#include <cstdint>
#include <vector>

#include "gg/box.hpp"
#include "ggsim/prediction.hpp"
#include "ggsim/mixture.hpp"
#include "ggsim/random.hpp"

namespace ggsim {

// N non-overlapping disks placed one by one at uniformly random free spots (random sequential
// addition). Throws gg::UsageError if the density is beyond what insertion can reach. With a
// mixture's sizes (n of them, larger radii first: draw_sizes()), contact at R_i + R_j, the larger
// placed first (they find room while there is most); the sizes are reordered with the positions.
template <int D>
std::vector<Vec<D>> random_positions(const gg::Box<D>& box, std::size_t n, Random& rng, Sizes* sizes = nullptr);

// N disks on a lattice filling the box (square in 1D, triangular in 2D, which reaches phi up to
// 0.9069; face-centred cubic in 3D, up to 0.7405); sites beyond N stay empty. Neighbours keep a gap
// (no two particles touch at t = 0): throws gg::UsageError naming the most the lattice holds in the
// box if N is more.
template <int D>
std::vector<Vec<D>> lattice_positions(const gg::Box<D>& box, std::size_t n);

// Gaussian velocities, shifted to zero total momentum and scaled so that
// T = sum v^2 / (d N) = T0 exactly (docs/DESIGN.md: T = m <v_x^2>).
template <int D>
std::vector<Vec<D>> maxwellian_velocities(std::size_t n, double T0, Random& rng);

// Shifts to zero total momentum and rescales to temperature T0 (used after equilibration).
template <int D>
void set_temperature(std::vector<Vec<D>>& v, double T0);

// The same for particles of masses `mass`: v_i Gaussian of variance T0 / m_i per component, zero
// total momentum sum m_i v_i, and T = sum m v^2 / (d N) = T0 exactly.
template <int D>
std::vector<Vec<D>> maxwellian_velocities(const std::vector<double>& mass, double T0, Random& rng);
template <int D>
void set_temperature(std::vector<Vec<D>>& v, double T0, const std::vector<double>& mass);

}  // namespace ggsim
