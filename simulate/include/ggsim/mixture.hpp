#pragma once
// Mixtures and polydisperse gases (gg-sim --radii, --masses, --fractions; docs/DESIGN.md
// "Mixtures"): a radius, a mass and a species per particle. The unit of length stays sigma, the
// diameter of a default particle (radius 1/2, mass 1); --rho stays the number density.
//
//   --radii 0.5,0.7 [--masses 1,2] [--fractions 0.5,0.5]   k species, in order
//   --radii uniform:0.4:0.6 [--masses 1]                    radii uniform in [0.4, 0.6], one species
//   --masses 1,4 [--fractions ...]                          radius 1/2, masses per species
//
// A mass not given is the volume at unit material density, m = (2R)^d (1 for a default particle).
#include <cstdint>
#include <string>
#include <vector>

#include "ggsim/random.hpp"

namespace ggsim {

// What a scene asks of a mixture (src/scene/mixture_scene.cpp), as given: radii per species or
// "uniform:LO:HI", masses per species (or one), number fractions per species; none: all empty.
struct MixtureParameters {
  std::string radii{}, masses{}, fractions{};
  bool given() const { return !radii.empty() || !masses.empty(); }
};

// What the scene asks for, parsed and checked (a malformed or impossible one throws gg::UsageError).
struct MixtureSpec {
  std::vector<double> radius;    // per species; with `uniform`, the bounds [lo, hi]
  std::vector<double> mass;      // per species (empty: by volume); with `uniform`, one constant or none
  std::vector<double> fraction;  // per species, summing to 1
  bool uniform = false;          // radii drawn uniformly between the two bounds (one species)

  static MixtureSpec parse(const std::string& radii, const std::string& masses, const std::string& fractions);
  std::size_t species() const { return uniform ? 1 : fraction.size(); }
  // Mean particle volume <v_d R^d> (length, area or volume), for the packing fraction rho <v>.
  double mean_volume(int dim) const;
};

// Per particle, by the number in the start. Empty vectors: every particle radius 1/2, mass 1,
// species 0 (a gas without mixture).
struct Sizes {
  std::vector<double> radius{}, mass{};
  std::vector<std::uint32_t> species{};
  std::uint32_t species_count = 1;

  bool empty() const { return radius.empty(); }
  // Reorders all three as order[k] = old number of the new k.
  void permute(const std::vector<std::size_t>& order);
};


// The n particles of a mixture, larger radii first (the random start places them in that order),
// drawn from rng for a distribution; the same spec, n and generator state give the same sizes.
Sizes draw_sizes(const MixtureSpec& spec, std::size_t n, int dim, Random& rng);

}  // namespace ggsim
