#pragma once
// The gg-cluster, gg-correlate, gg-domains and gg-velocity tools: command line -> validated config ->
// run(config). Each reads the selected snapshots of a particle file through open_frames (H5MD, GSD,
// a LAMMPS dump or extended XYZ; "-" = H5MD on stdin), coarse-grains every
// frame with one DensityGrid, runs its analysis and writes one group of docs/DESIGN.md "Files" with the
// analysis parameters as attributes and the provenance ('-' = stdout), atomically.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "cluster.hpp"
#include "domains.hpp"
#include "gg/common_flags.hpp"
#include "gg/density_grid.hpp"
#include "gg/errors.hpp"

namespace gg {

// What every structural tool takes: IN, -o OUT, --grid, --coarse, --rho-c, --frames.
struct StructureConfig {
  std::string input;
  std::string output;
  CoarseGrain grain;
  std::vector<long> frames;  // empty = every snapshot; negative counts from the end
};

struct ClusterConfig : StructureConfig {
  int connectivity = 0;       // 0 = faces; 4 or 8 (faces, also edges and corners) in 2D, 6 or 26 in 3D
  std::int64_t min_size = 1;  // clusters lighter than this are left out of every statistic
  bool histogram = false;     // also write the mass distribution
  bool particle_clusters = false;  // also write each particle's cluster index
};

struct CorrelateConfig : StructureConfig {
  double a = 0.5;         // l_C is where C first falls to a
  bool pairs = false;     // also g(r) of the particles and g(sigma+) (a pair search per frame)
  bool density = false;   // also S_rho(k) of the particle counts (a second FFT per frame)
  double g_max = 5;       // g(r) up to this r (cut to L_min / 2)
  double g_bin = 0.02;    // width of the g(r) bins
  double g_contact = 0.1; // g(sigma+) from the bins within this of sigma = 1
};

// gg-velocity: the velocity distribution and the flow field (docs/DESIGN.md "Velocities").
struct VelocityConfig : StructureConfig {
  double a = 0.5;           // correlation lengths: where C_L, C_T first fall to a
  double dc = 0.1;          // linear bins of c up to body_max
  double body_max = 3;      // then log-spaced bins, per_decade a decade, up to c_top
  int per_decade = 20;
  double c_top = 12;
  double tail_from = 1.5;   // the tail fit uses the bins at c >= tail_from
  bool fields = false;      // also write u, the vorticity and rho_loc of every analysed frame
  std::string profile;      // "x", "y" or "z": also the profiles along that axis; "" = none
  std::optional<std::int64_t> bins;  // slabs of the profile; unset: from bin_width
  double bin_width = 1;     // target slab width: max(1, round(L / bin_width)) slabs
};

struct DomainsConfig : StructureConfig {
  std::string phase = "both";
};

// Checks what can be checked before reading the input (the box-dependent checks, grid <= L and a
// block of 2*coarse+1 cells no wider than the grid, come when the box is known); throws UsageError
// with one line naming the flag.
void validate(const ClusterConfig& c);
void validate(const CorrelateConfig& c);
void validate(const DomainsConfig& c);
void validate(const VelocityConfig& c);

// The neighbours per cell that --connectivity `connectivity` (0: faces) means on a `dim`-dimensional
// grid: 2d (faces) or 3^d - 1 (also edges and corners), 2 in 1D; the values of another dimension (6
// on a 2D grid, 8 on a 3D one) throw UsageError naming the ones that fit.
std::int64_t cluster_neighbours(int connectivity, int dim);

// Run a tool; `argv` is recorded in the provenance. Return the exit status (0); errors are thrown
// (UsageError, RuntimeError) for guarded_main to report.
int run_cluster(const ClusterConfig& c, const CommonFlags& flags, const std::vector<std::string>& argv);
int run_correlate(const CorrelateConfig& c, const CommonFlags& flags, const std::vector<std::string>& argv);
int run_domains(const DomainsConfig& c, const CommonFlags& flags, const std::vector<std::string>& argv);
int run_velocity(const VelocityConfig& c, const CommonFlags& flags, const std::vector<std::string>& argv);

// The whole main() of each tool, kept thin so that tests call the same run_* directly: CLI11 with the
// common flags and the tool's options -> Config -> run_* (errors reported by guarded_main) -> exit
// status; `description` heads --help. The command lines live in structure_tools.cpp, the one file
// of the three tools that compiles CLI11.
int cluster_main(int argc, char** argv, const std::string& description);
int correlate_main(int argc, char** argv, const std::string& description);
int domains_main(int argc, char** argv, const std::string& description);
int velocity_main(int argc, char** argv, const std::string& description);

}  // namespace gg
