#pragma once
// The ballistic aggregation model (BAM; Carnevale, Pomeau & Young, PRL 64, 2913 (1990); the
// paper's eqs. 4-5): two particles that touch merge into one at their centre of mass, with the sum
// of their masses and momenta. The material density is fixed, so mass is volume (length in 1D,
// area in 2D): a start particle has mass 1 and radius 1/2, and an aggregate of mass m has radius
// m^(1/d) / 2, i.e. R^d = R_a^d + R_b^d (as Trizac & Hansen, PRL 74, 4114 (1995), in 2D;
// Frachebourg, PRL 82, 1502 (1999), in 1D, where lengths add).
#include <cmath>

#include "gg/box.hpp"
#include "ggsim/particles.hpp"

namespace ggsim {

// Radius of a particle made of two of radii ra, rb at one material density.
template <int D>
double merged_radius(double ra, double rb) {
  if constexpr (D == 1) return ra + rb;
  else if constexpr (D == 2) return std::sqrt(ra * ra + rb * rb);
  else return std::cbrt(ra * ra * ra + rb * rb * rb);
}

// Merges b (mass mb) into a (mass ma), both at the same time: a moves to their centre of mass,
// r_ab = r_a - r_b being their minimum-image separation, and takes their summed momentum.
template <int D>
void merge_into(Particle<D>& a, double ma, const Particle<D>& b, double mb, const Vec<D>& r_ab, const gg::Box<D>& box) {
  const double m = ma + mb, wb = mb / m;
  for (int k = 0; k < D; ++k) {
    a.r[k] = box.wrap_near(a.r[k] - wb * r_ab[k], k);
    a.v[k] = (ma * a.v[k] + mb * b.v[k]) / m;
  }
}

}  // namespace ggsim
