// gg-fit: ensemble averages, power-law and exponent fits with honest error bars.
#include "fit/tool.hpp"

int main(int argc, char** argv) { return gg::fit::gg_fit_main(argc, argv); }
