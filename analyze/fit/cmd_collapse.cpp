// gg-fit collapse: one common exponent and one amplitude per ensemble, and whether the amplitudes agree.
#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "fit/collapse.hpp"
#include "fit/ensemble.hpp"
#include "fit/subcommands.hpp"
#include "gg/errors.hpp"

namespace gg::fit::cli {

int run_collapse(const Common& c, const CollapseArgs& a) {
  Files files;
  std::vector<Loaded> in;
  for (const auto& arg : a.inputs) in.push_back(load_series(files, resolve(arg, "")));
  const std::size_t k = in.size();
  const std::vector<Window> w = windows_per_input(a.windows, k, "collapse");
  std::vector<Series> s;
  std::vector<const Loaded*> ptrs;
  for (const auto& l : in) {
    s.push_back(l.series);
    ptrs.push_back(&l);
  }
  CollapseFit f = fit_collapse(s, w, a.sigmas);
  // The amplitudes' agreement needs their run-to-run scatter, which the fit's covariance misses
  // (equal amplitudes "differed" in half of the synthetic trials by it): with --errors auto the
  // jackknife is used from 3 runs per input on, its interval with Student's t.
  const ErrorMode mode = error_mode(a.errors);
  bool every_has_runs = true;
  for (const Loaded* l : ptrs) every_has_runs = every_has_runs && l->runs && l->runs->size() >= 3;
  const bool jack = mode == ErrorMode::automatic ? every_has_runs : use_jackknife(mode, ptrs);
  std::size_t fewest = 0;
  if (jack) {
    std::vector<Ensemble> groups;
    for (const auto& l : in) groups.push_back(*l.runs);
    set_collapse_errors(f, jackknife(groups, [&](const std::vector<Series>& m) {
                          return collapse_parameters(fit_collapse(m, w, a.sigmas));
                        }));
    fewest = groups.front().size();
    for (const auto& g : groups) fewest = std::min(fewest, g.size());
  }
  const std::string errors = jack ? "jackknife over runs, every ensemble (fewest " + std::to_string(fewest) + " runs)"
                                  : errors_text(false, mode, s.front(), in.front().runs ? in.front().runs->size() : 0);
  std::vector<std::string> names;
  for (const auto& l : in) names.push_back(l.name);
  const std::string verdict = std::string(f.all_agree ? "yes" : "no") + ": amplitudes " +
                              (f.all_agree ? "agree" : "differ") + " within " + fmt(a.sigmas) + " sigma";
  Output out(c.output);
  if (out) {
    write_estimate(*out, "/fit/exponent", f.exponent, f.exponent_stderr);
    out->write("/fit/amplitude", f.amplitude);
    out->write("/fit/amplitude_stderr", f.amplitude_stderr);
    out->write("/fit/amplitude_ratio", f.ratio);
    out->write("/fit/amplitude_ratio_stderr", f.ratio_stderr);
    out->write("/fit/amplitude_ratio_dof", f.log_ratio_dof);
    out->write("/fit/agree", std::vector<std::int64_t>(f.agree.begin(), f.agree.end()));
    out->write_scalar("/fit/chi2_dof", f.chi2_dof);
    Array win{{k, 2}, {}};
    for (const auto& x : w) {
      win.data.push_back(x.t1);
      win.data.push_back(x.t2);
    }
    out->write("/fit/window", win);
    out->attr("/fit", "method",
              std::string("collapse: weighted least squares of ln y_j = ln A_j + z ln t, one exponent for all inputs, "
                          "one amplitude per input, each over its own window (GSL multifit_wlinear)"));
    out->attr("/fit", "inputs", names);
    out->attr("/fit", "input", names.front());
    out->attr("/fit", "reference", "amplitude_ratio = A_j / A_0, A_0 of " + names.front());
    out->attr("/fit", "agreement", "agree[j] = 1 if |ln(A_j/A_0)| <= t stderr of ln(A_j/A_0), t Student's quantile of "
                                   "amplitude_ratio_dof (inf: the normal's) at the coverage of a normal's " + fmt(a.sigmas) + " sigma");
    out->attr("/fit", "verdict", verdict);
    out->attr("/fit", "errors", errors);
    out->attr("/fit", "weights", weights_text(s.front(), 0));
  }
  std::string line = "collapse: " + std::to_string(k) + " ensembles, common z = " + pm(f.exponent, f.exponent_stderr) +
                     ", " + chi2_text(f.weighted, f.chi2_dof) + ";";
  for (std::size_t j = 0; j < k; ++j) {
    line += " [" + std::to_string(j) + "] " + names[j] + " t in " + fmt_window(w[j]) + ": A = " +
            pm(f.amplitude[j], f.amplitude_stderr[j]);
    if (j > 0)
      line += ", A/A_0 = " + pm(f.ratio[j], f.ratio_stderr[j]) + (f.agree[j] ? " (agrees)" : " (differs)");
    line += ";";
  }
  line += " amplitudes agree within " + fmt(a.sigmas) + " sigma: " + (f.all_agree ? "yes" : "no") + "; errors: " + errors;
  out.finish(c.argv, files, line);
  return 0;
}

}  // namespace gg::fit::cli
