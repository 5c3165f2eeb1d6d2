// gg-fit shift: the time factor that maps each ensemble onto the reference (y_j(t) = y_0(t / c_j)), the
// quality of that collapse, and the lag t_j(y) / t_0(y) at levels of y with its drift.
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <gsl/gsl_cdf.h>

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
  std::vector<std::vector<double>> se;
  for (std::size_t j = 1; j < k; ++j) {
    setup.push_back(shift_setup(in[0].series, w[0], in[j].series, w[j], L));
    fit.push_back(fit_shift(in[0].series, in[j].series, setup.back()));
    se.push_back(jackknife_stderr({*in[0].runs, *in[j].runs}, [&](const std::vector<Series>& m) {
      return shift_parameters(fit_shift(m[0], m[1], setup.back()));
    }));
  }
  // Verdicts: the collapse holds within errors when chi^2 per point stays below the chi^2 quantile
  // (1 - alpha of a normal at --sigmas) of its degrees of freedom; the factor is a constant when the
  // drift of the lag is within --sigmas of 0.
  const double alpha = 2 * gsl_cdf_ugaussian_Q(a.sigmas);
  bool all_collapse = true, all_constant = true;
  std::vector<std::int64_t> collapses{1}, constant{1};  // the reference with itself
  for (std::size_t j = 0; j + 1 < k; ++j) {
    const double dof = static_cast<double>(fit[j].points - 1);
    const bool col = fit[j].chi2_per_point <= gsl_cdf_chisq_Qinv(alpha, dof) / dof;
    // constant: 1 yes, 0 no (drifts), -1 undetermined (no error for the drift).
    const double drift_se = se[j].back();
    const int con = !std::isfinite(drift_se) || !std::isfinite(fit[j].drift) ? -1
                    : std::abs(fit[j].drift) <= a.sigmas * drift_se ? 1 : 0;
    collapses.push_back(col), constant.push_back(con);
    all_collapse = all_collapse && col, all_constant = all_constant && con == 1;
  }
  const std::string errors = "jackknife over runs, both ensembles of each pair";
  Output out(c.output);
  if (out) {
    std::vector<double> factor{1}, factor_se{0}, log_factor{0}, log_factor_se{0}, chi2{0}, drift{0}, drift_se{0};
    std::vector<std::int64_t> points{0};
    // The lag as rows (input j, level, ratio, stderr), every level of every ensemble but the reference.
    std::vector<double> lag, lag_se, levels;
    std::vector<std::int64_t> lag_input;
    Array range{{k, 2}, {kNaN, kNaN}};
    for (std::size_t j = 0; j + 1 < k; ++j) {
      const double lc = fit[j].log_factor;
      factor.push_back(std::exp(lc)), factor_se.push_back(std::exp(lc) * se[j][0]);
      log_factor.push_back(lc), log_factor_se.push_back(se[j][0]);
      chi2.push_back(fit[j].chi2_per_point), points.push_back(static_cast<std::int64_t>(fit[j].points));
      drift.push_back(fit[j].drift), drift_se.push_back(se[j].back());
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
    Array win{{k, 2}, {}};
    for (const auto& x : w) win.data.push_back(x.t1), win.data.push_back(x.t2);
    out->write("/shift/window", win);
    std::vector<std::string> names;
    for (const auto& l : in) names.push_back(l.name);
    out->attr("/shift", "inputs", names);
    out->attr("/shift", "method",
              std::string("y_j(t) = y_0(t / c_j): y_0 interpolated linearly in ln y - ln t; c_j minimises chi^2 = sum "
                          "(ln y_j(t_i) - ln y_0(t_i / c_j))^2 / (s_j^2 + s_0^2) over the samples of y_j in the y range "
                          "both windows cover (global minimum on a grid of ln c, refined by golden section); "
                          "chi2_per_point = chi^2 / (points - 1); lag = t_j(y) / t_0(y) at log-spaced levels of y "
                          "(first crossing, linear in ln y - ln t; rows: lag/input = j, lag/level = y), drift = "
                          "least-squares slope of ln lag on ln y"));
    out->attr("/shift", "verdicts",
              "collapses[j] = 1 if chi2_per_point <= the chi^2 quantile at " + fmt(a.sigmas) +
                  " sigma of its degrees of freedom; lag/constant[j] = 1 if |drift| <= " + fmt(a.sigmas) +
                  " stderr, 0 if not, -1 if the drift or its error is undetermined");
    out->attr("/shift", "errors", errors);
  }
  std::string line = "shift: " + std::to_string(k) + " ensembles against " + in[0].name + " over t in " + fmt_window(w[0]) + ";";
  for (std::size_t j = 0; j + 1 < k; ++j) {
    line += " [" + std::to_string(j + 1) + "] " + in[j + 1].name + " t in " + fmt_window(w[j + 1]) + ": c = " +
            pm(std::exp(fit[j].log_factor), std::exp(fit[j].log_factor) * se[j][0]) + " over y in [" +
            fmt(setup[j].y_lo) + ", " + fmt(setup[j].y_hi) + "] (" + std::to_string(fit[j].points) +
            " samples), chi2/point = " + fmt(fit[j].chi2_per_point) + (collapses[j + 1] ? " (collapses)" : " (does not collapse)") +
            ", lag drift d ln lag / d ln y = " + pm(fit[j].drift, se[j].back()) + (constant[j + 1] == 1 ? " (constant)" : constant[j + 1] == 0 ? " (drifts)" : " (undetermined)") + ";";
  }
  line += " all collapse within " + fmt(a.sigmas) + " sigma: " + (all_collapse ? "yes" : "no") +
          "; every factor constant: " + (all_constant ? "yes" : "no") + "; errors: " + errors;
  out.finish(c.argv, files, line);
  return 0;
}

}  // namespace gg::fit::cli
