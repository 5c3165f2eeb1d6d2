// gg-fit extrapolate: a quantity measured at several box sizes (one input per L), extrapolated to
// L -> infinity in 1/L, with the equality verdict at the largest L and in the limit.
#include <algorithm>
#include <cmath>
#include <limits>
#include <cstdint>
#include <string>
#include <vector>

#include "fit/extrapolate.hpp"
#include "fit/subcommands.hpp"
#include "gg/errors.hpp"

namespace gg::fit::cli {

namespace {

// Values of one input (a scalar or a 1-D dataset), of its `<name>_stderr` sibling, and of its
// `<name>_dof` sibling if there (the degrees of freedom of a jackknife's errors; else infinite).
struct Measured {
  std::string name;
  std::vector<double> value, err, dof;
};

Measured read_measured(Files& files, const DatasetRef& ref) {
  const H5Input& in = files.open(ref.file);
  Measured m;
  m.name = label(ref);
  const Array v = in.read(ref.dataset);
  if (v.shape.size() > 1) throw RuntimeError(m.name + " has rank " + std::to_string(v.shape.size()) +
                                             "; extrapolate takes a scalar or a 1-D dataset");
  const std::string err_name = ref.dataset + "_stderr";
  if (!in.exists(err_name))
    throw RuntimeError(m.name + " has no error bars: " + ref.file + " holds no " + err_name +
                       " (extrapolate weights each size by its standard error)");
  const Array e = in.read(err_name);
  if (e.data.size() != v.data.size())
    throw RuntimeError(ref.file + ":" + err_name + " holds " + std::to_string(e.data.size()) + " values for the " +
                       std::to_string(v.data.size()) + " of " + m.name);
  m.value = v.data;
  m.err = e.data;
  m.dof.assign(v.data.size(), std::numeric_limits<double>::infinity());
  if (in.exists(ref.dataset + "_dof")) {
    const Array d = in.read(ref.dataset + "_dof");
    if (d.data.size() != v.data.size())
      throw RuntimeError(ref.file + ":" + ref.dataset + "_dof holds " + std::to_string(d.data.size()) + " values for the " +
                         std::to_string(v.data.size()) + " of " + m.name);
    m.dof = d.data;
  }
  return m;
}

std::int64_t verdict_code(Verdict v) { return v == Verdict::supported ? 1 : v == Verdict::rejected ? -1 : 0; }

}  // namespace

int run_extrapolate(const Common& c, const ExtrapolateArgs& a) {
  if (a.inputs.size() != a.L.size())
    throw UsageError("extrapolate: " + std::to_string(a.inputs.size()) + " inputs for " + std::to_string(a.L.size()) +
                     " values of --L; give one box size per input, in the same order");
  for (std::size_t i = 1; i < a.L.size(); ++i)
    if (!(a.L[i] > a.L[i - 1])) throw UsageError("extrapolate: --L must increase (got " + fmt(a.L[i - 1]) + " then " + fmt(a.L[i]) + ")");
  if (!(a.tolerance > 0)) throw UsageError("extrapolate: --tolerance must be > 0 (a relative band, e.g. 0.1)");
  if (!(a.sigmas > 0)) throw UsageError("extrapolate: --sigmas must be > 0");
  Files files;
  std::vector<Measured> in;
  for (const auto& arg : a.inputs) in.push_back(read_measured(files, resolve(arg, "")));
  const std::size_t n = in.size(), k = in.front().value.size();
  for (const auto& m : in)
    if (m.value.size() != k)
      throw RuntimeError("extrapolate: " + m.name + " holds " + std::to_string(m.value.size()) + " values, " +
                         in.front().name + " " + std::to_string(k) + "; every size must measure the same quantities");

  // Per component j: the reference (value == expected, error 0 at every size, e.g. A_0/A_0) is
  // reported but not judged; the others get the value at the largest L where they are defined, the
  // limit L -> infinity when two or more sizes define them, and a verdict for each.
  std::vector<double> largest_L(k, kNaN), at_largest(k, kNaN), at_largest_err(k, kNaN);
  std::vector<double> limit(k, kNaN), limit_err(k, kNaN), slope(k, kNaN), slope_err(k, kNaN), chi2(k, kNaN);
  std::vector<std::int64_t> v_largest(k, 0), v_limit(k, 0), judged(k, 0);
  std::vector<Verdict> all_largest, all_limit;
  std::string line = "extrapolate: " + std::to_string(n) + " sizes L = ";
  for (std::size_t i = 0; i < n; ++i) line += (i ? ", " : "") + fmt(a.L[i]);
  line += ";";
  for (std::size_t j = 0; j < k; ++j) {
    std::vector<double> y(n), s(n), dof(n);
    bool reference = true;
    for (std::size_t i = 0; i < n; ++i) {
      y[i] = in[i].value[j];
      s[i] = in[i].err[j];
      dof[i] = in[i].dof[j];
      reference = reference && y[i] == a.expected && s[i] == 0;
    }
    if (reference) {
      line += " [" + std::to_string(j) + "] reference;";
      continue;
    }
    judged[j] = 1;
    double largest_dof = kNaN;
    for (std::size_t i = n; i-- > 0;)
      if (std::isfinite(y[i]) && std::isfinite(s[i]) && s[i] > 0) {
        largest_L[j] = a.L[i];
        at_largest[j] = y[i];
        at_largest_err[j] = s[i];
        largest_dof = dof[i];
        break;
      }
    const Verdict vl = equality_verdict(at_largest[j], at_largest_err[j], a.expected, a.sigmas, a.tolerance, largest_dof);
    v_largest[j] = verdict_code(vl);
    all_largest.push_back(vl);
    line += " [" + std::to_string(j) + "] at L = " + fmt(largest_L[j]) + ": " + pm(at_largest[j], at_largest_err[j]) +
            " (" + verdict_name(vl) + ")";
    // The limit combines the sizes: its interval takes the fewest degrees of freedom among them.
    std::size_t usable = 0;
    double fewest_dof = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < n; ++i)
      if (std::isfinite(y[i]) && std::isfinite(s[i]) && s[i] > 0) ++usable, fewest_dof = std::min(fewest_dof, dof[i]);
    if (usable >= 2) {
      const SizeExtrapolation x = extrapolate_in_inverse_size(a.L, y, s);
      limit[j] = x.limit;
      limit_err[j] = x.limit_stderr;
      slope[j] = x.slope;
      slope_err[j] = x.slope_stderr;
      chi2[j] = x.chi2_dof;
      const Verdict vi = equality_verdict(x.limit, x.limit_stderr, a.expected, a.sigmas, a.tolerance, fewest_dof);
      v_limit[j] = verdict_code(vi);
      all_limit.push_back(vi);
      line += ", L -> inf: " + pm(x.limit, x.limit_stderr) + " (" + verdict_name(vi) + ", " +
              std::to_string(usable) + " sizes)";
    } else {
      all_limit.push_back(Verdict::undecided);
      line += ", L -> inf: n/a (fewer than two sizes)";
    }
    line += ";";
  }
  const Verdict overall_largest = combined_verdict(all_largest), overall_limit = combined_verdict(all_limit);
  line += " value = " + fmt(a.expected) + " at " + fmt(a.sigmas) + " sigma within " + fmt(100 * a.tolerance) +
          "%: " + verdict_name(overall_largest) + " at the largest L, " + verdict_name(overall_limit) + " for L -> inf";

  Output out(c.output);
  if (out) {
    out->write("/extrapolate/L", a.L);
    Array vals{{n, k}, {}}, errs{{n, k}, {}};
    for (const auto& m : in) {
      vals.data.insert(vals.data.end(), m.value.begin(), m.value.end());
      errs.data.insert(errs.data.end(), m.err.begin(), m.err.end());
    }
    out->write("/extrapolate/value", vals);
    out->write("/extrapolate/value_stderr", errs);
    out->write("/extrapolate/judged", judged);
    out->write("/extrapolate/largest_L", largest_L);
    out->write("/extrapolate/at_largest", at_largest);
    out->write("/extrapolate/at_largest_stderr", at_largest_err);
    out->write("/extrapolate/limit", limit);
    out->write("/extrapolate/limit_stderr", limit_err);
    out->write("/extrapolate/slope", slope);
    out->write("/extrapolate/slope_stderr", slope_err);
    out->write("/extrapolate/chi2_dof", chi2);
    out->write("/extrapolate/verdict_largest", v_largest);
    out->write("/extrapolate/verdict_limit", v_limit);
    out->attr("/extrapolate", "model", std::string("y(L) = limit + slope / L, weighted least squares in 1/L"));
    out->attr("/extrapolate", "verdict_codes", std::string("1 supported, -1 rejected, 0 undecided"));
    out->attr("/extrapolate", "rule",
              "rejected if " + fmt(a.expected) + " lies outside value +- t stderr (t: Student's quantile, at the "
                  "coverage of a normal's " + fmt(a.sigmas) + " sigma, of the inputs' _dof where given, the fewest "
                  "among the sizes for the limit; the normal's without); supported if that whole interval lies within " +
                  fmt(a.expected) + " x (1 +- " + fmt(a.tolerance) + "); else undecided");
    out->attr("/extrapolate", "verdict_at_largest_L", verdict_name(overall_largest));
    out->attr("/extrapolate", "verdict_limit", verdict_name(overall_limit));
    std::vector<std::string> names;
    for (const auto& m : in) names.push_back(m.name);
    out->attr("/extrapolate", "inputs", names);
  }
  out.finish(c.argv, files, line);
  return 0;
}

}  // namespace gg::fit::cli
