// gg-domains: lengths between interfaces of psi along every grid row and column, their distribution P(l_d) and mean l.
// Thin main: CLI11 -> DomainsConfig -> run_domains (analyze/structure_tools).
#include "gg/cli.hpp"
#include "gg/errors.hpp"
#include "structure_tools.hpp"

int main(int argc, char** argv) {
  gg::DomainsConfig config;
  gg::CommonFlags flags;
  CLI::App app{"gg-domains: lengths between interfaces of psi along every grid row and column, their distribution P(l_d) and mean l (DESIGN.md; paper eq. 10)"};
  app.name("gg-domains");
  gg::add_common_flags(app, flags);
  gg::add_domains_options(app, config);
  if (const int status = gg::parse_cli(app, argc, argv); status >= 0) return status;
  return gg::guarded_main("gg-domains", [&] { return gg::run_domains(config, flags, gg::argv_strings(argc, argv)); },
                          gg::kStructureMemoryHint);
}
