// Bad input table (docs/DESIGN.md "Conventions of every tool"): each row runs a built tool in a
// fresh directory on one bad input and requires exit status 1 (runtime) or 2 (usage), exactly one
// line on stderr naming the problem, and no output or temporary file left behind. Then unusual but
// valid inputs that once broke a tool.
#include "bad_input_cases.hpp"
#include "h5_contents.hpp"

#include <sys/stat.h>

namespace gg::robust {
namespace {

std::string ident(std::string s) {
  for (char& ch : s)
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  return s;
}

// How each tool is pointed at an input particle file.
std::vector<std::string> reading(const std::string& tool, const std::string& file) {
  if (tool == "gg-sim") return {"--init", file, "--e", "0.5", "--t-max", "1", "-o", "out.h5"};
  return {file, "-o", "out.h5"};
}

std::vector<std::string> plus(std::vector<std::string> a, const std::vector<std::string>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

const std::vector<std::string> kParticleTools{"gg-sim", "gg-cluster", "gg-correlate", "gg-domains", "gg-velocity"};
const std::vector<std::string> kStructureTools{"gg-cluster", "gg-correlate", "gg-domains"};

// The bad particle files every tool that reads snapshots must refuse (runtime errors, status 1).
struct FileCase {
  std::string fixture;
  std::vector<std::string> needles;
};
const std::vector<FileCase> kBadParticleFiles{
    {"missing.h5", {"missing.h5", "no such file"}},
    {"dir.h5", {"dir.h5", "directory"}},
    {"empty.h5", {"empty.h5", "empty"}},
    {"text.h5", {"text.h5", "not an HDF5"}},
    {"nogroups.h5", {"nogroups.h5", "H5MD|/particles"}},
    {"nopositions.h5", {"nopositions.h5", "position"}},
    {"rank2.h5", {"rank2.h5", "rank"}},
    {"lastdim1.h5", {"lastdim1.h5", "position"}},
    {"strings.h5", {"strings.h5", "number|numeric"}},
    {"4d.h5", {"4d.h5", "dimension 4"}},
    {"nan.h5", {"nan.h5", "NaN|non-finite"}},
    {"inf.h5", {"inf.h5", "inf|non-finite"}},
    {"outside.h5", {"outside.h5", "outside the box"}},
    {"negative.h5", {"negative.h5", "outside the box"}},
    {"nanvel.h5", {"nanvel.h5", "velocit"}},
    {"badedges.h5", {"badedges.h5", "edge"}},
    // A sparse dataset: its claim must be refused before anything is allocated for it.
    {"huge_positions.h5", {"huge_positions.h5", "position", "damaged"}},
};

std::vector<BadCase> every_tool_cases() {
  std::vector<BadCase> cases;
  for (const auto& tool : kParticleTools) {
    for (const auto& f : kBadParticleFiles)
      cases.push_back({ident(tool + "_" + f.fixture), tool, reading(tool, f.fixture), {f.fixture}, 1, f.needles});
    cases.push_back({ident(tool + "_unknown_option"), tool, plus(reading(tool, "valid.h5"), {"--bogus", "3"}),
                     {"valid.h5"}, 2, {"--bogus"}});
    // The output named badly: its directory does not exist, or it is a directory.
    const std::vector<std::string> in = tool == "gg-sim" ? std::vector<std::string>{"--init", "valid.h5", "--e", "0.5", "--t-max", "1"}
                                                         : std::vector<std::string>{"valid.h5"};
    cases.push_back({ident(tool + "_output_dir_missing"), tool, plus(in, {"-o", "nodir/out.h5"}), {"valid.h5"}, 2,
                     {"nodir"}});
    cases.push_back({ident(tool + "_output_is_directory"), tool, plus(in, {"-o", "dir.h5"}), {"valid.h5", "dir.h5"}, 2,
                     {"dir.h5", "directory"}});
  }
  for (const auto& tool : kStructureTools) {
    cases.push_back({ident(tool + "_no_frames"), tool, reading(tool, "noframes.h5"), {"noframes.h5"}, 1,
                     {"noframes.h5", "no snapshots|0 frames"}});
    cases.push_back({ident(tool + "_stdin_empty"), tool, {"-", "-o", "out.h5"}, {}, 1, {"stdin", "no data"}});
    BadCase stdin_closed{ident(tool + "_stdin_closed"), tool, {"-", "-o", "out.h5"}, {}, 2, {"stdin", "closed"}};
    stdin_closed.close_fd = 0;
    cases.push_back(stdin_closed);
    BadCase stdout_closed{ident(tool + "_output_to_a_closed_stdout"), tool, {"valid.h5", "-o", "-"}, {"valid.h5"}, 2,
                          {"stdout", "closed"}};
    stdout_closed.close_fd = 1;
    cases.push_back(stdout_closed);
    cases.push_back({ident(tool + "_output_to_dev_full"), tool, {"valid.h5", "-o", "/dev/full"}, {"valid.h5"}, 1,
                     {"'/dev/full'", "no space left"}});
    cases.push_back({ident(tool + "_stdin_text"), tool, {"-", "-o", "out.h5"}, {}, 1, {"stdin", "not an HDF5"},
                     "text.h5"});
    cases.push_back({ident(tool + "_no_output_option"), tool, {"valid.h5"}, {"valid.h5"}, 2, {"--output"}});
    cases.push_back({ident(tool + "_frame_out_of_range"), tool, plus(reading(tool, "valid.h5"), {"--frames", "0,7"}),
                     {"valid.h5"}, 2, {"frame 7", "--frames|frames (0..1"}});
    // A frame analysed twice would repeat its time in the output; valid.h5 has 2 frames, so -1 is 1.
    cases.push_back({ident(tool + "_frame_repeated"), tool, plus(reading(tool, "valid.h5"), {"--frames", "1,0,1"}),
                     {"valid.h5"}, 2, {"--frames", "frame 1 twice"}});
    // CLI11 alone would drop the empty item and analyse frames 0 and 1.
    cases.push_back({ident(tool + "_frame_list_with_a_gap"), tool, plus(reading(tool, "valid.h5"), {"--frames", "0,,1"}),
                     {"valid.h5"}, 2, {"--frames", "empty item in '0,,1'"}});
    cases.push_back({ident(tool + "_frame_repeated_from_the_end"), tool,
                     plus(reading(tool, "valid.h5"), {"--frames", "1,-1"}), {"valid.h5"}, 2,
                     {"--frames", "frame 1 twice (as 1 and -1)"}});
    cases.push_back({ident(tool + "_grid_zero"), tool, plus(reading(tool, "valid.h5"), {"--grid", "0"}),
                     {"valid.h5"}, 2, {"--grid"}});
    cases.push_back({ident(tool + "_grid_beyond_box"), tool, plus(reading(tool, "valid.h5"), {"--grid", "100"}),
                     {"valid.h5"}, 2, {"--grid"}});
    cases.push_back({ident(tool + "_coarse_negative"), tool, plus(reading(tool, "valid.h5"), {"--coarse", "-1"}),
                     {"valid.h5"}, 2, {"--coarse"}});
    // The box is 10 cells wide at --grid 1: a block of 11 cells would count one twice.
    cases.push_back({ident(tool + "_coarse_wider_than_the_grid"), tool,
                     plus(reading(tool, "valid.h5"), {"--coarse", "5"}), {"valid.h5"}, 2,
                     {"--coarse 5", "10 cells per side", "--coarse <= 4"}});
    cases.push_back({ident(tool + "_rho_c_nan"), tool, plus(reading(tool, "valid.h5"), {"--rho-c", "nan"}),
                     {"valid.h5"}, 2, {"--rho-c"}});
    // 10^12 cells of the default --grid 1 (would be allocated), and 2^32 + 1 cells (round(L/grid)
    // once wrapped to 1 cell, and the tool "succeeded").
    cases.push_back({ident(tool + "_box_1e6_cells"), tool, reading(tool, "bigbox.h5"), {"bigbox.h5"}, 2,
                     {"--grid", "1e+06 x 1e+06"}});
    cases.push_back({ident(tool + "_cell_count_overflow"), tool, reading(tool, "wrapbox1d.h5"), {"wrapbox1d.h5"}, 2,
                     {"--grid", "4.29497e+09"}});
  }
  cases.push_back({"gg_cluster_connectivity_6", "gg-cluster", plus(reading("gg-cluster", "valid.h5"), {"--connectivity", "6"}),
                   {"valid.h5"}, 2, {"--connectivity"}});
  cases.push_back({"gg_cluster_min_size_negative", "gg-cluster", plus(reading("gg-cluster", "valid.h5"), {"--min-size", "-2"}),
                   {"valid.h5"}, 2, {"--min-size"}});
  cases.push_back({"gg_correlate_a_beyond_1", "gg-correlate", plus(reading("gg-correlate", "valid.h5"), {"--a", "1.5"}),
                   {"valid.h5"}, 2, {"--a"}});
  // gg-velocity: a file without velocities (one line naming the remedy), and its own options.
  cases.push_back({"gg_velocity_no_velocities", "gg-velocity", reading("gg-velocity", "novelocities.h5"),
                   {"novelocities.h5"}, 1, {"novelocities.h5", "no velocities", "--velocities"}});
  cases.push_back({"gg_velocity_a_beyond_1", "gg-velocity", plus(reading("gg-velocity", "valid.h5"), {"--a", "1.5"}),
                   {"valid.h5"}, 2, {"--a"}});
  cases.push_back({"gg_velocity_dc_zero", "gg-velocity", plus(reading("gg-velocity", "valid.h5"), {"--dc", "0"}),
                   {"valid.h5"}, 2, {"--dc"}});
  cases.push_back({"gg_velocity_body_beyond_top", "gg-velocity",
                   plus(reading("gg-velocity", "valid.h5"), {"--body-max", "12", "--c-top", "5"}), {"valid.h5"}, 2,
                   {"--body-max", "--c-top"}});
  cases.push_back({"gg_velocity_per_decade_zero", "gg-velocity",
                   plus(reading("gg-velocity", "valid.h5"), {"--per-decade", "0"}), {"valid.h5"}, 2, {"--per-decade"}});
  cases.push_back({"gg_velocity_tail_from_negative", "gg-velocity",
                   plus(reading("gg-velocity", "valid.h5"), {"--tail-from", "-1"}), {"valid.h5"}, 2, {"--tail-from"}});
  cases.push_back({"gg_velocity_rho_c_is_not_an_option", "gg-velocity",
                   plus(reading("gg-velocity", "valid.h5"), {"--rho-c", "0.5"}), {"valid.h5"}, 2, {"--rho-c"}});
  // --profile: an axis the 2D file lacks (known once the file is read), an axis that is none, no
  // slabs, a slab width of 0, slab options without --profile, and a file without velocities.
  const auto profile = [&](std::vector<std::string> options) { return plus(reading("gg-velocity", "valid.h5"), options); };
  cases.push_back({"gg_velocity_profile_axis_beyond_dimension", "gg-velocity", profile({"--profile", "z"}), {"valid.h5"}, 2,
                   {"--profile z", "2D"}});
  cases.push_back({"gg_velocity_profile_axis_unknown", "gg-velocity", profile({"--profile", "w"}), {"valid.h5"}, 2,
                   {"--profile w", "x, y or z"}});
  cases.push_back({"gg_velocity_profile_bins_zero", "gg-velocity", profile({"--profile", "y", "--bins", "0"}),
                   {"valid.h5"}, 2, {"--bins 0", "at least 1"}});
  cases.push_back({"gg_velocity_profile_bin_width_zero", "gg-velocity", profile({"--profile", "y", "--bin-width", "0"}),
                   {"valid.h5"}, 2, {"--bin-width"}});
  cases.push_back({"gg_velocity_bins_without_profile", "gg-velocity", profile({"--bins", "4"}), {"valid.h5"}, 2,
                   {"--bins", "--profile"}});
  cases.push_back({"gg_velocity_profile_no_velocities", "gg-velocity",
                   plus(reading("gg-velocity", "novelocities.h5"), {"--profile", "y"}), {"novelocities.h5"}, 1,
                   {"novelocities.h5", "no velocities", "--velocities"}});
  cases.push_back({"gg_correlate_g_bin_zero", "gg-correlate",
                   plus(reading("gg-correlate", "valid.h5"), {"--pairs", "--g-bin", "0"}), {"valid.h5"}, 2, {"--g-bin"}});
  // Bins so fine that their histogram would not fit in memory: refused naming the option, not "out of memory".
  cases.push_back({"gg_correlate_g_bin_tiny", "gg-correlate",
                   plus(reading("gg-correlate", "valid.h5"), {"--pairs", "--g-bin", "1e-12"}), {"valid.h5"}, 2,
                   {"--g-bin", "bins"}});
  cases.push_back({"gg_velocity_dc_tiny", "gg-velocity", plus(reading("gg-velocity", "valid.h5"), {"--dc", "1e-12"}),
                   {"valid.h5"}, 2, {"--dc", "bins"}});
  cases.push_back({"gg_domains_phase_unknown", "gg-domains", plus(reading("gg-domains", "valid.h5"), {"--phase", "sideways"}),
                   {"valid.h5"}, 2, {"--phase"}});
  return cases;
}

// gg-sim's own values (usage errors, status 2, unless the problem is in a file).
std::vector<BadCase> sim_cases() {
  const std::vector<std::string> ok{"--dim", "2", "--e", "0.5", "-o", "out.h5"};
  auto sim = [&](const std::string& name, std::vector<std::string> args, std::vector<std::string> needles,
                 std::vector<std::string> inputs = {}, int status = 2) {
    return BadCase{"gg_sim_" + name, "gg-sim", std::move(args), std::move(inputs), status, std::move(needles)};
  };
  const std::vector<std::string> run{"--N", "50", "--rho", "0.1", "--e", "0.5", "-o", "out.h5"};
  // 10^9 samples per decade (about 200 GB): refused before anything is allocated, with the
  // value that asks for it (the OOM killer ended it at 24 GB, without a word).
  BadCase samples_huge = sim("samples_per_decade_huge", plus(run, {"--t-max", "1", "--samples-per-decade", "1e9"}),
                             {"needs about", "of memory", "samples of E(t)", "--samples-per-decade",
                              "--no-resource-check"}, {}, 1);
  // 2.6e8 disks, about 40 GB: in 1 GB of address space here (skipped under ASan, which cannot cap
  // it, where a large machine might have that much).
  BadCase n_huge = sim("N_beyond_the_memory", plus({"--N", "2.6e8", "--rho", "0.3", "--t-max", "1"}, ok),
                       {"needs about", "particles", "--N"}, {}, 1);
  n_huge.out_of_memory = true;
  const std::vector<std::string> run_to{"--N", "50", "--rho", "0.1", "--e", "0.5", "--t-max", "1", "-o"};
  BadCase stdout_closed = sim("output_to_a_closed_stdout", plus(run_to, {"-"}), {"stdout", "closed"});
  stdout_closed.close_fd = 1;
  const std::vector<std::string> resume_alone{"--resume", "checkpoint.h5", "-o", "out.h5"};
  return {
      samples_huge,
      n_huge,
      stdout_closed,
      // Outputs that are not regular files: /dev/full is written through (and fails), never replaced.
      sim("output_to_dev_full", plus(run_to, {"/dev/full"}), {"'/dev/full'", "no space left"}, {}, 1),
      // Folders found unusable only at the first checkpoint or at the end, after the work: now first.
      sim("checkpoint_dir_missing", plus(run, {"--t-max", "1", "--checkpoint", "nodir/ck.h5"}), {"--checkpoint", "nodir"}),
      sim("checkpoint_dir_not_writable", plus(run, {"--t-max", "1", "--checkpoint", "/proc/gg-ck.h5"}),
          {"--checkpoint", "/proc", "cannot create"}),
      sim("output_dir_not_writable", plus(run_to, {"/proc/gg-out.h5"}), {"-o", "/proc", "cannot create"}),
      // --aggregate (touching particles merge): options without a meaning there, and checkpoints.
      sim("aggregate_with_e", {"--N", "50", "--rho", "0.1", "--aggregate", "--e", "0.5", "--t-max", "1", "-o", "out.h5"},
          {"--e", "no meaning with --aggregate"}),
      sim("aggregate_with_delta",
          {"--N", "50", "--rho", "0.1", "--aggregate", "--delta", "1e-4", "--t-max", "1", "-o", "out.h5"},
          {"--aggregate cannot be combined with --delta", "drop one of them"}),
      sim("aggregate_with_tc", {"--N", "50", "--rho", "0.1", "--aggregate", "--tc", "1e-4", "--t-max", "1", "-o", "out.h5"},
          {"--aggregate cannot be combined with --tc"}),
      sim("aggregate_with_pressure",
          {"--N", "50", "--rho", "0.1", "--aggregate", "--pressure", "--t-max", "1", "-o", "out.h5"},
          {"--aggregate cannot be combined with --pressure"}),
      sim("aggregate_unwrapped", {"--N", "50", "--rho", "0.1", "--aggregate", "--unwrapped", "--t-max", "1", "-o", "out.h5"},
          {"--aggregate cannot be combined with --unwrapped", "no single image"}),
      sim("aggregate_from_aggregates", {"--init", "aggregates.h5", "--aggregate", "--t-max", "1", "-o", "out.h5"},
          {"--init", "aggregates", "unit mass"}, {"aggregates.h5"}),
      // --drive (white-noise kicks): a drive gg-sim has, a positive strength, and no drive options alone.
      sim("drive_unknown", plus(run, {"--t-max", "1", "--drive", "sinusoidal", "--drive-strength", "1"}),
          {"--drive 'sinusoidal'", "white-noise"}),
      sim("drive_strength_negative", plus(run, {"--t-max", "1", "--drive", "white-noise", "--drive-strength", "-1"}),
          {"--drive-strength", "positive"}),
      sim("drive_strength_without_drive", plus(run, {"--t-max", "1", "--drive-strength", "0.5"}),
          {"--drive-strength", "--drive white-noise"}),
      sim("drive_with_aggregate",
          {"--N", "50", "--rho", "0.1", "--aggregate", "--drive", "white-noise", "--drive-strength", "1", "--t-max", "1",
           "-o", "out.h5"},
          {"--aggregate cannot be combined with --drive"}),
      // Viscoelastic particles: K out of range, and --e beside the law that replaces it.
      sim("viscoelastic_negative", {"--N", "50", "--rho", "0.1", "--viscoelastic", "-1", "--t-max", "1", "-o", "out.h5"},
          {"--viscoelastic", ">= 0", "-1"}),
      sim("viscoelastic_with_e",
          {"--N", "50", "--rho", "0.1", "--e", "0.9", "--viscoelastic", "0.1", "--t-max", "1", "-o", "out.h5"},
          {"--e", "--viscoelastic", "drop"}),
      // Impact-speed restitution: V out of range, its exponent without it, and a second law beside it.
      sim("e_speed_with_aggregate",
          {"--N", "50", "--rho", "0.1", "--aggregate", "--e-speed", "1", "--t-max", "1", "-o", "out.h5"},
          {"--aggregate cannot be combined with --e-speed", "merges at contact"}),
      sim("e_speed_negative", {"--N", "50", "--rho", "0.1", "--e", "0.5", "--e-speed", "-1", "--t-max", "1", "-o", "out.h5"},
          {"--e-speed", ">= 0", "-1"}),
      sim("e_exponent_without_e_speed",
          {"--N", "50", "--rho", "0.1", "--e", "0.5", "--e-exponent", "0.5", "--t-max", "1", "-o", "out.h5"},
          {"--e-exponent", "--e-speed"}),
      sim("e_speed_with_viscoelastic",
          {"--N", "50", "--rho", "0.1", "--viscoelastic", "0.1", "--e-speed", "1", "--t-max", "1", "-o", "out.h5"},
          {"--e-speed cannot be combined with --viscoelastic", "drop one"}),
      // Walls and gravity: the density follows from N and the box, 2D or 3D, options of walls only with walls,
      // a wall that bounces, no other effect beside them.
      sim("walls_with_rho", {"--N", "50", "--rho", "0.1", "--walls", "20", "--e", "1", "--t-max", "1", "-o", "out.h5"},
          {"--walls", "--N and --L"}),
      sim("walls_in_1d", {"--dim", "1", "--N", "5", "--L", "20", "--walls", "20", "--e", "1", "--t-max", "1", "-o", "out.h5"},
          {"--walls", "--dim 2 or 3"}),
      sim("gravity_without_walls", {"--N", "50", "--L", "20", "--gravity", "1", "--e", "1", "--t-max", "1", "-o", "out.h5"},
          {"--gravity", "--walls"}),
      sim("wall_e_zero", {"--N", "50", "--L", "20", "--walls", "20", "--wall-e", "0", "--e", "1", "--t-max", "1", "-o", "out.h5"},
          {"--wall-e", "(0, 1]"}),
      sim("walls_with_pressure",
          {"--N", "50", "--L", "20", "--walls", "20", "--e", "1", "--pressure", "--t-max", "1", "-o", "out.h5"},
          {"--walls cannot be combined with --pressure"}),
      sim("walls_with_e_speed",
          {"--N", "50", "--L", "20", "--walls", "20", "--e", "0.9", "--e-speed", "1", "--t-max", "1", "-o", "out.h5"},
          {"--walls cannot be combined with --e-speed"}),
      // Shear (--shear-rate): a flow and a gradient axis, no other effect but the images, a box of 3 cells across y.
      sim("shear_in_1d", {"--dim", "1", "--N", "50", "--rho", "0.1", "--shear-rate", "0.1", "--e", "1", "--t-max", "1", "-o", "out.h5"},
          {"--shear-rate", "--dim 2 or 3"}),
      sim("shear_with_pressure",
          {"--N", "50", "--rho", "0.1", "--shear-rate", "0.1", "--e", "1", "--pressure", "--t-max", "1", "-o", "out.h5"},
          {"--shear-rate cannot be combined with --pressure"}),
      sim("shear_with_e_speed",
          {"--N", "50", "--rho", "0.1", "--shear-rate", "0.1", "--e", "0.9", "--e-speed", "1", "--t-max", "1", "-o", "out.h5"},
          {"--shear-rate cannot be combined with --e-speed"}),
      sim("shear_with_walls",
          {"--N", "50", "--L", "20", "--walls", "20", "--shear-rate", "0.1", "--e", "1", "--t-max", "1", "-o", "out.h5"},
          {"--walls cannot be combined with --shear-rate", "drop one of them"}),
      sim("shear_box_too_small", {"--N", "10", "--rho", "0.5", "--shear-rate", "0.1", "--e", "1", "--t-max", "1", "-o", "out.h5"},
          {"sheared box", "3 cells"}),
      // Rough particles (--beta): values out of range, no rotation in 1D, their options without --beta.
      sim("beta_above_one", {"--N", "50", "--rho", "0.1", "--e", "0.9", "--beta", "1.5", "--t-max", "1", "-o", "out.h5"},
          {"--beta", "[-1, 1]", "1.5"}),
      sim("beta_in_1d",
          {"--dim", "1", "--N", "50", "--rho", "0.1", "--e", "0.9", "--beta", "0", "--t-max", "1", "-o", "out.h5"},
          {"--beta", "1D"}),
      sim("inertia_zero",
          {"--N", "50", "--rho", "0.1", "--e", "0.9", "--beta", "0", "--inertia", "0", "--t-max", "1", "-o", "out.h5"},
          {"--inertia", "(0, 1]"}),
      sim("inertia_above_one",
          {"--N", "50", "--rho", "0.1", "--e", "0.9", "--beta", "0", "--inertia", "1.2", "--t-max", "1", "-o", "out.h5"},
          {"--inertia", "(0, 1]", "1.2"}),
      sim("T0_rot_without_beta", {"--N", "50", "--rho", "0.1", "--e", "0.9", "--T0-rot", "1", "--t-max", "1", "-o", "out.h5"},
          {"--T0-rot", "--beta"}),
      // Mixtures (--radii, --masses, --fractions).
      sim("radius_negative", {"--N", "50", "--rho", "0.1", "--e", "0.9", "--radii", "-1", "--t-max", "1", "-o", "out.h5"},
          {"--radii", "positive"}),
      sim("fractions_not_summing_to_one",
          {"--N", "50", "--rho", "0.1", "--e", "0.9", "--radii", "0.5,0.7", "--fractions", "0.3,0.3", "--t-max", "1",
           "-o", "out.h5"},
          {"--fractions", "not 1"}),
      sim("fractions_count_mismatch",
          {"--N", "50", "--rho", "0.1", "--e", "0.9", "--radii", "0.5,0.7", "--fractions", "1", "--t-max", "1", "-o",
           "out.h5"},
          {"--fractions", "one per species"}),
      sim("radii_too_large_for_density",
          {"--N", "50", "--rho", "0.5", "--e", "0.9", "--radii", "0.6,0.9", "--t-max", "1", "-o", "out.h5"},
          {"--radii", "packing fraction"}),
      sim("drive_in_a_mixture", {"--N", "50", "--rho", "0.1", "--e", "0.9", "--drive", "white-noise",
                                 "--drive-strength", "1", "--masses", "1,4", "--t-max", "1", "-o", "out.h5"},
          {"--drive cannot be combined with --radii or --masses"}),
      sim("beta_in_a_mixture", {"--N", "50", "--rho", "0.1", "--e", "0.9", "--beta", "0", "--radii", "0.5,0.7",
                                "--t-max", "1", "-o", "out.h5"},
          {"--beta cannot be combined with --radii or --masses"}),
      sim("radii_with_aggregate", {"--N", "50", "--rho", "0.1", "--aggregate", "--radii", "0.5,0.7", "--t-max", "1",
                                   "-o", "out.h5"},
          {"--aggregate cannot be combined with --radii or --masses"}),
      // Empty values (a script's unset variable) are errors, not 0.
      sim("e_empty", {"--N", "50", "--rho", "0.1", "--e", "", "--t-max", "1", "-o", "out.h5"}, {"--e", "empty value"}),
      sim("e_blank_after_equals", {"--N", "50", "--rho", "0.1", "--e= ", "--t-max", "1", "-o", "out.h5"},
          {"--e", "empty value"}),
      sim("rho_empty", {"--N", "50", "--rho", "", "--e", "0.5", "--t-max", "1", "-o", "out.h5"}, {"--rho", "empty value"}),
      sim("N_empty", {"--N", "", "--rho", "0.1", "--e", "0.5", "--t-max", "1", "-o", "out.h5"}, {"--N", "empty value"}),
      sim("scene_value_empty", {"--scene", "scene_blank.ini", "-o", "out.h5"}, {"--e", "empty value"}, {"scene_blank.ini"}),
      // Lattices that would start with disks in contact (then "inelastic collapse at t = 0" at e = 1).
      sim("lattice_without_a_gap", plus({"--L", "32", "--rho", "1.1", "--init", "lattice", "--t-max", "1"}, ok),
          {"lattice of 1126 disks", "no gap", "at most N = 1116", "--rho 1.08984"}),
      sim("lattice_1d_without_a_gap",
          {"--dim", "1", "--N", "100", "--rho", "1", "--init", "lattice", "--e", "1", "--t-max", "1", "-o", "out.h5"},
          {"lattice of 100 rods", "at most N = 99"}),
      // A stall at e = 1 is no collapse: a start in contact, said as such, and nothing written.
      sim("start_in_contact", {"--dim", "1", "--init", "touching1d.h5", "--e", "1", "--t-max", "1", "-o", "out.h5"},
          {"touching1d.h5", "e = 1", "no inelastic collapse", "in contact"}, {"touching1d.h5"}, 1),
      sim("init_float_rounding", {"--init", "float_overlap.h5", "--e", "0.5", "--t-max", "1", "-o", "out.h5"},
          {"float_overlap.h5", "overlap", "single-precision", "/restart"}, {"float_overlap.h5"}, 1),
      sim("t_max_inf_alone", plus(run, {"--t-max", "inf"}), {"--t-max inf", "never ends", "--max-collisions"}),
      sim("snapshots_unsorted", plus(run, {"--t-max", "5", "--snapshots", "3,1,1"}), {"--snapshots", "3 before 1"}),
      sim("snapshots_list_with_a_gap", plus(run, {"--t-max", "5", "--snapshots", "1,,3"}),
          {"--snapshots", "empty item in '1,,3'"}),
      sim("snapshots_not_a_number", plus(run, {"--t-max", "5", "--snapshots", "1,x"}), {"--snapshots", "'x' is not a number"}),
      sim("continue_without_init", plus(run, {"--t-max", "5", "--continue"}), {"--continue", "--init"}),
      sim("continue_to_an_earlier_t_max",
          {"--init", "valid.h5", "--continue", "--e", "0.5", "--t-max", "0.5", "-o", "out.h5"},
          {"--t-max 0.5", "--continue", "valid.h5"}, {"valid.h5"}),
      // --resume CK alone takes the scene from CK; what is given must agree (the key and both values).
      sim("resume_with_another_e", plus(resume_alone, {"--e", "0.7"}),
          {"checkpoint.h5", "another scene", "e = 1 there, 0.7 here", "(--e)"}, {"checkpoint.h5"}),
      sim("resume_in_another_dimension", plus(resume_alone, {"--dim", "1"}), {"dim = 2 there, 1 here"},
          {"checkpoint.h5"}),
      sim("resume_to_an_earlier_t_max", plus(resume_alone, {"--t-max", "5"}),
          {"--t-max 5", "less than the 1e+09", "further"}, {"checkpoint.h5"}),
      sim("resume_with_a_collision_limit", plus(resume_alone, {"--max-collisions", "1"}),
          {"--max-collisions 1", "started without", "drop --max-collisions"}, {"checkpoint.h5"}),
      sim("resume_damaged", {"--resume", "ck_damaged.h5", "-o", "out.h5"}, {"ck_damaged.h5", "damaged", "checksum"},
          {"ck_damaged.h5"}, 1),
      sim("resume_unsealed", {"--resume", "ck_unsealed.h5", "-o", "out.h5"}, {"ck_unsealed.h5", "damaged", "seal"},
          {"ck_unsealed.h5"}, 1),
      sim("init_zero_particles", {"--init", "zeroN.h5", "--e", "0.5", "--t-max", "1", "-o", "out.h5"},
          {"zeroN.h5", "particle"}, {"zeroN.h5"}, kEither),
      sim("overlapping_init", {"--init", "overlap.h5", "--e", "0.5", "--t-max", "1", "-o", "out.h5"},
          {"overlap.h5", "overlap"}, {"overlap.h5"}, 1),
      sim("init_with_N_and_rho", {"--init", "valid.h5", "--N", "50", "--rho", "0.3", "--e", "0.5", "--t-max", "1", "-o", "out.h5"},
          {"--init", "--N"}, {"valid.h5"}, 2),
      sim("init_without_snapshots", {"--init", "noframes.h5", "--e", "0.5", "--t-max", "1", "-o", "out.h5"},
          {"noframes.h5", "no snapshots|0 frames"}, {"noframes.h5"}, 1),
      sim("box_too_small", plus({"--N", "1", "--rho", "0.37", "--t-max", "1"}, ok), {"too small", "--N"}),
      sim("snapshot_beyond_t_max", plus(run, {"--t-max", "1", "--snapshots", "0,0.5,5"}), {"--snapshots", "--t-max"}),
      sim("output_is_the_init_file", {"--init", "valid.h5", "--e", "0.5", "--t-max", "1", "-o", "./valid.h5"},
          {"valid.h5", "also an input"}, {"valid.h5"}),
      sim("checkpoint_is_the_output", plus(run, {"--t-max", "1", "--checkpoint", "out.h5"}), {"--checkpoint", "output"}),
      // A file where the checkpoint goes would be overwritten, then removed at the end: only the run
      // resumed from it may take its place (an interrupted run's own, or any other file).
      sim("new_run_over_an_interrupted_one", plus(run, {"--t-max", "1"}), {"out.h5.checkpoint.h5", "exists", "--resume"},
          {"out.h5.checkpoint.h5"}),
      sim("checkpoint_path_holds_a_file", plus(run, {"--t-max", "1", "--checkpoint", "checkpoint.h5"}),
          {"checkpoint.h5", "exists", "another --checkpoint"}, {"checkpoint.h5"}),
      sim("checkpoint_is_the_init_file",
          {"--init", "valid.h5", "--e", "0.5", "--t-max", "1", "--checkpoint", "valid.h5", "-o", "out.h5"},
          {"--checkpoint", "--init"}, {"valid.h5"}),
      sim("init_1d_file_for_2d", {"--init", "valid1d.h5", "--dim", "2", "--e", "0.5", "--t-max", "1", "-o", "out.h5"},
          {"valid1d.h5", "--dim"}, {"valid1d.h5"}),
      sim("N_zero", plus({"--N", "0", "--rho", "0.3", "--t-max", "1"}, ok), {"--N"}),
      sim("N_zero_from_L_rho", plus({"--L", "1", "--rho", "0.1", "--t-max", "1"}, ok), {"no particle|--N"}),
      sim("N_negative", plus({"--N", "-5", "--rho", "0.3", "--t-max", "1"}, ok), {"--N"}),
      sim("rho_beyond_random_insertion", plus({"--N", "1000", "--rho", "0.9", "--t-max", "1"}, ok),
          {"random insertion", "--rho"}),
      sim("rho_beyond_lattice", plus({"--N", "400", "--rho", "1.3", "--init", "lattice", "--t-max", "1"}, ok),
          {"lattice", "--rho"}),
      sim("rho_negative", plus({"--N", "100", "--rho", "-0.3", "--t-max", "1"}, ok), {"--rho"}),
      sim("L_negative", plus({"--N", "100", "--L", "-20", "--t-max", "1"}, ok), {"--L"}),
      sim("e_above_1", {"--N", "50", "--rho", "0.1", "--e", "1.5", "--t-max", "1", "-o", "out.h5"}, {"--e"}),
      sim("e_negative", {"--N", "50", "--rho", "0.1", "--e", "-0.1", "--t-max", "1", "-o", "out.h5"}, {"--e"}),
      sim("e_nan", {"--N", "50", "--rho", "0.1", "--e", "nan", "--t-max", "1", "-o", "out.h5"}, {"--e"}),
      sim("t_max_negative", plus(run, {"--t-max", "-1"}), {"--t-max"}),
      sim("t_max_zero", plus(run, {"--t-max", "0"}), {"--t-max"}),
      sim("t_max_nan", plus(run, {"--t-max", "nan"}), {"--t-max"}),
      sim("snapshot_negative", plus(run, {"--t-max", "1", "--snapshots", "-1"}), {"--snapshots"}),
      sim("snapshot_list_negative", plus(run, {"--t-max", "1", "--snapshots", "0.5,-2"}), {"--snapshots"}),
      sim("snapshots_per_decade_negative", plus(run, {"--t-max", "1", "--snapshots-per-decade", "-1"}),
          {"--snapshots-per-decade"}),
      sim("samples_per_decade_zero", plus(run, {"--t-max", "1", "--samples-per-decade", "0"}), {"--samples-per-decade"}),
      sim("delta_negative", plus(run, {"--t-max", "1", "--delta", "-0.01"}), {"--delta"}),
      sim("tc_negative", plus(run, {"--t-max", "1", "--tc", "-0.01"}), {"--tc"}),
      sim("T0_zero", plus(run, {"--t-max", "1", "--T0", "0"}), {"--T0"}),
      // Beyond the range the collision arithmetic holds (a run at 1e300 stalled, at 1e308 overflowed).
      sim("T0_overflowing", plus(run, {"--t-max", "1", "--T0", "1e300"}), {"--T0", "1e100", "units"}),
      // Flags that shape the snapshots of a run that takes none, and one that shapes a resume of a new run:
      // each would do nothing, silently.
      sim("velocities_without_snapshots", plus(run, {"--t-max", "1", "--velocities"}),
          {"--velocities", "--snapshots"}),
      sim("float_snapshots_without_snapshots", plus(run, {"--t-max", "1", "--float-snapshots"}),
          {"--float-snapshots", "--snapshots"}),
      sim("unwrapped_without_snapshots", plus(run, {"--t-max", "1", "--unwrapped"}), {"--unwrapped", "--snapshots"}),
      sim("allow_other_build_without_resume", plus(run, {"--t-max", "1", "--allow-other-build"}),
          {"--allow-other-build", "--resume"}),
      sim("dim_4", plus(run, {"--t-max", "1", "--dim", "4"}), {"--dim"}),
      sim("unknown_option_in_new_run", plus(run, {"--t-max", "1", "--frobnicate"}), {"--frobnicate"}),
      sim("scene_key_unknown", {"--scene", "scene_bogus.ini", "-o", "out.h5"}, {"bogus"}, {"scene_bogus.ini"}),
      sim("scene_section_header", {"--scene", "scene_section.ini", "-o", "out.h5"}, {"[gg-sim]", "no sections"},
          {"scene_section.ini"}),
      sim("scene_missing", {"--scene", "noscene.ini", "-o", "out.h5"}, {"noscene.ini"}),
      sim("N_L_rho_all_given", plus({"--N", "100", "--L", "20", "--rho", "0.3", "--t-max", "1"}, ok),
          {"two of --N, --L, --rho"}),
      sim("N_L_rho_scene_and_flag", {"--scene", "scene_nrho.ini", "--L", "30", "-o", "out.h5"},
          {"two of --N, --L, --rho"}, {"scene_nrho.ini"}),
      sim("only_N_given", plus({"--N", "100", "--t-max", "1"}, ok), {"two of --N, --L, --rho"}),
      sim("no_end_of_run", plus({"--N", "100", "--rho", "0.3"}, ok), {"--t-max", "--max-collisions"}),
      sim("no_output_option", {"--N", "50", "--rho", "0.1", "--e", "0.5", "--t-max", "1"}, {"--output"}),
      sim("no_e", {"--N", "50", "--rho", "0.1", "--t-max", "1", "-o", "out.h5"}, {"--e", "required"}),
  };
}

// gg-fit: a few rows (fit_cli_test has its own).
std::vector<BadCase> fit_cases() {
  auto fit = [](const std::string& name, std::vector<std::string> args, std::vector<std::string> inputs, int status,
                std::vector<std::string> needles) {
    return BadCase{"gg_fit_" + name, "gg-fit", std::move(args), std::move(inputs), status, std::move(needles)};
  };
  auto power_law = [](const std::string& file) {
    return std::vector<std::string>{"power-law", file + ":/cluster/mean_mass", "--window", "1", "1000", "-o", "out.h5"};
  };
  return {
      fit("missing_file", power_law("missing.h5"), {}, 1, {"missing.h5", "no such file"}),
      fit("directory", power_law("dir.h5"), {"dir.h5"}, 1, {"dir.h5", "directory"}),
      fit("empty_file", power_law("empty.h5"), {"empty.h5"}, 1, {"empty.h5", "empty"}),
      fit("text_file", power_law("text.h5"), {"text.h5"}, 1, {"text.h5", "not an HDF5"}),
      fit("no_such_dataset", power_law("nogroups.h5"), {"nogroups.h5"}, 1, {"nogroups.h5", "/cluster/mean_mass"}),
      fit("wrong_rank", power_law("series_rank2.h5"), {"series_rank2.h5"}, 1, {"rank"}),
      fit("strings", power_law("series_strings.h5"), {"series_strings.h5"}, 1, {"/cluster/mean_mass", "number|numeric"}),
      fit("nan_values", power_law("series_nan.h5"), {"series_nan.h5"}, 1, {"non-finite|NaN"}),
      fit("nonpositive_in_log_fit", {"power-law", "series_nonpositive.h5:/cluster/mean_mass", "--window", "1", "1e4",
                                     "-o", "out.h5"},
          {"series_nonpositive.h5"}, 1, {"non-positive|positive"}),
      fit("time_length_differs", power_law("series_short_time.h5"), {"series_short_time.h5"}, 1, {"time"}),
      fit("no_time_axis", power_law("series_notime.h5"), {"series_notime.h5"}, 1, {"time"}),
      fit("window_without_samples", {"power-law", "series.h5:/cluster/mean_mass", "--window", "1e6", "1e7", "-o", "out.h5"},
          {"series.h5"}, 1, {"window"}),
      fit("window_reversed", {"power-law", "series.h5:/cluster/mean_mass", "--window", "100", "10", "-o", "out.h5"},
          {"series.h5"}, 2, {"window"}),
      fit("window_one_number", {"power-law", "series.h5:/cluster/mean_mass", "--window", "100", "-o", "out.h5"},
          {"series.h5"}, 2, {"window"}),
      fit("no_dataset_named", {"power-law", "series.h5", "--window", "1", "100", "-o", "out.h5"}, {"series.h5"}, 2,
          {"series.h5", "dataset"}),
      fit("unknown_subcommand", {"frobnicate", "series.h5:/cluster/mean_mass"}, {"series.h5"}, 2, {"frobnicate"}),
      fit("option_before_the_subcommand", {"--bogus", "series.h5:/cluster/mean_mass"}, {"series.h5"}, 2,
          {"--bogus", "subcommand"}),
      fit("unknown_option", plus(power_law("series.h5"), {"--bogus"}), {"series.h5"}, 2, {"--bogus"}),
      fit("local_exponent_window_zero", {"local-exponent", "series.h5:/cluster/mean_mass", "--window", "0", "-o", "out.h5"},
          {"series.h5"}, 2, {"--window", "decades"}),
      fit("average_ranks_differ", {"average", "series.h5:/cluster/mean_mass", "series_rank2.h5:/cluster/mean_mass", "-o",
                                   "out.h5"},
          {"series.h5", "series_rank2.h5"}, 1, {"rank"}),
      fit("average_missing_output", {"average", "series.h5:/cluster/mean_mass"}, {"series.h5"}, 2, {"--output"}),
      // One quantity of different runs: not one run twice (it would shrink the error), not two quantities.
      fit("average_one_run_twice", {"average", "series.h5:/cluster/mean_mass", "./series.h5:/cluster/mean_mass", "-o", "out.h5"},
          {"series.h5"}, 2, {"series.h5", "twice"}),
      fit("average_two_datasets", {"average", "series.h5:/cluster/mean_mass", "series_rank2.h5:/cluster/count", "-o", "out.h5"},
          {"series.h5", "series_rank2.h5"}, 2, {"different datasets"}),
      // Real-valued options: CLI11 reads "nan" as a number; a level or a band must be positive.
      fit("haff_e_nan", {"haff", "series.h5:/cluster/mean_mass", "--e", "nan"}, {"series.h5"}, 2, {"--e", "finite"}),
      fit("late_exponent_sigmas_negative", {"late-exponent", "series.h5:/cluster/mean_mass", "--sigmas", "-1"}, {"series.h5"},
          2, {"--sigmas", "above 0"}),
      fit("ratio_tolerance_nan", {"ratio", "series.h5:/cluster/mean_mass", "series.h5:/cluster/mean_mass", "--tolerance", "nan"},
          {"series.h5"}, 2, {"--tolerance", "finite"}),
      fit("table_missing_file", {"table", "missing.h5"}, {}, 1, {"missing.h5"}),
      fit("output_dir_missing", {"power-law", "series.h5:/cluster/mean_mass", "--window", "1", "1000", "-o", "nodir/out.h5"},
          {"series.h5"}, 2, {"nodir"}),
      fit("stdin_empty", {"power-law", "-:/cluster/mean_mass", "--window", "1", "1000", "-o", "out.h5"}, {}, 1,
          {"stdin", "no data"}),
      fit("huge_dataset", power_law("huge_series.h5"), {"huge_series.h5"}, 1,
          {"huge_series.h5", "/cluster/mean_mass", "damaged"}),
      // The fit works, copying the input's provenance into -o fails: the error is the one line (the
      // result line is printed only once -o is written).
      fit("damaged_input_provenance", power_law("damaged_provenance.h5"), {"damaged_provenance.h5"}, 1,
          {"damaged_provenance.h5", "cannot copy"}),
  };
}

// -o naming a file the tool reads, however spelled: refused before anything is written (the commit
// would rename the output over the input). Usage errors, status 2, the input unchanged.
std::vector<BadCase> output_is_input_cases() {
  const std::vector<std::string> clash{"also an input", "choose another -o"};
  std::vector<BadCase> cases;
  for (const auto& tool : kStructureTools) {
    cases.push_back({ident(tool + "_output_is_the_input"), tool, {"valid.h5", "-o", "valid.h5"}, {"valid.h5"}, 2,
                     plus({"'valid.h5'"}, clash)});
    cases.push_back({ident(tool + "_output_is_the_input_as_dot_slash"), tool, {"valid.h5", "-o", "./valid.h5"},
                     {"valid.h5"}, 2, plus({"'./valid.h5'"}, clash)});
    cases.push_back({ident(tool + "_output_is_the_input_via_parent"), tool, {"valid.h5", "-o", "../work/valid.h5"},
                     {"valid.h5"}, 2, plus({"'../work/valid.h5'"}, clash)});
    cases.push_back({ident(tool + "_output_is_the_input_behind_a_symlink"), tool, {"link_to_valid.h5", "-o", "valid.h5"},
                     {"valid.h5", "link_to_valid.h5"}, 2, plus({"'valid.h5'"}, clash)});
  }
  auto fit = [&](const std::string& name, std::vector<std::string> args, std::vector<std::string> inputs,
                 const std::string& output) {
    args.insert(args.end(), {"-o", output});
    return BadCase{"gg_fit_" + name, "gg-fit", std::move(args), std::move(inputs), 2, plus({"'" + output + "'"}, clash)};
  };
  const std::string m = ":/cluster/mean_mass";
  const std::vector<std::string> two{"series.h5", "dense_series.h5"};
  const std::vector<BadCase> fits{
      fit("power_law_output_is_the_input", {"power-law", "series.h5" + m, "--window", "1", "1000"}, {"series.h5"},
          "series.h5"),
      fit("power_law_output_is_the_input_as_dot_slash", {"power-law", "series.h5" + m, "--window", "1", "1000"},
          {"series.h5"}, "./series.h5"),
      fit("power_law_output_is_the_input_behind_a_symlink",
          {"power-law", "link_to_series.h5" + m, "--window", "1", "1000"}, {"series.h5", "link_to_series.h5"},
          "series.h5"),
      fit("local_exponent_output_is_the_input", {"local-exponent", "series.h5" + m}, {"series.h5"}, "./series.h5"),
      fit("onset_output_is_the_input", {"onset", "series.h5" + m, "--asymptote", "0.6"}, {"series.h5"}, "series.h5"),
      fit("haff_output_is_the_input", {"haff", "series.h5" + m, "--window", "1", "10"}, {"series.h5"}, "series.h5"),
      fit("collapse_output_is_the_second_input",
          {"collapse", "series.h5" + m, "dense_series.h5" + m, "--window", "1", "1000"}, two, "./dense_series.h5"),
      fit("average_output_is_an_input", {"average", "series.h5" + m, "dense_series.h5" + m}, two, "dense_series.h5"),
      fit("average_output_is_a_bare_input", {"average", "series.h5", "dense_series.h5", "--dataset", "/cluster/mean_mass"},
          two, "./series.h5"),
  };
  cases.insert(cases.end(), fits.begin(), fits.end());
  return cases;
}

std::vector<BadCase> all_cases() {
  std::vector<BadCase> all = every_tool_cases();
  for (auto part : {sim_cases(), fit_cases(), output_is_input_cases()}) all.insert(all.end(), part.begin(), part.end());
  return all;
}

class BadInput : public ::testing::TestWithParam<BadCase> {};

TEST_P(BadInput, RefusedWithOneLineAndNoOutput) {
  if (kAddressSanitizer && GetParam().out_of_memory)
    GTEST_SKIP() << "needs the memory cap that ASan builds cannot set (the tool would abort in ASan's allocator)";
  check_bad_case(GetParam());
}

INSTANTIATE_TEST_SUITE_P(Table, BadInput, ::testing::ValuesIn(all_cases()), case_name);

// ------------------------------------------------------------------------------------------------
// Unusual but valid input

class ValidInput : public ::testing::Test {
 protected:
  ValidInput() {
    fs::create_directory(work_);
    fs::create_directory(capture_);
  }
  RunResult run(const std::string& tool, const std::vector<std::string>& args) {
    return run_tool(tool_path(tool), args, work_, capture_);
  }
  TempDir root_;
  const fs::path work_ = root_.path() / "work", capture_ = root_.path() / "capture";
};

// An input whose provenance holds more than 8 string attributes (stored densely, e.g. from another
// writer): every tool copies it into its output (H5Ocopy of HDF5 < 1.14.4 crashed on it,
// HDFGroup/hdf5#2414).
TEST_F(ValidInput, DenseProvenanceOfTheInputIsCopied) {
  const std::vector<std::vector<std::string>> runs{
      {"gg-cluster", "dense_provenance.h5", "-o", "out.h5"},
      {"gg-correlate", "dense_provenance.h5", "-o", "out.h5"},
      {"gg-domains", "dense_provenance.h5", "-o", "out.h5"},
      {"gg-fit", "power-law", "dense_series.h5:/cluster/mean_mass", "--window", "1", "100", "-o", "out.h5"},
  };
  make_input(work_, "dense_provenance.h5");
  make_input(work_, "dense_series.h5");
  for (const auto& r : runs) {
    SCOPED_TRACE(r[0]);
    const RunResult res = run(r[0], {r.begin() + 1, r.end()});
    ASSERT_EQ(res.status, 0) << res.describe();
    const Contents out = h5_contents((work_ / "out.h5").string());
    EXPECT_TRUE(out.count("/parameters/provenance/inputs/0@note9")) << "the input's provenance is not in the output";
    EXPECT_EQ(entries(work_), (std::set<std::string>{"dense_provenance.h5", "dense_series.h5", "out.h5"}));
    fs::remove(work_ / "out.h5");
  }
}

// gg-sim --init FILE records N/L^d of the file as /parameters/rho (not the unset flag's 0, which
// made gg-fit haff refuse the output).
TEST_F(ValidInput, SimInitFromFileRecordsTheDensityOfTheFile) {
  make_input(work_, "valid.h5");
  const RunResult r = run("gg-sim", {"--init", "valid.h5", "--e", "0.5", "--t-max", "1", "-o", "out.h5"});
  ASSERT_EQ(r.status, 0) << r.describe();
  H5Input in((work_ / "out.h5").string());
  EXPECT_EQ(in.attr_double("/parameters", "N"), static_cast<double>(kN));
  EXPECT_EQ(in.attr_double("/parameters", "L"), kL);
  EXPECT_DOUBLE_EQ(in.attr_double("/parameters", "rho").value_or(-1), static_cast<double>(kN) / (kL * kL));
}

// gg-sim --init FILE with velocities starts at the file's temperature and records it as T0, or,
// given --T0, scales the velocities to it (docs/DESIGN.md: the start has T = T0); either way the file's
// provenance is copied into the output's. (T0 said 1 while the run started at the file's T.)
TEST_F(ValidInput, SimInitFromFileStartsAtTheTemperatureItRecords) {
  const RunResult first = run("gg-sim", {"--N", "400", "--rho", "0.3", "--e", "0.7", "--t-max", "5", "--snapshots", "5",
                                         "--velocities", "-o", "start.h5"});
  ASSERT_EQ(first.status, 0) << first.describe();
  // The file's temperature from its last frame (mass 1, T = <v_x^2> per degree of freedom; the
  // momentum is zero).
  const Snapshots s = read_snapshots(H5Input((work_ / "start.h5").string()), {-1});
  double sum2 = 0;
  for (double u : s.velocity) sum2 += u * u;
  const double t_file = sum2 / static_cast<double>(s.velocity.size());
  ASSERT_LT(t_file, 0.9) << "the start should have cooled below the default T0 = 1";
  const std::vector<std::pair<std::vector<std::string>, double>> runs{{{}, t_file}, {{"--T0", "2"}, 2.0}};
  for (const auto& [flags, t_start] : runs) {
    SCOPED_TRACE(flags.empty() ? "without --T0" : "with --T0 2");
    const RunResult r = run("gg-sim", plus({"--init", "start.h5", "--e", "0.7", "--t-max", "1", "-o", "out.h5"}, flags));
    ASSERT_EQ(r.status, 0) << r.describe();
    const H5Input out((work_ / "out.h5").string());
    EXPECT_NEAR(out.attr_double("/parameters", "T0").value_or(-1), t_start, 1e-12 * t_start);
    const TimeSeries e = read_observable(out, "kinetic_energy");
    ASSERT_FALSE(e.time.empty());
    EXPECT_EQ(e.time[0], 0);
    EXPECT_NEAR(e.value[0], t_start, 1e-12 * t_start) << "E = (d/2) T at t = 0 in 2D";
    EXPECT_EQ(out.attr_string("/parameters/provenance/inputs/0", "program").value_or(""), "gg-sim");
    fs::remove(work_ / "out.h5");
  }
}

// Every gg-sim output says how its run ended (an interrupted one: tests/simulate/resume_test.sh),
// so a file cut short never passes for a finished one; an unset collision budget is recorded as
// infinite, as an unset t_max is (it was 2^64 - 1 rounded to 1.8e19).
TEST_F(ValidInput, SimRecordsWhyItStopped) {
  struct Run {
    std::vector<std::string> flags;
    std::string reason;
    double budget;
  };
  const std::vector<Run> runs{{{"--t-max", "2"}, "t_max", std::numeric_limits<double>::infinity()},
                              {{"--t-max", "1000", "--max-collisions", "100"}, "max_collisions", 100}};
  for (const Run& x : runs) {
    const RunResult r = run("gg-sim", plus({"--N", "100", "--rho", "0.3", "--e", "0.9", "-o", "out.h5"}, x.flags));
    ASSERT_EQ(r.status, 0) << r.describe();
    const H5Input out((work_ / "out.h5").string());
    EXPECT_EQ(out.attr_string("/parameters", "stop_reason").value_or(""), x.reason);
    EXPECT_EQ(out.attr_double("/parameters", "max_collisions").value_or(-1), x.budget);
    fs::remove(work_ / "out.h5");
  }
}

// An output that is not a regular file is written through, never replaced (the final rename put an
// HDF5 file where /dev/full's device node was): a FIFO gets the whole file and stays a FIFO, and
// the devices stay devices, whether the write succeeds (/dev/null) or fails (/dev/full).
TEST_F(ValidInput, SimOutputThroughAFifoOrADeviceLeavesItInPlace) {
  const fs::path fifo = work_ / "out.fifo";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0644), 0);
  std::string received;
  std::thread reader([&] { received = read_bytes(fifo.string()); });
  const std::vector<std::string> scene{"--N", "50", "--rho", "0.1", "--e", "0.5", "--t-max", "1", "--snapshots", "1"};
  const RunResult r = run("gg-sim", plus(scene, {"-o", "out.fifo"}));
  reader.join();
  ASSERT_EQ(r.status, 0) << r.describe();
  EXPECT_TRUE(fs::is_fifo(fifo));
  ASSERT_GT(received.size(), 8u);
  EXPECT_EQ(received.substr(0, 8), std::string("\x89HDF\r\n\x1a\n", 8)) << "not an HDF5 file";
  EXPECT_EQ(entries(work_), (std::set<std::string>{"out.fifo"}));
  EXPECT_EQ(run("gg-sim", plus(scene, {"-o", "/dev/null"})).status, 0);
  EXPECT_EQ(run("gg-sim", plus(scene, {"-o", "/dev/full"})).status, 1);
  EXPECT_TRUE(fs::is_character_file("/dev/null"));
  EXPECT_TRUE(fs::is_character_file("/dev/full"));
}

// A symbolic link as output: the file it points to is replaced (created, if the link dangles),
// the link stays a link (it was replaced by the output).
TEST_F(ValidInput, SimOutputThroughASymlinkWritesItsTarget) {
  fs::create_directory(work_ / "data");
  fs::create_symlink("data/target.h5", work_ / "out.h5");
  const std::vector<std::string> scene{"--N", "50", "--rho", "0.1", "--e", "0.5", "--t-max", "1", "-o", "out.h5"};
  for (int round = 0; round < 2; ++round) {  // dangling, then pointing to the first round's file
    SCOPED_TRACE(round == 0 ? "dangling link" : "link to a file");
    const RunResult r = run("gg-sim", scene);
    ASSERT_EQ(r.status, 0) << r.describe();
    EXPECT_TRUE(fs::is_symlink(work_ / "out.h5"));
    EXPECT_EQ(H5Input((work_ / "data/target.h5").string()).attr_string("/parameters", "stop_reason").value_or(""), "t_max");
    EXPECT_EQ(entries(work_ / "data"), (std::set<std::string>{"target.h5"}));
  }
}

// An analysis of a run that stopped early says so on stderr and in its output, and so does an
// analysis of that analysis (the analyses of an interrupted run passed for complete ones).
TEST_F(ValidInput, AnalysesOfAnInterruptedRunWarnAndRecordIt) {
  make_input(work_, "interrupted.h5");
  const RunResult cluster = run("gg-cluster", {"interrupted.h5", "-o", "cluster.h5"});
  ASSERT_EQ(cluster.status, 0) << cluster.describe();
  EXPECT_TRUE(contains_any(cluster.err, "gg-cluster: warning: interrupted.h5 is from a run that stopped early")) << cluster.err;
  EXPECT_EQ(std::count(cluster.err.begin(), cluster.err.end(), '\n'), 1) << cluster.err;
  EXPECT_EQ(H5Input((work_ / "cluster.h5").string()).attr_strings("/parameters/provenance", "incomplete_inputs"),
            std::vector<std::string>{"interrupted.h5: stop_reason = interrupted"});
  ASSERT_EQ(run("gg-cluster", {"interrupted.h5", "--grid", "2", "-o", "cluster2.h5"}).status, 0);
  const RunResult average =
      run("gg-fit", {"average", "cluster.h5:/cluster/count", "cluster2.h5:/cluster/count", "-o", "average.h5"});
  ASSERT_EQ(average.status, 0) << average.describe();
  EXPECT_TRUE(contains_any(average.err, "cluster.h5 was made from a run that stopped early")) << average.err;
  EXPECT_EQ(H5Input((work_ / "average.h5").string()).attr_strings("/parameters/provenance", "incomplete_inputs"),
            (std::vector<std::string>{"cluster.h5 <- interrupted.h5: stop_reason = interrupted",
                                      "cluster2.h5 <- interrupted.h5: stop_reason = interrupted"}));
}

// --init FILE --continue starts at the time and collision count of FILE's last frame; a float
// output's last frame is kept in double (/restart), so a clustered gas written with
// --float-snapshots can start a run (its single-precision frame has disks 1 - 1e-6 apart).
TEST_F(ValidInput, SimContinuesAFloatOutputOnItsOwnClock) {
  const std::vector<std::string> scene{"--e", "0.5", "--tc", "1e-4"};
  const RunResult first = run("gg-sim", plus(scene, {"--L", "40", "--rho", "0.37", "--t-max", "50", "--snapshots",
                                                     "20,50", "--velocities", "--float-snapshots", "-o", "first.h5"}));
  ASSERT_EQ(first.status, 0) << first.describe();
  const RunResult next = run("gg-sim", plus(scene, {"--init", "first.h5", "--continue", "--t-max", "80", "-o", "next.h5"}));
  ASSERT_EQ(next.status, 0) << next.describe();
  const H5Input a((work_ / "first.h5").string()), b((work_ / "next.h5").string());
  EXPECT_EQ(b.attr_double("/parameters", "t_start").value_or(-1), 50);
  const TimeSeries ea = read_observable(a, "kinetic_energy"), eb = read_observable(b, "kinetic_energy");
  EXPECT_EQ(eb.time.front(), 50);
  EXPECT_EQ(eb.time.back(), 80);
  EXPECT_EQ(eb.step.front(), ea.step.back()) << "the collisions count on from the file's";
  // The same velocities summed in another order (the engine's numbering): equal to round-off.
  EXPECT_NEAR(eb.value.front(), ea.value.back(), 1e-12 * ea.value.back()) << "the start is the file's last state";
}

// A group linking back to the root (legal HDF5; h5ls -r prints "same as /"): `gg-fit table FILE`
// prints every group once, as if the link were not there (it recursed forever).
TEST_F(ValidInput, FitTableOfAGroupCyclePrintsEachGroupOnce) {
  make_input(work_, "series.h5");
  const RunResult plain = run("gg-fit", {"table", "series.h5"});
  ASSERT_EQ(plain.status, 0) << plain.describe();
  fs::remove(work_ / "series.h5");
  make_input(work_, "cycle.h5");
  fs::rename(work_ / "cycle.h5", work_ / "series.h5");  // the same name, so the same column names
  const RunResult cycle = run("gg-fit", {"table", "series.h5"});
  ASSERT_EQ(cycle.status, 0) << cycle.describe();
  EXPECT_EQ(cycle.out, plain.out);
  EXPECT_EQ(cycle.err, "");
}

}  // namespace
}  // namespace gg::robust
