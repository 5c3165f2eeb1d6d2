#pragma once
// The gg-fit subcommands: the arguments each takes, filled by the CLI11 wiring in fit/tool.cpp,
// and the function that runs it (fit/cmd_*.cpp). Each run_* returns the exit status; errors are
// thrown (gg/errors.hpp) and reported by guarded_main. Private to the gg-fit command line.
#include <limits>
#include <string>
#include <vector>

#include "fit/onset.hpp"
#include "fit/subcommand_support.hpp"

namespace gg::fit::cli {

// ------------------------------------------------------------------------------------------------
// Subcommands

// What every subcommand but table takes: argv (for the provenance) and -o.
struct Common {
  std::vector<std::string> argv;
  std::string output;
};

// average ----------------------------------------------------------------------------------------
struct AverageArgs {
  std::vector<std::string> inputs;
  std::string dataset;
  bool interpolate = false;
  double from = -std::numeric_limits<double>::infinity();  // samples before it left out
};
int run_average(const Common& c, const AverageArgs& a);

// power-law --------------------------------------------------------------------------------------
struct PowerLawArgs {
  std::string input;
  std::vector<double> window;
  bool offset = false;
  std::string errors = "auto";
};
int run_power_law(const Common& c, const PowerLawArgs& a);

// local-exponent ---------------------------------------------------------------------------------
struct LocalArgs {
  std::string input;
  double decades = 0.5;
  std::string errors = "auto";
};
int run_local_exponent(const Common& c, const LocalArgs& a);

// onset ------------------------------------------------------------------------------------------
struct OnsetArgs {
  std::string input;
  OnsetCriterion criterion;
  double asymptote = kNaN;
  std::vector<double> window;
  std::string errors = "auto";
};
int run_onset(const Common& c, const OnsetArgs& a);

// haff -------------------------------------------------------------------------------------------
struct HaffArgs {
  std::string input;
  std::vector<double> window;
  double rho = kNaN, e = kNaN, T0 = kNaN;
  int dim = 0;
  std::string contact = "henderson";
  std::string errors = "auto";
};
int run_haff(const Common& c, const HaffArgs& a);

// collapse ---------------------------------------------------------------------------------------
struct CollapseArgs {
  std::vector<std::string> inputs;
  std::vector<double> windows;  // pairs
  double sigmas = 2;
  std::string errors = "auto";
};
int run_collapse(const Common& c, const CollapseArgs& a);

// shift ------------------------------------------------------------------------------------------
struct ShiftArgs {
  std::vector<std::string> inputs;
  std::vector<double> windows;  // pairs
  std::size_t levels = 8;
  double sigmas = 2;
};
int run_shift(const Common& c, const ShiftArgs& a);

// late-exponent ----------------------------------------------------------------------------------
struct LateExponentArgs {
  std::string input;
  double end = kNaN;  // default: the last sample
  double decades = 0.5;
  double sigmas = 2;
};
int run_late_exponent(const Common& c, const LateExponentArgs& a);

// ratio ------------------------------------------------------------------------------------------
struct RatioArgs {
  std::string reference, other;
  std::vector<double> window;
  double sigmas = 2, tolerance = 0.1;
};
int run_ratio(const Common& c, const RatioArgs& a);

// at-equal ---------------------------------------------------------------------------------------
struct AtEqualArgs {
  std::vector<std::string> inputs;  // X Y pairs, the reference's first
  std::vector<double> levels;
  double sigmas = 2, tolerance = 0.1;
};
int run_at_equal(const Common& c, const AtEqualArgs& a);

// crossing ---------------------------------------------------------------------------------------
struct CrossingArgs {
  std::vector<std::string> inputs;  // ensemble means, the reference (of the ratios) first
  double level = kNaN;
  bool stays = false;
  bool per_run = false;   // the mean of the runs' own ln t* (for 0/1 steps), not the mean's crossing
  std::vector<double> x;  // one per input, or none
  double sigmas = 2, tolerance = 0.1;
};
int run_crossing(const Common& c, const CrossingArgs& a);

// compare ----------------------------------------------------------------------------------------
struct CompareArgs {
  std::vector<std::string> inputs;  // estimates, the reference first
  double sigmas = 2;
};
int run_compare(const Common& c, const CompareArgs& a);

// extrapolate ------------------------------------------------------------------------------------
struct ExtrapolateArgs {
  std::vector<std::string> inputs;  // one per box size
  std::vector<double> L;
  double expected = 1, sigmas = 2, tolerance = 0.1;
};
int run_extrapolate(const Common& c, const ExtrapolateArgs& a);

// table ------------------------------------------------------------------------------------------
struct TableArgs {
  std::vector<std::string> inputs;
  bool header = true;
};
int run_table(const TableArgs& a);

}  // namespace gg::fit::cli
