#pragma once
// The gg-fit command line: CLI11 subcommands average, power-law, local-exponent, onset,
// haff, collapse, table. Reads and writes HDF5 through ggcommon; all numerics live in the ggfit
// library (fit/*.hpp), which works on plain vectors.

namespace gg::fit {

// The whole program: parse, run the chosen subcommand, return the exit status
// (0 ok, 1 runtime error, 2 usage error; docs/DESIGN.md "Conventions of every tool").
int gg_fit_main(int argc, char** argv);

}  // namespace gg::fit
