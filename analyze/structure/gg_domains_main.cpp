// gg-domains: lengths between interfaces of psi along every grid row and column, their distribution P(l_d) and mean l.
// Thin main: CLI11 -> DomainsConfig -> run_domains (analyze/structure/structure_tools).
#include "structure_tools.hpp"

int main(int argc, char** argv) {
  return gg::structure_main(argc, argv, "gg-domains",
                            "gg-domains: lengths between interfaces of psi along every grid row and column, their "
                            "distribution P(l_d) and mean l (docs/DESIGN.md; paper eq. 10)",
                            gg::add_domains_options, gg::run_domains);
}
