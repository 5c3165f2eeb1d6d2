// gg-fit: the command-line layer over the ggfit library. Each subcommand reads its inputs into
// plain Series / Ensemble structs, calls the library, prints one readable line on stderr and, with
// -o, writes its results (plus provenance) to an HDF5 file; stdout carries only data.
// This file wires the subcommands (fit/subcommands.hpp, one fit/cmd_*.cpp each) into CLI11.
#include "fit/tool.hpp"

#include <string>
#include <vector>

#include "fit/onset.hpp"
#include "fit/subcommands.hpp"
#include "gg/cli.hpp"
#include "gg/errors.hpp"
#include "gg/h5file.hpp"

namespace gg::fit {
namespace cli {
namespace {

// ------------------------------------------------------------------------------------------------
// Command line

// --window T1 T2: exactly two values per occurrence (repeatable where a subcommand allows it).
CLI::Option* add_window(CLI::App* sub, std::vector<double>& w, const std::string& help) {
  return sub->add_option("--window", w, help)
      ->type_size(2)
      ->allow_extra_args(false)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)
      ->type_name("T1 T2");
}

// --sigmas of a verdict whose interval takes Student's t (help prefixed by `what`), and --tolerance of
// one that can also say "supported".
void add_level(CLI::App* sub, double& sigmas, const std::string& what = "") {
  sub->add_option("--sigmas", sigmas, what + "Level of the interval: the coverage of a normal's +-sigmas (2: 95.4%), "
                                             "with Student's t quantile of the jackknife's degrees of freedom")
      ->check(number_at_least(0, true))
      ->capture_default_str();
}
void add_tolerance(CLI::App* sub, double& tolerance) {
  sub->add_option("--tolerance", tolerance, "Relative band around 1 that 'supported' requires")
      ->check(number_at_least(0, true))
      ->capture_default_str();
}

// An optional -o.
void add_output(CLI::App* sub, std::string& output) {
  sub->add_option("-o,--output", output, "Output HDF5 file, '-' = stdout (default: none, only the printed line)");
}

// What every fit subcommand takes last: --errors and an optional -o.
void add_errors_and_output(CLI::App* sub, std::string& mode, std::string& output) {
  sub->add_option("--errors", mode,
                  "Error bars: 'covariance' of the fit (weighted by the ensemble stderr and scaled by max(1, chi2/dof); "
                  "unweighted: scaled by chi2/dof), 'jackknife' over the runs behind an ensemble average (needs the "
                  "/average/samples written by 'gg-fit average'; includes correlations between times), or 'auto' = "
                  "jackknife when >= " + std::to_string(kJackknifeMinRuns) + " runs are available, else covariance")
      ->check(CLI::IsMember({"auto", "covariance", "jackknife"}))
      ->capture_default_str();
  add_output(sub, output);
}

}  // namespace
}  // namespace cli

int gg_fit_main(int argc, char** argv) {
  using namespace cli;  // the subcommands (fit/subcommands.hpp) and the names they share, e.g. kProgram
  return guarded_main(kProgram, [&]() -> int {
    CLI::App app{"gg-fit: ensemble averages, power-law and exponent fits with honest error bars (GSL).\n"
                 "Datasets are named FILE.h5:/group/dataset ('-:/group/dataset' = stdin); each is paired with the 'time' dataset "
                 "beside it. A dataset with a 'stderr' sibling (e.g. OUT.h5:/average/mean) is fitted weighted by it. "
                 "Every fit prints one readable line on stderr; -o writes the numbers to HDF5 ('-' = stdout).",
                 kProgram};
    CommonFlags flags;
    add_common_flags(app, flags);
    app.require_subcommand(1);
    app.fallthrough();  // --quiet/--progress also after the subcommand, as with every other tool
    Common common;
    common.argv = argv_strings(argc, argv);

    AverageArgs av;
    auto* s_av = app.add_subcommand("average", "Mean and standard error over runs at each time (frame by frame for [T][R] data "
                                               "such as C(r,t) or P(l_d)); writes /average/{time,mean,stderr,runs} and, for "
                                               "time series, the runs themselves as /average/samples [R][T]");
    s_av->add_option("inputs", av.inputs, "Runs: FILE.h5:/group/dataset, or FILE.h5 with --dataset")->required();
    s_av->add_option("--dataset", av.dataset, "Dataset path for inputs given as bare file names (e.g. /cluster/mean_mass)");
    s_av->add_flag("--interpolate", av.interpolate,
                   "Runs on different time grids: interpolate linearly in ln t onto the first run's times inside the "
                   "range all runs cover (default: off; different grids are an error)");
    s_av->add_option("--from", av.from, "Leave out every run's samples before this time (e.g. where no cluster exists "
                                        "yet and the mean mass is undefined); default: none left out");
    s_av->add_option("-o,--output", common.output, "Output HDF5 file, '-' = stdout")->required();

    PowerLawArgs pl;
    auto* s_pl = app.add_subcommand("power-law", "Fit y = A t^z (least squares of ln y on ln t) over a window; "
                                                 "--offset fits y = y0 + A t^z. Writes /fit/{exponent,exponent_stderr,"
                                                 "amplitude,amplitude_stderr,chi2_dof,window}");
    s_pl->add_option("input", pl.input, "FILE.h5:/group/dataset")->required();
    add_window(s_pl, pl.window, "Fit window in time, inclusive")->required();
    s_pl->add_flag("--offset", pl.offset, "Fit y = y0 + A t^z by nonlinear least squares (data that start from a plateau)");
    add_errors_and_output(s_pl, pl.errors, common.output);

    LocalArgs le;
    auto* s_le = app.add_subcommand("local-exponent", "Local exponent d ln y / d ln t from sliding least-squares fits; "
                                                      "writes /local_exponent/{time,exponent,stderr}");
    s_le->add_option("input", le.input, "FILE.h5:/group/dataset")->required();
    s_le->add_option("--window", le.decades, "Width of the sliding window in decades of t")->capture_default_str();
    add_errors_and_output(s_le, le.errors, common.output);

    OnsetArgs on;
    OnsetCriterion defaults;
    auto* s_on = app.add_subcommand(
        "onset", "Onset of clustering. (1) " + describe_plateau(defaults) + ". (2) " +
                     describe_asymptote(defaults, 0.6) +
                     " (0.6 stands for --asymptote, or the exponent fitted over --window). Writes /onset/...; NaN = never");
    s_on->add_option("input", on.input, "FILE.h5:/group/dataset, e.g. m(t)")->required();
    s_on->add_option("--plateau-samples", on.criterion.plateau_samples, "K: the plateau is the median of the first K samples")
        ->capture_default_str();
    s_on->add_option("--tol", on.criterion.plateau_tol, "Leaves the plateau when y > plateau * (1 + tol)")->capture_default_str();
    s_on->add_option("--persist", on.criterion.persist, "... for this many consecutive samples (both criteria)")
        ->capture_default_str();
    s_on->add_option("--decades", on.criterion.decades, "Window of the local exponent, in decades")->capture_default_str();
    s_on->add_option("--exponent-tol", on.criterion.exponent_tol, "Local exponent within this of the asymptote")
        ->capture_default_str();
    auto* o_as = s_on->add_option("--asymptote", on.asymptote, "Asymptotic exponent (e.g. 0.6)")->check(finite_number());
    auto* o_win = add_window(s_on, on.window, "Or fit the asymptotic exponent over this window");
    o_as->excludes(o_win);
    add_errors_and_output(s_on, on.errors, common.output);

    HaffArgs hf;
    auto* s_hf = app.add_subcommand(
        "haff", "Fit E(t) = E0/(1+t/t0)^2 over an early window and compare t0 with Enskog: t0 = 2d/((1-e^2) omega0); "
                "omega0 = 2 sqrt(pi) rho g sqrt(T0) in 2D, 4 sqrt(pi) rho g sqrt(T0) with the Carnahan-Starling g = "
                "(1-eta/2)/(1-eta)^3, eta = pi rho/6, in 3D, (2/sqrt(pi)) rho g sqrt(T0) with g = 1/(1-rho) in 1D. "
                "rho, e, T0, dim come from the input's /parameters unless given as flags");
    s_hf->add_option("input", hf.input, "FILE.h5:/group/dataset, e.g. sim.h5:/observables/kinetic_energy/value")->required();
    add_window(s_hf, hf.window, "Fit window (default: from the first sample to half the Enskog t0)");
    s_hf->add_option("--rho", hf.rho, "Number density (default: /parameters rho, or N/L^d)")->check(number_at_least(0, true));
    s_hf->add_option("--e", hf.e, "Coefficient of restitution (default: /parameters e)")
        ->check(finite_number())
        ->check(CLI::Range(0.0, 1.0));
    s_hf->add_option("--T0", hf.T0, "Initial temperature (default: /parameters T0, else 2 E/d at the first sample)")
        ->check(number_at_least(0, true));
    s_hf->add_option("--dim", hf.dim, "Dimension 1, 2 or 3 (default: /parameters dim, else the H5MD box, else 2)")
        ->check(CLI::IsMember({1, 2, 3}));
    s_hf->add_option("--contact", hf.contact,
                     "2D pair correlation at contact: henderson = (1 - 7 phi/16)/(1 - phi)^2, luding = henderson - "
                     "phi^3/(128 (1 - phi)^4); phi = pi rho/4")
        ->check(CLI::IsMember({"henderson", "luding"}))
        ->capture_default_str();
    add_errors_and_output(s_hf, hf.errors, common.output);

    CollapseArgs co;
    auto* s_co = app.add_subcommand("collapse", "Several ensembles (e.g. one per e): one common exponent, one amplitude "
                                                "each (ln y_j = ln A_j + z ln t), amplitude ratios A_j/A_0 with errors "
                                                "and whether they agree within --sigmas. With --errors auto the errors "
                                                "are the jackknife's over runs from 3 runs per input on (the agreement "
                                                "needs the amplitudes' run-to-run scatter), their intervals with Student's t");
    s_co->add_option("inputs", co.inputs, "FILE.h5:/group/dataset, one per ensemble (first = reference)")->required();
    add_window(s_co, co.windows, "Fit window: once for all inputs, or once per input in order")->required();
    add_level(s_co, co.sigmas, "Amplitudes agree when ln(A_j/A_0) is 0 within its interval. ");
    add_errors_and_output(s_co, co.errors, common.output);

    ShiftArgs sh;
    auto* s_sh = app.add_subcommand(
        "shift", "Time-shift collapse without an assumed form: the factor c_j with y_j(t) = y_0(t / c_j) for each "
                 "ensemble against the first (y_0 interpolated in ln y - ln t), over the range of y both windows cover; "
                 "chi^2 per point of the collapsed data (a description); the lag t_j(y)/t_0(y) at --levels levels of y, "
                 "its drift d ln lag / d ln y and its curvature. Verdicts: collapses when drift and curvature are both "
                 "0 within their intervals, c constant when the drift is. Errors: jackknife over runs (>= 3 per "
                 "ensemble), intervals with Student's t (docs/PHYSICS.md \"Calibration of the verdicts\")");
    s_sh->add_option("inputs", sh.inputs, "FILE.h5:/average/mean of gg-fit average, one per ensemble (first = reference)")
        ->required();
    add_window(s_sh, sh.windows, "Part of each curve compared (past its onset, before finite size): once for all inputs, "
                                 "or once per input in order")->required();
    s_sh->add_option("--levels", sh.levels, "Levels of y at which the lag is read")->capture_default_str();
    add_level(s_sh, sh.sigmas);
    add_output(s_sh, common.output);

    LateExponentArgs lx;
    auto* s_lx = app.add_subcommand(
        "late-exponent", "The exponent of y = A t^z over the last --decades before --end, the same over the --decades "
                         "before those, and whether it has settled (their change within --sigmas). Errors: jackknife "
                         "over runs (>= 3)");
    s_lx->add_option("input", lx.input, "FILE.h5:/average/mean of gg-fit average")->required();
    s_lx->add_option("--end", lx.end, "End of the late window (default: the last sample)")->check(number_at_least(0, true));
    s_lx->add_option("--decades", lx.decades, "Width of each window, in decades")->capture_default_str();
    add_level(s_lx, lx.sigmas, "Settled when the change is 0 within its interval. ");
    add_output(s_lx, common.output);

    RatioArgs ra;
    auto* s_ra = app.add_subcommand(
        "ratio", "The ratio y_other(t)/y_reference(t) at equal times, averaged in ln over a window (no fitted exponent), "
                 "and whether it equals 1: supported (--sigmas interval within 1 +- --tolerance), rejected (1 outside "
                 "it) or undecided. Errors: jackknife over runs (>= 3 per ensemble)");
    s_ra->add_option("reference", ra.reference, "FILE.h5:/average/mean of the reference ensemble")->required();
    s_ra->add_option("other", ra.other, "FILE.h5:/average/mean of the other ensemble")->required();
    add_window(s_ra, ra.window, "Times compared (the reference's samples in it)")->required();
    add_level(s_ra, ra.sigmas);
    add_tolerance(s_ra, ra.tolerance);
    add_output(s_ra, common.output);

    AtEqualArgs ae;
    auto* s_ae = app.add_subcommand(
        "at-equal", "One quantity at equal values of another across ensembles, e.g. m at equal energy: for each X Y "
                    "pair (gg-fit average outputs of the same runs, in the same order), the time at which the mean of "
                    "X first crosses each --at level and the mean of Y there (both linear in ln - ln t), the ratio "
                    "Y_j / Y_0 at each level and averaged in ln over them, and whether that equals 1: supported, "
                    "rejected or undecided as for 'ratio'. Errors: jackknife over runs (>= 3 per ensemble), a run's X "
                    "and Y left out together");
    s_ae->add_option("inputs", ae.inputs, "X Y pairs, FILE.h5:/average/mean each, the reference's pair first")->required();
    s_ae->add_option("--at", ae.levels, "Values of X to compare at (every ensemble must reach them)")->required();
    add_level(s_ae, ae.sigmas);
    add_tolerance(s_ae, ae.tolerance);
    add_output(s_ae, common.output);

    CrossingArgs cr;
    auto* s_cr = app.add_subcommand(
        "crossing",
        "The time t* at which each ensemble's mean first reaches --level, e.g. the giant-cluster time t_g (the mean of "
        "/cluster/largest_share_of_clustered reaching 0.5) or, with --per-run, the first time the runs' largest cluster wraps (each run's "
        "/cluster/largest_wraps, 0/1 per frame, reaching 0.5). The direction is set by the side of the level the mean's first sample lies on "
        "(below: reached when >= level; above: when <= level; start the average where the series is on the side you mean, "
        "e.g. 'gg-fit average --from'). t* is interpolated linearly in the mean against ln t between the two samples around "
        "the crossing (linear in the mean, so 0 and step-like means are fine). With --stays: the first time after which the "
        "mean stays at or beyond the level to its last sample. Errors: delete-one jackknife over the runs behind each mean "
        "(>= 3, the /average/samples of 'gg-fit average'; with --interpolate when the runs' times differ) of ln t*, with "
        "runs - 1 degrees of freedom and Student's t intervals; also how many runs' own series reach the level, and "
        "t*_j / t*_0 with its interval (Welch's degrees of freedom). NaN with the reason when the mean never reaches the "
        "level. With --x (one positive value per input, e.g. the box edge L): the slope kappa of ln t* against ln x "
        "(least squares weighted by each input's number of runs, error propagated from the jackknife variances, "
        "Welch-Satterthwaite's degrees of freedom) "
        "and the verdict 'grows with x' / 'falls with x' (the interval excludes 0), 'independent of x' (it lies within "
        "+-tolerance) or 'undecided'. Prints one line per input and one for the slope; -o writes /crossing/{level, time, "
        "time_low, time_high, log_time_stderr, log_time_dof, runs, runs_reaching, ratio, ratio_low, ratio_high, ratio_dof, "
        "x, slope, slope_stderr, slope_dof} with attributes inputs, verdict, no_crossing, method, verdict_rule");
    s_cr->add_option("inputs", cr.inputs, "FILE.h5:/average/mean of each ensemble (the first is the reference of the ratios)")
        ->required();
    s_cr->add_option("--level", cr.level, "The value of the mean to reach, e.g. 0.5")->required()->check(finite_number());
    s_cr->add_flag("--stays", cr.stays, "t* = the first time after which the mean stays at or beyond --level to its end");
    s_cr->add_flag("--per-run", cr.per_run,
                   "t* = exp(mean over runs of ln t_r), each run's own crossing time, with the standard error of that mean: "
                   "for series that are 0/1 per run (a wrapping flag), where the mean's crossing is the runs' median and its "
                   "jackknife too narrow; NaN when a run never reaches the level (its time is censored)");
    s_cr->add_option("--x", cr.x, "One value per input, in order (e.g. the box edges L), > 0: the slope of ln t* against ln x");
    add_level(s_cr, cr.sigmas);
    s_cr->add_option("--tolerance", cr.tolerance, "Band +-tolerance of the slope within which t* is 'independent of x'")
        ->capture_default_str();
    add_output(s_cr, common.output);

    CompareArgs cm;
    auto* s_cm = app.add_subcommand(
        "compare", "Whether estimates agree with the first (e.g. the late exponents of several ensembles): each "
                   "FILE.h5:/path with its /path_stderr and /path_dof siblings (as late-exponent writes /late/exponent); "
                   "the difference from the first, its error in quadrature and Welch-Satterthwaite's degrees of freedom, "
                   "and whether it is 0 within its Student-t interval");
    s_cm->add_option("inputs", cm.inputs, "FILE.h5:/path of each estimate, the reference first")->required();
    add_level(s_cm, cm.sigmas);
    add_output(s_cm, common.output);

    ExtrapolateArgs ex;
    auto* s_ex = app.add_subcommand(
        "extrapolate", "A quantity measured at several box sizes (one input per L, each with its _stderr sibling, "
                       "e.g. collapse's /fit/amplitude_ratio): y(L) = y_inf + b/L fitted in 1/L, and whether "
                       "y == --expected is supported (the --sigmas interval lies within --tolerance), rejected "
                       "(--expected outside it) or undecided, at the largest L and for L -> infinity");
    s_ex->add_option("inputs", ex.inputs, "FILE.h5:/group/dataset, one per box size, in the order of --L")->required();
    s_ex->add_option("--L", ex.L, "Box edge of each input, increasing (give it after the inputs)")->required();
    s_ex->add_option("--expected", ex.expected, "The value the claim says the quantity has")->capture_default_str();
    s_ex->add_option("--sigmas", ex.sigmas, "Width of the interval, in standard errors")->capture_default_str();
    s_ex->add_option("--tolerance", ex.tolerance, "Relative band around --expected that 'supported' requires")
        ->capture_default_str();
    add_output(s_ex, common.output);

    TableArgs tb;
    bool no_header = false;
    auto* s_tb = app.add_subcommand("table", "Datasets as a tab-separated table on stdout (time first when they share "
                                             "one). A bare FILE.h5 or '-' prints every group with a time axis as its own "
                                             "block (gnuplot 'index'); a 2-D [T][R] dataset prints 'time x value' "
                                             "rows, a blank line between times, where x = r when its group has an r "
                                             "of length R (gg-correlate's C), the bin centre when it has bin_edges of "
                                             "length R+1 (gg-domains' histogram), else the column index (the header "
                                             "names it; time is the row index when there is no time axis); scalars "
                                             "print as one row");
    s_tb->add_option("inputs", tb.inputs, "FILE.h5:/group/dataset ... or FILE.h5 or '-'")->required();
    s_tb->add_flag("--no-header", no_header, "Omit the '#' header lines");

    std::vector<std::string> args = common.argv;
    std::vector<char*> argp;
    for (auto& a : args) {
      if (a.rfind("-:/", 0) == 0) a = kStdinName + a.substr(1);
      argp.push_back(a.data());
    }
    // CLI11 would only say "A subcommand is required" for a misspelt one.
    if (argc > 1 && argp[1][0] != '-') {
      std::string names;
      bool known = false;
      for (const auto* sub : app.get_subcommands({})) {
        names += (names.empty() ? "" : ", ") + sub->get_name();
        known = known || sub->get_name() == argp[1];
      }
      if (!known) throw UsageError("unknown subcommand '" + std::string(argp[1]) + "'; use one of " + names + "; see --help");
    }
    if (int status = parse_cli(app, argc, argp.data()); status >= 0) return status;
    // Checked here, once for every subcommand and before any of them opens a file: a subcommand's
    // positional arguments are what it reads (FILE.h5:/group/dataset, or FILE.h5 with --dataset),
    // and -o written over one of them would replace it.
    for (const CLI::App* sub : app.get_subcommands()) {
      std::vector<std::string> inputs;
      for (const CLI::Option* o : sub->get_options([](const CLI::Option* opt) { return opt->get_positional(); }))
        inputs.insert(inputs.end(), o->results().begin(), o->results().end());
      require_output_is_not_an_input(common.output, inputs);
    }
    if (s_av->parsed()) return run_average(common, av);
    if (s_pl->parsed()) return run_power_law(common, pl);
    if (s_le->parsed()) return run_local_exponent(common, le);
    if (s_on->parsed()) return run_onset(common, on);
    if (s_hf->parsed()) return run_haff(common, hf);
    if (s_co->parsed()) return run_collapse(common, co);
    if (s_sh->parsed()) return run_shift(common, sh);
    if (s_lx->parsed()) return run_late_exponent(common, lx);
    if (s_ra->parsed()) return run_ratio(common, ra);
    if (s_ae->parsed()) return run_at_equal(common, ae);
    if (s_cr->parsed()) return run_crossing(common, cr);
    if (s_cm->parsed()) return run_compare(common, cm);
    if (s_ex->parsed()) return run_extrapolate(common, ex);
    if (s_tb->parsed()) {
      tb.header = !no_header;
      return run_table(tb);
    }
    return kExitUsage;
  });
}

}  // namespace gg::fit
