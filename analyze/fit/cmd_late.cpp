// gg-fit late-exponent and ratio: the late end of growth curves read without a common exponent: the
// late exponent and whether it has settled, and the ratio of two curves at equal times.
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "fit/ensemble.hpp"
#include "fit/extrapolate.hpp"
#include "fit/late_growth.hpp"
#include "fit/subcommands.hpp"
#include "gg/errors.hpp"

namespace gg::fit::cli {

namespace {

// The jackknife over the runs behind every input: its standard errors are all these commands report.
void require_runs(const std::vector<const Loaded*>& in, const std::string& what) {
  for (const Loaded* l : in)
    if (!l->runs || l->runs->size() < 3)
      throw UsageError(what + ": " + l->name + " carries " + std::to_string(l->runs ? l->runs->size() : 0) +
                       " runs; the jackknife needs >= 3 (give gg-fit average's /average/mean of >= 3 runs)");
}

}  // namespace

int run_late_exponent(const Common& c, const LateExponentArgs& a) {
  Files files;
  Loaded in = load_series(files, resolve(a.input, ""));
  require_runs({&in}, "late-exponent");
  const double t_end = std::isnan(a.end) ? in.series.t.back() : a.end;
  const LateExponent f = late_exponent(in.series, t_end, a.decades);
  const Jackknife j =
      jackknife({*in.runs}, [&](const std::vector<Series>& m) { return late_exponent_parameters(late_exponent(m[0], t_end, a.decades)); });
  const std::vector<double>& se = j.se;
  const bool settled = within({f.change, se[2], j.dof[2]}, 0, a.sigmas);
  Output out(c.output);
  if (out) {
    write_estimate(*out, "/late/exponent", f.late, se[0]);
    out->write_scalar("/late/exponent_dof", j.dof[0]);
    write_estimate(*out, "/late/exponent_before", f.before, se[1]);
    write_estimate(*out, "/late/change", f.change, se[2]);
    out->write("/late/settled", std::vector<std::int64_t>{settled});
    out->write("/late/window", std::vector<double>{f.late_window.t1, f.late_window.t2});
    out->write("/late/window_before", std::vector<double>{f.before_window.t1, f.before_window.t2});
    out->attr("/late", "method",
              "exponent of y = A t^z (least squares of ln y on ln t) over the last " + fmt(a.decades) +
                  " decades before the end, and over the " + fmt(a.decades) + " decades before those; change = late - before");
    out->attr("/late", "verdict", "settled = 1 if |change| <= t stderr of the change, t Student's quantile of exponent_dof "
                                  "degrees of freedom at the coverage of a normal's " + fmt(a.sigmas) + " sigma");
    out->attr("/late", "input", in.name);
    out->attr("/late", "errors", "jackknife over " + std::to_string(in.runs->size()) + " runs (exponent_dof = runs - 1)");
  }
  out.finish(c.argv, files, "late-exponent: " + in.name + ": z = " + pm(f.late, se[0]) + " over t in " + fmt_window(f.late_window) +
      ", z = " + pm(f.before, se[1]) + " over " + fmt_window(f.before_window) + ", change " + pm(f.change, se[2]) +
      (settled ? ": settled" : ": still changing") + " (within " + fmt(a.sigmas) + " sigma); errors: jackknife over " +
      std::to_string(in.runs->size()) + " runs");
  return 0;
}

int run_ratio(const Common& c, const RatioArgs& a) {
  Files files;
  Loaded ref = load_series(files, resolve(a.reference, "")), other = load_series(files, resolve(a.other, ""));
  require_runs({&ref, &other}, "ratio");
  const Window w = window_from(a.window, "ratio");
  const EqualTimeRatio r = equal_time_ratio(ref.series, other.series, w);
  const Jackknife j = jackknife({*ref.runs, *other.runs}, [&](const std::vector<Series>& m) {
    return std::vector<double>{equal_time_ratio(m[0], m[1], w).log_ratio};
  });
  const double se = j.se[0], ratio = std::exp(r.log_ratio), ratio_se = ratio * se;
  // Against the claim y_B = y_A, on the Student-t interval of ln ratio.
  const std::string verdict = verdict_name(ratio_verdict(r.log_ratio, se, j.dof[0], a.sigmas, a.tolerance));
  Output out(c.output);
  if (out) {
    write_estimate(*out, "/ratio/ratio", ratio, ratio_se);
    write_estimate(*out, "/ratio/log_ratio", r.log_ratio, se);
    out->write_scalar("/ratio/log_ratio_dof", j.dof[0]);
    out->write("/ratio/points", std::vector<std::int64_t>{static_cast<std::int64_t>(r.points)});
    out->write("/ratio/window", std::vector<double>{w.t1, w.t2});
    out->attr("/ratio", "method",
              std::string("exp of the mean of ln(y_other(t) / y_reference(t)) over the reference's samples in the window, "
                          "y_other interpolated linearly in ln y - ln t"));
    out->attr("/ratio", "inputs", std::vector<std::string>{ref.name, other.name});
    out->attr("/ratio", "verdict", verdict);
    out->attr("/ratio", "verdict_rule",
              "against ratio = 1: rejected if 1 lies outside the interval of ln ratio +- t stderr (t: Student's quantile "
              "of log_ratio_dof degrees of freedom at the coverage of a normal's " + fmt(a.sigmas) + " sigma), supported "
              "if the interval lies within 1 +- " + fmt(a.tolerance) + ", else undecided");
    out->attr("/ratio", "errors", "jackknife over runs, both ensembles (log_ratio_dof: Welch-Satterthwaite)");
  }
  out.finish(c.argv, files, "ratio: " + other.name + " / " + ref.name + " at equal times in " + fmt_window(w) + " (" +
      std::to_string(r.points) + " samples) = " + pm(ratio, ratio_se) + "; y_other = y_reference: " + verdict +
      " (" + fmt(a.sigmas) + " sigma, within " + fmt(a.tolerance) + "); errors: jackknife over runs");
  return 0;
}

}  // namespace gg::fit::cli
