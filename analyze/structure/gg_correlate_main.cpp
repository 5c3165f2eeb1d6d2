// gg-correlate: two-point correlation C(r,t) of the order parameter psi by FFT, and its length l_C.
// Thin main: correlate_main of analyze/structure/structure_tools (CLI11 -> CorrelateConfig -> run_correlate).
#include "structure_tools.hpp"

int main(int argc, char** argv) {
  return gg::correlate_main(argc, argv,
                            "gg-correlate: two-point correlation C(r,t) of the order parameter psi by FFT, and "
                            "its length l_C (docs/DESIGN.md; paper Figs. 4-5)");
}
