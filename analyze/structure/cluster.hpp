#pragma once
// Clusters of the coarse-grained density (docs/DESIGN.md "Cluster"; paper Fig. 3): connected sets of cells
// with psi = +1, periodic in every direction. Mass = particles whose centres lie in the cluster's cells.
// Each cluster also knows the axes along which it wraps the periodic box (docs/PHYSICS.md "Wrapping and
// the giant cluster").
#include <cstddef>
#include <cstdint>
#include <vector>

#include "gg/density_grid.hpp"

namespace gg {

// Which cells touch. `face`: cells sharing a face (2d neighbours; "4" on the command line, 4 in 2D).
// `full`: cells sharing a face, an edge or a corner (3^d - 1 neighbours; "8", 8 in 2D).
// In 1D both are the left and right neighbours.
enum class Connectivity { face, full };

struct Cluster {
  std::int64_t mass = 0;        // particles in its cells
  std::int64_t cells = 0;       // number of cells
  std::size_t first_cell = 0;   // smallest row-major cell index in the cluster
  // Bit k set: the cluster wraps the box along axis k, i.e. it holds a closed path whose winding number
  // along k is not zero. Touching or crossing the face of the box is not wrapping.
  std::uint8_t wraps = 0;
};

struct ClusterResult {
  // Sorted by mass, largest first; ties by first_cell (deterministic, independent of traversal).
  std::vector<Cluster> clusters;
  // Per cell: index into `clusters`, or -1 for psi = -1 cells.
  std::vector<std::int32_t> label;
};

// Labels the psi = +1 cells of `grid` (union-find, periodic) and finds the axes each cluster wraps.
// The union-find carries each cell's image of the box relative to its root (Newman & Ziff, PRE 64,
// 016706 (2001)): a bond inside one set whose images disagree closes a loop that winds around the box
// along the axes where they differ. It takes 5 + 4d bytes a cell while it runs.
ClusterResult find_clusters(const DensityGrid& grid, Connectivity connectivity);

// Each particle's cluster (index into ClusterResult::clusters, so 0 is the largest), or -1 for a
// particle in a psi = -1 cell; `positions` [N][d] as given to grid.assign(). Every cluster counts,
// whatever its mass (min_size is a matter of the statistics).
std::vector<std::int32_t> particle_clusters(const DensityGrid& grid, const ClusterResult& result,
                                            const double* positions, std::size_t n_particles);

// The per-snapshot numbers of gg-cluster, over the clusters of mass >= min_size:
// number-average mass, weight-average mass sum(m^2)/sum(m), count, largest mass.
// With no such cluster: count = largest = 0 and both averages NaN (an average over nothing).
struct ClusterStats {
  double mean_mass = 0;
  double weight_mass = 0;
  std::int64_t count = 0;
  std::int64_t largest = 0;
};
ClusterStats summarize(const std::vector<Cluster>& clusters, std::int64_t min_size);

// The largest cluster (clusters[0], when its mass is >= min_size) against the rest, per snapshot:
//   share              = its mass / all particles of the frame (0 with no such cluster; NaN with no particles);
//   share_of_clustered = its mass / the particles in clusters of mass >= min_size (NaN with no such cluster);
//   rest_mean_mass     = number-average mass of the other clusters of mass >= min_size (NaN with none:
//                        an average over nothing, as mean_mass);
//   wraps              = its Cluster::wraps (0 with no such cluster).
struct GiantCluster {
  double share = 0;
  double share_of_clustered = 0;
  double rest_mean_mass = 0;
  std::uint8_t wraps = 0;
};
GiantCluster giant_cluster(const std::vector<Cluster>& clusters, std::int64_t n_particles, std::int64_t min_size);

// Edges 1, 2, 4, ..., 2^B of the mass histogram (log2 bins [2^j, 2^(j+1))), with 2^B > max_mass.
std::vector<double> mass_bin_edges(std::int64_t max_mass);
// Number of clusters of mass >= min_size in each bin of `edges`.
std::vector<double> mass_histogram(const std::vector<Cluster>& clusters, std::int64_t min_size,
                                   const std::vector<double>& edges);

}  // namespace gg
