#pragma once
// The radial distribution function g(r) of the particles themselves (not of the grid), in a periodic
// box of any dimension (docs/DESIGN.md "Correlation"):
//   g(r_b) = (2 / N) (pairs with |r_ij| in bin b) / ((N - 1) / V * volume of the shell of bin b),
// minimum-image separations, bins [b dr, (b + 1) dr) up to r_max <= L_min / 2, reported at the bin
// centres. Its contact value g(sigma+) is the chi of the Enskog formulas (docs/PHYSICS.md).
#include <cstddef>
#include <vector>

namespace gg {

struct RadialDistribution {
  std::vector<double> r;  // bin centres [B]
  std::vector<double> g;  // [B]; NaN for fewer than 2 particles
};

// `positions` [N][d] (d = edges.size(), wrapped into the box if outside); r_max is cut to L_min / 2.
// Pairs are found through cells at least r_max wide, so the cost is N times the particles within
// r_max.
RadialDistribution radial_distribution(const double* positions, std::size_t n, const std::vector<double>& edges,
                                       double r_max, double dr);

// g(sigma+): the least-squares line through the bins whose centres lie in (sigma, sigma + width],
// evaluated at sigma; NaN with fewer than 2 such bins or a NaN among them.
double contact_value(const RadialDistribution& g, double sigma, double width);

}  // namespace gg
