// gg-fit crossing: the time each ensemble's mean first reaches a level (e.g. the giant-cluster time
// t_g, where the largest cluster's share of the clustered particles reaches 1/2), with its jackknife
// error over runs, or with --per-run the mean of the runs' own ln t (the first wrapping time), and with
// --x how it scales with x (e.g. the box edge L).
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "fit/crossing.hpp"
#include "fit/ensemble.hpp"
#include "fit/subcommands.hpp"
#include "gg/errors.hpp"

namespace gg::fit::cli {

int run_crossing(const Common& c, const CrossingArgs& a) {
  if (a.inputs.empty()) throw UsageError("crossing: give at least one FILE.h5:/average/mean");
  if (!std::isfinite(a.level)) throw UsageError("crossing: give the level to reach with --level (e.g. --level 0.5)");
  if (!(a.sigmas > 0)) throw UsageError("crossing: --sigmas must be > 0");
  if (!(a.tolerance > 0)) throw UsageError("crossing: --tolerance must be > 0 (a band of the slope, e.g. 0.1)");
  if (!a.x.empty()) {
    if (a.x.size() != a.inputs.size())
      throw UsageError("crossing: " + std::to_string(a.inputs.size()) + " inputs for " + std::to_string(a.x.size()) +
                       " values of --x; give one x per input, in the same order");
    if (a.inputs.size() < 2) throw UsageError("crossing: a slope against --x needs at least two inputs");
    for (double x : a.x)
      if (!(x > 0) || !std::isfinite(x)) throw UsageError("crossing: --x must be > 0 (got " + fmt(x) + "); the slope is taken in ln x");
  }
  const CrossingRule rule = a.stays ? CrossingRule::stays : CrossingRule::first;
  Files files;
  std::vector<Loaded> in;
  for (const auto& arg : a.inputs) {
    in.push_back(load_series(files, resolve(arg, "")));
    const Loaded& l = in.back();
    if (!l.runs || l.runs->size() < 3)
      throw UsageError("crossing: " + l.name + " carries " + std::to_string(l.runs ? l.runs->size() : 0) +
                       " runs; the jackknife needs >= 3 (give gg-fit average's /average/mean of >= 3 runs)");
  }
  const std::size_t n = in.size();
  std::vector<double> time(n), log_se(n), log_dof(n), lo(n), hi(n);
  std::vector<std::int64_t> runs(n), reaching(n);
  std::vector<std::string> names, reasons;
  for (std::size_t j = 0; j < n; ++j) {
    const Ensemble& e = *in[j].runs;
    names.push_back(in[j].name);
    const CrossingEstimate c = a.per_run ? mean_of_crossings(e, a.level, rule) : crossing_of_mean(e, a.level, rule);
    time[j] = std::exp(c.log_time), log_se[j] = c.log_time_stderr, log_dof[j] = c.log_time_dof;
    runs[j] = static_cast<std::int64_t>(e.size()), reaching[j] = static_cast<std::int64_t>(c.runs_reaching);
    reasons.push_back(!a.per_run || std::isfinite(time[j]) ? no_crossing_reason(in[j].series, a.level, rule)
                                                           : std::to_string(e.size() - c.runs_reaching) + " of " +
                                                                 std::to_string(e.size()) + " runs never reach " + fmt(a.level) +
                                                                 " (censored: the mean of their times is not known)");
    const double half = student_quantile(a.sigmas, log_dof[j]) * log_se[j];
    lo[j] = time[j] * std::exp(-half), hi[j] = time[j] * std::exp(half);
  }
  // Each input against the first: ln(t*_j / t*_0), its error in quadrature, Welch's dof.
  std::vector<double> ratio(n), ratio_lo(n), ratio_hi(n), ratio_dof(n);
  for (std::size_t j = 0; j < n; ++j) {
    const Estimate d = difference({std::log(time[j]), log_se[j], log_dof[j]}, {std::log(time[0]), log_se[0], log_dof[0]});
    const double half = j == 0 ? 0 : student_quantile(a.sigmas, d.dof) * d.se;
    ratio[j] = std::exp(d.value), ratio_lo[j] = ratio[j] * std::exp(-half), ratio_hi[j] = ratio[j] * std::exp(half);
    ratio_dof[j] = j == 0 ? kNaN : d.dof;
  }
  CrossingSlope slope{kNaN, kNaN, kNaN, 0};
  std::string verdict = "none: no --x";
  if (!a.x.empty()) {
    std::vector<double> weight(n), lt(n), var(n);
    for (std::size_t j = 0; j < n; ++j)
      weight[j] = static_cast<double>(runs[j]), lt[j] = std::log(time[j]), var[j] = log_se[j] * log_se[j];
    slope = crossing_slope(a.x, weight, lt, var, log_dof);
    verdict = slope_verdict(slope, a.sigmas, a.tolerance);
  }

  Output out(c.output);
  if (out) {
    out->write("/crossing/level", std::vector<double>{a.level});
    out->write("/crossing/time", time);
    out->write("/crossing/log_time_stderr", log_se);
    out->write("/crossing/log_time_dof", log_dof);
    out->write("/crossing/time_low", lo);
    out->write("/crossing/time_high", hi);
    out->write("/crossing/runs", runs);
    out->write("/crossing/runs_reaching", reaching);
    out->write("/crossing/ratio", ratio);
    out->write("/crossing/ratio_low", ratio_lo);
    out->write("/crossing/ratio_high", ratio_hi);
    out->write("/crossing/ratio_dof", ratio_dof);
    if (!a.x.empty()) out->write("/crossing/x", a.x);
    out->write("/crossing/slope", std::vector<double>{slope.slope});
    out->write("/crossing/slope_stderr", std::vector<double>{slope.slope_stderr});
    out->write("/crossing/slope_dof", std::vector<double>{slope.slope_dof});
    out->attr("/crossing", "inputs", names);
    out->attr("/crossing", "verdict", verdict);
    out->attr("/crossing", "no_crossing", reasons);
    const std::string series = a.per_run ? "each run's own series" : "the ensemble mean";
    out->attr("/crossing", "method",
              (a.per_run ? std::string("time = exp(mean over runs of ln t_r), t_r = ") : std::string("time = ")) +
                  (a.stays ? "the first time after which " + series + " stays at or beyond level to its last sample"
                           : "the first time " + series + " reaches level") +
                  " (from the side of level its first sample lies on), linear in the series against ln t between the samples "
                  "around it; NaN if it never does (no_crossing says why). log_time_stderr: " +
                  (a.per_run ? "the standard error of the mean of ln t_r" : "delete-one jackknife over runs of ln time") +
                  ", log_time_dof = runs - 1; time_low/high: time x exp(-+ t log_time_stderr), t Student's quantile "
                  "at the coverage of a normal's " + fmt(a.sigmas) + " sigma. runs_reaching: runs whose own series reach "
                  "level by the same rule. ratio = time_j / time_0 with its interval (Welch-Satterthwaite's ratio_dof). "
                  "slope: of ln time against ln x, least squares weighted by the runs of each input (fixed weights: see "
                  "docs/PHYSICS.md), stderr propagated from log_time_stderr, dof by Welch-Satterthwaite; over the inputs "
                  "whose time and error are finite (NaN without --x)");
    out->attr("/crossing", "verdict_rule",
              "on slope +- t slope_stderr (t: Student's quantile of slope_dof at the coverage of a normal's " + fmt(a.sigmas) +
                  " sigma): 'grows with x' above 0, 'falls with x' below 0, 'independent of x' within +-" + fmt(a.tolerance) +
                  ", else 'undecided'");
  }
  const std::string rule_name = a.stays ? "stays at or beyond " : "first reaches ";
  std::string line = "crossing: " + std::string(a.per_run ? "the mean over runs of ln t, t where each run " : "the mean ") +
                     rule_name + fmt(a.level) + ":";
  for (std::size_t j = 0; j < n; ++j) {
    line += "\n" + std::string(kProgram) + " crossing: [" + std::to_string(j) + "] " + names[j] +
            (a.x.empty() ? "" : " (x = " + fmt(a.x[j]) + ")") + ": ";
    if (std::isfinite(time[j]))
      line += "t* = " + fmt(time[j]) + ", " + fmt(a.sigmas) + "-sigma interval [" + fmt(lo[j]) + ", " + fmt(hi[j]) +
              "] (ln t* +/- " + fmt(log_se[j]) + ", " + fmt(log_dof[j]) + " dof)" +
              (j > 0 ? ", t*/t*_0 = " + fmt(ratio[j]) + " [" + fmt(ratio_lo[j]) + ", " + fmt(ratio_hi[j]) + "]" : "");
    else
      line += "t* = NaN: " + reasons[j];
    line += "; " + std::to_string(reaching[j]) + " of " + std::to_string(runs[j]) + " runs reach it";
  }
  if (!a.x.empty())
    line += "\n" + std::string(kProgram) + " crossing: slope of ln t* against ln x = " +
            (std::isfinite(slope.slope) ? pm(slope.slope, slope.slope_stderr) + " (" + fmt(slope.slope_dof) + " dof, " +
                                              std::to_string(slope.points) + " inputs)"
                                        : std::string("NaN (fewer than two inputs reach the level with an error)")) +
            ": " + verdict + " (" + fmt(a.sigmas) + " sigma, Student's t; independent within +-" + fmt(a.tolerance) + ")";
  out.finish(c.argv, files, line);
  return 0;
}

}  // namespace gg::fit::cli
