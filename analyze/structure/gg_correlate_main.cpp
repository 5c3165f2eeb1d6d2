// gg-correlate: two-point correlation C(r,t) of the order parameter psi by FFT, and its length l_C.
// Thin main: CLI11 -> CorrelateConfig -> run_correlate (analyze/structure/structure_tools).
#include "structure_tools.hpp"

int main(int argc, char** argv) {
  return gg::structure_main(argc, argv, "gg-correlate",
                            "gg-correlate: two-point correlation C(r,t) of the order parameter psi by FFT, and "
                            "its length l_C (docs/DESIGN.md; paper Figs. 4-5)",
                            gg::add_correlate_options, gg::run_correlate);
}
