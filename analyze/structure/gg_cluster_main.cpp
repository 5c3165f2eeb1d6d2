// gg-cluster: clusters of the coarse-grained density in every snapshot: number- and weight-average mass, count, largest.
// Thin main: CLI11 -> ClusterConfig -> run_cluster (analyze/structure/structure_tools).
#include "structure_tools.hpp"

int main(int argc, char** argv) {
  return gg::structure_main(argc, argv, "gg-cluster",
                            "gg-cluster: clusters of the coarse-grained density in every snapshot: number- and "
                            "weight-average mass, count, largest (docs/DESIGN.md; paper Fig. 3)",
                            gg::add_cluster_options, gg::run_cluster);
}
