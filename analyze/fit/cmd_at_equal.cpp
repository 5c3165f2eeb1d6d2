// gg-fit at-equal: y of each ensemble at the times its own x crosses given levels (e.g. m at equal
// energy E), and the ratio of each ensemble's y to the reference's there, with whether it equals 1.
#include <cmath>
#include <string>
#include <vector>

#include "fit/at_equal.hpp"
#include "fit/ensemble.hpp"
#include "fit/extrapolate.hpp"
#include "fit/subcommands.hpp"
#include "gg/errors.hpp"

namespace gg::fit::cli {

int run_at_equal(const Common& c, const AtEqualArgs& a) {
  if (a.inputs.size() < 4 || a.inputs.size() % 2 != 0)
    throw UsageError("at-equal: give X Y pairs, the reference's first and at least one other (got " +
                     std::to_string(a.inputs.size()) + " inputs)");
  if (a.levels.empty()) throw UsageError("at-equal: give the values of x to compare at with --at");
  Files files;
  std::vector<Loaded> x, y;
  for (std::size_t i = 0; i < a.inputs.size(); i += 2) {
    x.push_back(load_series(files, resolve(a.inputs[i], "")));
    y.push_back(load_series(files, resolve(a.inputs[i + 1], "")));
  }
  const std::size_t k = x.size(), K = a.levels.size();
  for (std::size_t j = 0; j < k; ++j) {
    for (const Loaded* l : {&x[j], &y[j]})
      if (!l->runs || l->runs->size() < 3)
        throw UsageError("at-equal: " + l->name + " carries " + std::to_string(l->runs ? l->runs->size() : 0) +
                         " runs; the jackknife needs >= 3 (give gg-fit average's /average/mean of >= 3 runs)");
    if (x[j].runs->size() != y[j].runs->size())
      throw UsageError("at-equal: " + x[j].name + " and " + y[j].name + " carry " + std::to_string(x[j].runs->size()) +
                       " and " + std::to_string(y[j].runs->size()) + " runs; average x and y over the same runs, in the same order");
    for (double level : a.levels) {
      const double t = time_at_level(x[j].series, level);
      if (!std::isfinite(value_at_time(y[j].series, t)))
        throw RuntimeError("at-equal: " + (std::isfinite(t) ? y[j].name + " has no sample around t = " + fmt(t) + ", where "
                                                            : std::string("")) +
                           x[j].name + (std::isfinite(t) ? " crosses " : " never crosses ") + fmt(level) +
                           "; choose --at values every ensemble's x and y reach (x spans [" + fmt(x[j].series.y.front()) +
                           ", " + fmt(x[j].series.y.back()) + "])");
    }
  }
  // Per other ensemble j: the comparison with the reference and its jackknife over both ensembles'
  // runs, x and y of a run left out together.
  std::vector<AtEqual> cmp;
  std::vector<Jackknife> jack;
  std::vector<Verdict> verdict;
  for (std::size_t j = 1; j < k; ++j) {
    const auto est = [&](const std::vector<Series>& m) {
      const AtEqual e = at_equal(m[0], m[1], m[2], m[3], a.levels);
      std::vector<double> p = at_equal_parameters(e);
      p.insert(p.end(), e.log_y_ref.begin(), e.log_y_ref.end());
      p.insert(p.end(), e.log_y_other.begin(), e.log_y_other.end());
      return p;
    };
    cmp.push_back(at_equal(x[0].series, y[0].series, x[j].series, y[j].series, a.levels));
    jack.push_back(jackknife_linked({{*x[0].runs, *y[0].runs}, {*x[j].runs, *y[j].runs}}, est));
    verdict.push_back(ratio_verdict(cmp.back().mean_log_ratio, jack.back().se[0], jack.back().dof[0], a.sigmas, a.tolerance));
  }
  // y at each level with its error: the reference's from its first comparison (its runs alone vary
  // the reference's y there), every other's from its own.
  Array y_at{{k, K}, {}}, y_se{{k, K}, {}}, t_at{{k, K}, {}}, ratio{{k, K}, {}}, ratio_se{{k, K}, {}};
  for (std::size_t j = 0; j < k; ++j)
    for (std::size_t l = 0; l < K; ++l) {
      const bool ref = j == 0;
      const AtEqual& e = cmp[ref ? 0 : j - 1];
      const Jackknife& jk = jack[ref ? 0 : j - 1];
      const double ly = ref ? e.log_y_ref[l] : e.log_y_other[l];
      y_at.data.push_back(std::exp(ly)), y_se.data.push_back(std::exp(ly) * jk.se[1 + K + (ref ? 0 : K) + l]);
      t_at.data.push_back(time_at_level(x[j].series, a.levels[l]));
      ratio.data.push_back(ref ? 1 : std::exp(e.log_ratio[l]));
      ratio_se.data.push_back(ref ? 0 : std::exp(e.log_ratio[l]) * jk.se[1 + l]);
    }
  std::vector<double> mean{1}, mean_se{0}, mean_dof{kNaN};
  std::vector<std::string> verdicts{"reference"};
  for (std::size_t j = 0; j + 1 < k; ++j) {
    mean.push_back(std::exp(cmp[j].mean_log_ratio)), mean_se.push_back(mean.back() * jack[j].se[0]);
    mean_dof.push_back(jack[j].dof[0]), verdicts.push_back(verdict_name(verdict[j]));
  }
  std::vector<std::string> names;
  for (std::size_t j = 0; j < k; ++j) names.push_back(y[j].name + " at " + x[j].name);
  Output out(c.output);
  if (out) {
    out->write("/at_equal/level", a.levels);
    out->write("/at_equal/crossing_time", t_at);
    out->write("/at_equal/y", y_at);
    out->write("/at_equal/y_stderr", y_se);
    out->write("/at_equal/ratio", ratio);
    out->write("/at_equal/ratio_stderr", ratio_se);
    out->write("/at_equal/mean_ratio", mean);
    out->write("/at_equal/mean_ratio_stderr", mean_se);
    out->write("/at_equal/mean_ratio_dof", mean_dof);
    out->attr("/at_equal", "inputs", names);
    out->attr("/at_equal", "verdicts", verdicts);
    out->attr("/at_equal", "method",
              std::string("rows j = input pair, columns = level of x: crossing_time = first crossing of the level by the ensemble "
                          "mean of x (linear in ln x - ln t), y = the ensemble mean of y there (linear in ln y - ln t), "
                          "ratio = y_j / y_0 at the same level, mean_ratio = exp of the mean of ln ratio over the levels"));
    out->attr("/at_equal", "verdict_rule",
              "against mean_ratio = 1: rejected if 1 lies outside the interval of ln mean_ratio +- t stderr (t: Student's "
              "quantile of mean_ratio_dof degrees of freedom at the coverage of a normal's " + fmt(a.sigmas) +
              " sigma), supported if the interval lies within 1 +- " + fmt(a.tolerance) + ", else undecided");
    out->attr("/at_equal", "errors",
              "jackknife over runs, both ensembles of each pair, a run's x and y left out together (dof: Welch-Satterthwaite)");
  }
  std::string line = "at-equal: " + std::to_string(k) + " ensembles against " + names[0] + " at x =";
  for (double l : a.levels) line += " " + fmt(l);
  line += ":";
  for (std::size_t j = 1; j < k; ++j) {
    line += " [" + std::to_string(j) + "] " + names[j] + ": y / y_0 =";
    for (std::size_t l = 0; l < K; ++l) line += " " + pm(ratio.data[j * K + l], ratio_se.data[j * K + l]);
    line += ", mean " + pm(mean[j], mean_se[j]) + ", = 1: " + verdicts[j] + ";";
  }
  out.finish(c.argv, files, line + " (" + fmt(a.sigmas) + " sigma, within " + fmt(a.tolerance) +
                                "); errors: jackknife over runs, intervals with Student's t");
  return 0;
}

}  // namespace gg::fit::cli
