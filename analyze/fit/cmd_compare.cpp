// gg-fit compare: whether estimates written by other subcommands (each with its _stderr and _dof
// siblings, e.g. late-exponent's /late/exponent) agree with the first, by Welch's test.
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "fit/ensemble.hpp"
#include "fit/subcommands.hpp"
#include "gg/errors.hpp"

namespace gg::fit::cli {

namespace {

// The scalar at `path`, or RuntimeError naming what is missing and where it comes from.
double scalar(const H5Input& in, const std::string& path, const std::string& name) {
  if (!in.exists(path))
    throw RuntimeError("compare: " + name + " has no " + path + "; give an estimate with its _stderr and _dof siblings "
                       "(e.g. gg-fit late-exponent's /late/exponent)");
  const Array a = in.read(path);
  if (a.data.size() != 1) throw RuntimeError("compare: " + name + ":" + path + " is not a scalar");
  return a.data[0];
}

}  // namespace

int run_compare(const Common& c, const CompareArgs& a) {
  if (a.inputs.size() < 2) throw UsageError("compare: give the reference estimate and at least one other");
  Files files;
  std::vector<Estimate> e;
  std::vector<std::string> names;
  for (const auto& arg : a.inputs) {
    const DatasetRef r = resolve(arg, "");
    const H5Input& in = files.open(r.file);
    names.push_back(label(r));
    e.push_back({scalar(in, r.dataset, r.file), scalar(in, r.dataset + "_stderr", r.file), scalar(in, r.dataset + "_dof", r.file)});
  }
  std::vector<double> diff{0}, diff_se{0}, diff_dof{kNaN};
  std::vector<std::int64_t> agree{1};
  std::string line = "compare: against " + names[0] + " = " + pm(e[0].value, e[0].se) + ":";
  bool all = true;
  for (std::size_t j = 1; j < e.size(); ++j) {
    const Estimate d = difference(e[j], e[0]);
    // 1 agrees, 0 differs, -1 undetermined (an estimate or its error not finite).
    const int ok = !std::isfinite(d.value) || !std::isfinite(d.se) ? -1 : within(d, 0, a.sigmas) ? 1 : 0;
    diff.push_back(d.value), diff_se.push_back(d.se), diff_dof.push_back(d.dof), agree.push_back(ok);
    all = all && ok == 1;
    line += " [" + std::to_string(j) + "] " + names[j] + " = " + pm(e[j].value, e[j].se) + ", difference " + pm(d.value, d.se) +
            " (" + fmt(d.dof) + " dof): " + (ok == 1 ? "agrees" : ok == 0 ? "differs" : "undetermined") + ";";
  }
  Output out(c.output);
  if (out) {
    out->write("/compare/difference", diff);
    out->write("/compare/difference_stderr", diff_se);
    out->write("/compare/difference_dof", diff_dof);
    out->write("/compare/agree", agree);
    out->attr("/compare", "inputs", names);
    out->attr("/compare", "method",
              std::string("difference[j] = x_j - x_0, stderr in quadrature, dof by Welch-Satterthwaite from each "
                          "estimate's _dof (Welch 1947)"));
    out->attr("/compare", "verdict",
              "agree[j] = 1 if |difference| <= t stderr, t Student's quantile of difference_dof at the coverage of a "
              "normal's " + fmt(a.sigmas) + " sigma, 0 if not, -1 if the difference or its error is not finite");
  }
  out.finish(c.argv, files, line + " all agree within " + fmt(a.sigmas) + " sigma (Student's t): " + (all ? "yes" : "no"));
  return 0;
}

}  // namespace gg::fit::cli
