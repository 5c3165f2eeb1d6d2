// gg-cluster: clusters of the coarse-grained density in every snapshot: number- and weight-average mass, count, largest.
// Thin main: CLI11 -> ClusterConfig -> run_cluster (analyze/structure_tools).
#include "gg/cli.hpp"
#include "gg/errors.hpp"
#include "structure_tools.hpp"

int main(int argc, char** argv) {
  gg::ClusterConfig config;
  gg::CommonFlags flags;
  CLI::App app{"gg-cluster: clusters of the coarse-grained density in every snapshot: number- and weight-average mass, count, largest (DESIGN.md; paper Fig. 3)"};
  app.name("gg-cluster");
  gg::add_common_flags(app, flags);
  gg::add_cluster_options(app, config);
  if (const int status = gg::parse_cli(app, argc, argv); status >= 0) return status;
  return gg::guarded_main("gg-cluster", [&] { return gg::run_cluster(config, flags, gg::argv_strings(argc, argv)); },
                          gg::kStructureMemoryHint);
}
