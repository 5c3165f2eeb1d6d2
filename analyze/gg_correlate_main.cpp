// gg-correlate: two-point correlation C(r,t) of the order parameter psi by FFT, and its length l_C.
// Thin main: CLI11 -> CorrelateConfig -> run_correlate (analyze/structure_tools).
#include "gg/cli.hpp"
#include "gg/errors.hpp"
#include "structure_tools.hpp"

int main(int argc, char** argv) {
  gg::CorrelateConfig config;
  gg::CommonFlags flags;
  CLI::App app{"gg-correlate: two-point correlation C(r,t) of the order parameter psi by FFT, and its length l_C (DESIGN.md; paper Figs. 4-5)"};
  app.name("gg-correlate");
  gg::add_common_flags(app, flags);
  gg::add_correlate_options(app, config);
  if (const int status = gg::parse_cli(app, argc, argv); status >= 0) return status;
  return gg::guarded_main("gg-correlate", [&] { return gg::run_correlate(config, flags, gg::argv_strings(argc, argv)); },
                          gg::kStructureMemoryHint);
}
