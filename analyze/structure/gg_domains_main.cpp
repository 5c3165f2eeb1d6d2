// gg-domains: lengths between interfaces of psi along every grid row and column, their distribution P(l_d) and mean l.
// Thin main: domains_main of analyze/structure/structure_tools (CLI11 -> DomainsConfig -> run_domains).
#include "structure_tools.hpp"

int main(int argc, char** argv) {
  return gg::domains_main(argc, argv,
                          "gg-domains: lengths between interfaces of psi along every grid row and column, their "
                          "distribution P(l_d) and mean l (docs/DESIGN.md; paper eq. 10)");
}
