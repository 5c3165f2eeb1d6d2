#pragma once
// The volume of a particle of radius r in d dimensions (length 2r, area pi r^2, volume 4/3 pi r^3):
// a mixture's masses by default (gg-sim --radii), its packing fraction, and the weight of a particle
// in the density grid of a file with radii (docs/DESIGN.md "Coarse-grained density").
#include <numbers>

namespace gg {

inline double particle_volume(double r, int dim) {
  if (dim == 1) return 2 * r;
  if (dim == 2) return std::numbers::pi * r * r;
  return 4.0 / 3.0 * std::numbers::pi * r * r * r;
}

}  // namespace gg
