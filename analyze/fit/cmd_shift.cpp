// gg-fit shift: the time factor that maps each ensemble onto the reference (y_j(t) = y_0(t / c_j)), the
// quality of that collapse, and the lag t_j(y) / t_0(y) at levels of y with its drift.
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "fit/ensemble.hpp"
#include "fit/shift.hpp"
#include "fit/subcommands.hpp"
#include "gg/errors.hpp"

namespace gg::fit::cli {

int run_shift(const Common& c, const ShiftArgs& a) {
  Files files;
  std::vector<Loaded> in;
  for (const auto& arg : a.inputs) in.push_back(load_series(files, resolve(arg, "")));
  const std::size_t k = in.size();
  if (k < 2) throw UsageError("shift: give the reference and at least one other ensemble");
  const std::vector<Window> w = windows_per_input(a.windows, k, "shift");
  // A factor without an error bar is not an answer: every input must carry its runs (>= 3).
  for (const auto& l : in)
    if (!l.runs || l.runs->size() < 3)
      throw UsageError("shift: " + l.name + " carries " + std::to_string(l.runs ? l.runs->size() : 0) +
                       " runs; the jackknife needs >= 3 per ensemble (give gg-fit average's /average/mean of >= 3 runs)");
  const std::size_t L = a.levels;
  std::vector<ShiftSetup> setup;
  std::vector<ShiftFit> fit;
  std::vector<Jackknife> jack;
  std::vector<ShiftVerdict> verdict;
  for (std::size_t j = 1; j < k; ++j) {
    setup.push_back(shift_setup(in[0].series, w[0], in[j].series, w[j], L));
    fit.push_back(fit_shift(in[0].series, in[j].series, setup.back()));
    jack.push_back(jackknife({*in[0].runs, *in[j].runs}, [&](const std::vector<Series>& m) {
      return shift_parameters(fit_shift(m[0], m[1], setup.back()));
    }));
    verdict.push_back(shift_verdict(fit.back(), jack.back(), a.sigmas));
  }
  bool all_collapse = true, all_constant = true;
  std::vector<std::int64_t> collapses{1}, constant{1};  // the reference with itself
  for (const ShiftVerdict& v : verdict) {
    collapses.push_back(v.collapses), constant.push_back(v.constant);
    all_collapse = all_collapse && v.collapses, all_constant = all_constant && v.constant == 1;
  }
  const std::size_t drift_at = L + 1, curvature_at = L + 2;  // in shift_parameters
  std::vector<std::vector<double>> se;
  for (const Jackknife& j : jack) se.push_back(j.se);
  const auto interval_at = [&](std::size_t j, int end) {
    return std::exp(fit[j].log_factor + (end ? 1 : -1) * verdict[j].log_factor_halfwidth);
  };
  const std::string errors = "jackknife over runs, both ensembles of each pair; intervals with Student's t";
  Output out(c.output);
  if (out) {
    std::vector<double> factor{1}, factor_se{0}, log_factor{0}, log_factor_se{0}, chi2{0}, drift{0}, drift_se{0},
        curv{0}, curv_se{0}, dof{kNaN};
    Array interval{{k, 2}, {1, 1}};
    std::vector<std::int64_t> points{0};
    // The lag as rows (input j, level, ratio, stderr), every level of every ensemble but the reference.
    std::vector<double> lag, lag_se, levels;
    std::vector<std::int64_t> lag_input;
    Array range{{k, 2}, {kNaN, kNaN}};
    for (std::size_t j = 0; j + 1 < k; ++j) {
      const double lc = fit[j].log_factor;
      factor.push_back(std::exp(lc)), factor_se.push_back(std::exp(lc) * se[j][0]);
      log_factor.push_back(lc), log_factor_se.push_back(se[j][0]), dof.push_back(jack[j].dof[0]);
      interval.data.push_back(interval_at(j, 0)), interval.data.push_back(interval_at(j, 1));
      chi2.push_back(fit[j].chi2_per_point), points.push_back(static_cast<std::int64_t>(fit[j].points));
      drift.push_back(fit[j].drift), drift_se.push_back(se[j][drift_at]);
      curv.push_back(fit[j].curvature), curv_se.push_back(se[j][curvature_at]);
      for (std::size_t l = 0; l < L; ++l) {
        lag_input.push_back(static_cast<std::int64_t>(j + 1));
        levels.push_back(setup[j].levels[l]);
        lag.push_back(std::exp(fit[j].log_lag[l]));
        lag_se.push_back(std::exp(fit[j].log_lag[l]) * se[j][1 + l]);
      }
      range.data.push_back(setup[j].y_lo), range.data.push_back(setup[j].y_hi);
    }
    out->write("/shift/factor", factor);
    out->write("/shift/factor_stderr", factor_se);
    out->write("/shift/log_factor", log_factor);
    out->write("/shift/log_factor_stderr", log_factor_se);
    out->write("/shift/log_factor_dof", dof);
    out->write("/shift/factor_interval", interval);
    out->write("/shift/chi2_per_point", chi2);
    out->write("/shift/points", points);
    out->write("/shift/y_range", range);
    out->write("/shift/collapses", collapses);
    out->write("/shift/lag/input", lag_input);
    out->write("/shift/lag/level", levels);
    out->write("/shift/lag/ratio", lag);
    out->write("/shift/lag/ratio_stderr", lag_se);
    out->write("/shift/lag/drift", drift);
    out->write("/shift/lag/drift_stderr", drift_se);
    out->write("/shift/lag/constant", constant);
    out->write("/shift/lag/curvature", curv);
    out->write("/shift/lag/curvature_stderr", curv_se);
    Array win{{k, 2}, {}};
    for (const auto& x : w) win.data.push_back(x.t1), win.data.push_back(x.t2);
    out->write("/shift/window", win);
    std::vector<std::string> names;
    for (const auto& l : in) names.push_back(l.name);
    out->attr("/shift", "inputs", names);
    out->attr("/shift", "method",
              std::string("y_j(t) = y_0(t / c_j): y_0 interpolated linearly in ln y - ln t; c_j minimises sum "
                          "(ln y_j(t_i) - ln y_0(t_i / c_j))^2 over the samples of y_j in the y range both windows cover "
                          "(global minimum on a grid of ln c, refined by golden section); chi2_per_point = that sum "
                          "divided by (s_j^2 + s_0^2) at each sample, over (points - 1); lag = t_j(y) / t_0(y) at log-spaced levels of y "
                          "(first crossing, linear in ln y - ln t; rows: lag/input = j, lag/level = y), drift = "
                          "least-squares slope of ln lag on ln y, curvature = its quadratic coefficient on ln y mapped "
                          "onto [-1, 1] over the levels"));
    out->attr("/shift", "verdicts",
              "at the two-sided level of a normal's " + fmt(a.sigmas) + " sigma, each interval with Student's t "
                  "quantile of its jackknife's Welch-Satterthwaite degrees of freedom (log_factor_dof): factor_interval "
                  "= exp(ln c +- t stderr); collapses[j] = 1 if the lag's drift and curvature are both within their "
                  "intervals at half that level (Bonferroni); lag/constant[j] = 1 if the drift is within its interval, "
                  "0 if not, -1 if the drift or its error is undetermined; chi2_per_point describes the collapse, it "
                  "decides nothing");
    out->attr("/shift", "errors", errors);
  }
  std::string line = "shift: " + std::to_string(k) + " ensembles against " + in[0].name + " over t in " + fmt_window(w[0]) + ";";
  for (std::size_t j = 0; j + 1 < k; ++j) {
    line += " [" + std::to_string(j + 1) + "] " + in[j + 1].name + " t in " + fmt_window(w[j + 1]) + ": c = " +
            pm(std::exp(fit[j].log_factor), std::exp(fit[j].log_factor) * se[j][0]) + " (interval [" +
            fmt(interval_at(j, 0)) + ", " + fmt(interval_at(j, 1)) + "]) over y in [" +
            fmt(setup[j].y_lo) + ", " + fmt(setup[j].y_hi) + "] (" + std::to_string(fit[j].points) +
            " samples), chi2/point = " + fmt(fit[j].chi2_per_point) + ", lag curvature " +
            pm(fit[j].curvature, se[j][curvature_at]) + (collapses[j + 1] ? " (collapses)" : " (does not collapse)") +
            ", lag drift d ln lag / d ln y = " + pm(fit[j].drift, se[j][drift_at]) +
            (constant[j + 1] == 1 ? " (constant)" : constant[j + 1] == 0 ? " (drifts)" : " (undetermined)") + ";";
  }
  line += " all collapse within " + fmt(a.sigmas) + " sigma: " + (all_collapse ? "yes" : "no") +
          "; every factor constant: " + (all_constant ? "yes" : "no") + "; errors: " + errors;
  out.finish(c.argv, files, line);
  return 0;
}

}  // namespace gg::fit::cli
