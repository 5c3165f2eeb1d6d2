// gg-cluster: clusters of the coarse-grained density in every snapshot: number- and weight-average mass, count,
// the largest (its share, whether it wraps the box) and the mean mass of the rest.
// Thin main: cluster_main of analyze/structure/structure_tools (CLI11 -> ClusterConfig -> run_cluster).
#include "structure_tools.hpp"

int main(int argc, char** argv) {
  return gg::cluster_main(argc, argv,
                          "gg-cluster: clusters of the coarse-grained density in every snapshot: number- and "
                          "weight-average mass, count, largest, the largest's share of the particles and whether "
                          "it wraps the periodic box, the mean mass of the rest (docs/DESIGN.md; paper Fig. 3)");
}
