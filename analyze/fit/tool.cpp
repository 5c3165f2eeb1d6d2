// gg-fit: the command-line layer over the ggfit library. Each subcommand reads its inputs into
// plain Series / Ensemble structs, calls the library, prints one readable line on stderr and, with
// -o, writes its results (plus provenance) to an HDF5 file; stdout carries only data.
#include "fit/tool.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "fit/collapse.hpp"
#include "fit/ensemble.hpp"
#include "fit/haff.hpp"
#include "fit/onset.hpp"
#include "fit/power_law.hpp"
#include "fit/series.hpp"
#include "gg/cli.hpp"
#include "gg/dataset_ref.hpp"
#include "gg/errors.hpp"
#include "gg/h5file.hpp"
#include "gg/provenance.hpp"

namespace gg::fit {
namespace {

constexpr const char* kProgram = "gg-fit";
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// The jackknife's own variance has R - 1 degrees of freedom; below this many runs `--errors auto`
// keeps the covariance of the weighted fit instead.
constexpr std::size_t kJackknifeMinRuns = 5;
// CLI11 takes any argument that starts with '-' for an option, so "-:/average/mean" (a dataset on
// stdin) is rewritten to "<stdin>:/average/mean" before parsing; Files maps the name back to "-".
constexpr const char* kStdinName = "<stdin>";

// ------------------------------------------------------------------------------------------------
// Inputs

// Every file is opened once (stdin can only be read once), in the order first named.
class Files {
 public:
  const H5Input& open(const std::string& given) {
    const std::string path = given == kStdinName ? "-" : given;
    auto it = files_.find(path);
    if (it != files_.end()) return *it->second;
    auto& f = files_[path];
    f = std::make_unique<H5Input>(path);
    order_.push_back(f.get());
    return *f;
  }
  const std::vector<const H5Input*>& all() const { return order_; }

 private:
  std::map<std::string, std::unique_ptr<H5Input>> files_;
  std::vector<const H5Input*> order_;
};

// "file.h5:/g/ds", or a bare file name completed by `--dataset`.
DatasetRef resolve(const std::string& arg, const std::string& default_dataset) {
  if (arg.find(":/") == std::string::npos) {
    if (default_dataset.empty())
      throw UsageError("'" + arg + "' does not name a dataset; write FILE.h5:/group/dataset (or give --dataset)");
    if (default_dataset.front() != '/')
      throw UsageError("--dataset must be an absolute path inside the file, e.g. /cluster/mean_mass");
    return {arg, default_dataset};
  }
  return parse_dataset_ref(arg);
}

std::string label(const DatasetRef& r) { return (r.file == "-" ? std::string(kStdinName) : r.file) + ":" + r.dataset; }

std::string parent(const std::string& path) {
  const auto slash = path.find_last_of('/');
  return slash == 0 || slash == std::string::npos ? "" : path.substr(0, slash);
}

std::string basename(const std::string& path) { return path.substr(path.find_last_of('/') + 1); }

// A 1-D dataset with its time axis, its `stderr` sibling as error bars, and the per-run `samples`
// sibling (written by `gg-fit average`) when those average to the dataset.
struct Loaded {
  std::string name;
  const H5Input* file = nullptr;
  std::string dataset;
  Series series;
  std::optional<Ensemble> runs;
};

std::vector<double> read_time(const H5Input& in, const std::string& dataset, std::size_t n, const std::string& name) {
  const std::string tpath = paired_time(in, dataset);
  Array t = in.read(tpath, 1);
  if (t.data.size() != n)
    throw RuntimeError(name + ": " + std::to_string(n) + " samples but its time axis " + tpath + " has " +
                       std::to_string(t.data.size()) + "; the dataset and its time must have the same length");
  return t.data;
}

Loaded load_series(Files& files, const DatasetRef& ref) {
  Loaded L;
  L.name = label(ref);
  L.file = &files.open(ref.file);
  L.dataset = ref.dataset;
  const H5Input& in = *L.file;
  Array a = in.read(ref.dataset);
  if (a.shape.size() != 1 && !(a.shape.size() == 2 && a.shape[1] == 1))
    throw RuntimeError(L.name + ": a fit needs a 1-D time series, but the dataset has rank " +
                       std::to_string(a.shape.size()) + "; name one column, e.g. /cluster/mean_mass");
  L.series.y = a.data;
  L.series.t = read_time(in, ref.dataset, a.data.size(), L.name);
  const std::string group = parent(ref.dataset), leaf = basename(ref.dataset);
  const std::string err = group + "/stderr", samples = group + "/samples";
  if (leaf != "stderr" && leaf != "samples" && in.is_dataset(err)) {
    Array e = in.read(err);
    if (e.data.size() == a.data.size()) L.series.err = e.data;
  }
  if (leaf != "stderr" && leaf != "samples" && in.is_dataset(samples)) {
    Array s = in.read(samples);
    const std::size_t n = a.data.size();
    if (s.shape.size() == 2 && s.shape[1] == n && s.shape[0] >= 2) {
      Ensemble e;
      e.t = L.series.t;
      for (std::size_t r = 0; r < s.shape[0]; ++r)
        e.runs.emplace_back(s.data.begin() + static_cast<long>(r * n), s.data.begin() + static_cast<long>((r + 1) * n));
      bool matches = true;  // only the runs whose mean this dataset is
      for (std::size_t k = 0; k < n && matches; ++k) {
        double m = 0;
        for (const auto& run : e.runs) m += run[k];
        m /= static_cast<double>(e.runs.size());
        matches = std::abs(m - a.data[k]) <= 1e-9 * std::max(1.0, std::abs(a.data[k]));
      }
      if (matches) L.runs = std::move(e);
    }
  }
  check_series(L.series, L.name);
  return L;
}

// ------------------------------------------------------------------------------------------------
// Error bars: covariance of the fit, or jackknife over the runs behind an ensemble average.

enum class ErrorMode { automatic, covariance, jackknife };

ErrorMode error_mode(const std::string& name) {
  if (name == "covariance") return ErrorMode::covariance;
  if (name == "jackknife") return ErrorMode::jackknife;
  return ErrorMode::automatic;
}

bool use_jackknife(ErrorMode mode, const std::vector<const Loaded*>& in) {
  bool all = true;
  std::size_t fewest = std::numeric_limits<std::size_t>::max();
  for (const Loaded* l : in) {
    if (!l->runs) all = false;
    else fewest = std::min(fewest, l->runs->size());
  }
  if (mode == ErrorMode::jackknife) {
    if (!all)
      throw UsageError("--errors jackknife needs the per-run samples of an ensemble average: fit the mean "
                       "written by 'gg-fit average' (e.g. OUT.h5:/average/mean)");
    return true;
  }
  return mode == ErrorMode::automatic && all && fewest >= kJackknifeMinRuns;
}

std::string weights_text(const Series& s, std::size_t raised) {
  if (!s.weighted()) return "none (unweighted; error bars from the scatter of the residuals)";
  std::string t = "1/stderr^2 of the ensemble (relative variance smoothed over +-" + std::to_string(kSmooth) + " samples)";
  if (raised) t += ", " + std::to_string(raised) + " zero-stderr sample(s) given the smallest non-zero one";
  return t;
}

std::string errors_text(bool jack, ErrorMode mode, const Series& s, std::size_t runs) {
  if (jack) return "jackknife over " + std::to_string(runs) + " runs (includes correlations between times)";
  if (s.weighted()) {
    std::string t = "covariance of the weighted fit, scaled by max(1, chi2/dof)";
    if (mode == ErrorMode::automatic && runs)
      t += " (" + std::to_string(runs) + " runs: too few for the jackknife; ignores correlations between times)";
    else if (runs)
      t += " (ignores correlations between times)";
    return t;
  }
  return "covariance scaled by chi2/dof (residual scatter)";
}

// chi2/dof as printed: for an unweighted fit it is the residual variance of ln y, so say so.
std::string chi2_text(bool weighted, double chi2_dof) {
  return weighted ? "chi2/dof = " + fmt(chi2_dof) : "residual variance of ln y = " + fmt(chi2_dof);
}

std::string pm(double v, double e) { return fmt(v) + " +/- " + fmt(e); }

// ------------------------------------------------------------------------------------------------
// Output

class Output {
 public:
  explicit Output(const std::string& path) {
    if (!path.empty()) out_ = std::make_unique<H5Output>(path);
  }
  explicit operator bool() const { return static_cast<bool>(out_); }
  H5Output& operator*() { return *out_; }
  H5Output* operator->() { return out_.get(); }
  // Writes -o, then prints the result line: a failure writing -o is then the one line on stderr.
  void finish(const std::vector<std::string>& argv, const Files& files, const std::string& result_line) {
    if (out_) {
      write_provenance(*out_, Provenance{kProgram, argv, std::nullopt}, files.all());
      out_->commit();
    }
    std::cerr << kProgram << " " << result_line << '\n';
  }

 private:
  std::unique_ptr<H5Output> out_;
};

// What every fit of one series over a window writes beside its parameters: /fit/chi2_dof, /fit/window,
// and how the fit was made as attributes of /fit.
// An estimate and its standard error, as datasets `path` and `path`_stderr.
void write_estimate(H5Output& out, const std::string& path, double value, double stderr_) {
  out.write_scalar(path, value);
  out.write_scalar(path + "_stderr", stderr_);
}

void write_fit_quality(H5Output& out, const Loaded& in, const FitQuality& q, const Window& w, const std::string& method,
                       const std::string& model, const std::string& errors) {
  out.write_scalar("/fit/chi2_dof", q.chi2_dof);
  out.write("/fit/window", std::vector<double>{w.t1, w.t2});
  out.attr("/fit", "method", method);
  out.attr("/fit", "model", model);
  out.attr("/fit", "input", in.name);
  out.attr("/fit", "weights", weights_text(in.series, q.raised_errors));
  out.attr("/fit", "errors", errors);
  out.attr("/fit", "points", static_cast<std::int64_t>(q.points));
}

Window window_from(const std::vector<double>& w, const std::string& what) {
  if (w.size() != 2) throw UsageError(what + ": --window takes two times, T1 T2");
  return {w[0], w[1]};
}

// ------------------------------------------------------------------------------------------------
// Subcommands

struct Common {
  std::vector<std::string> argv;
  std::string output;
};

// average ----------------------------------------------------------------------------------------
struct AverageArgs {
  std::vector<std::string> inputs;
  std::string dataset;
  bool interpolate = false;
};

// Scene values (DESIGN.md: gg-sim writes them as attributes of /parameters) carried over when every
// run agrees on them, so that e.g. `haff` can predict t0 from an averaged energy.
const char* const kSceneKeys[] = {"dim", "N", "L", "rho", "e", "T0", "delta", "tc"};

std::optional<double> param(const H5Input& in, const std::string& name) {
  if (!in.exists("/parameters")) return std::nullopt;
  try {
    if (auto v = in.attr_double("/parameters", name)) return v;
  } catch (const RuntimeError&) {
    // stored as a string: parse it below
  }
  try {
    if (auto s = in.attr_string("/parameters", name)) {
      std::size_t used = 0;
      const double v = std::stod(*s, &used);
      if (used == s->size()) return v;
    }
  } catch (const std::exception&) {
  }
  return std::nullopt;
}

int run_average(const Common& c, const AverageArgs& a) {
  Files files;
  std::vector<RunData> runs;
  std::vector<std::string> names;
  std::vector<std::size_t> shape0;
  std::vector<double> axis_r, axis_edges;  // 2-D data: the second axis, if stored beside it
  for (const std::string& arg : a.inputs) {
    DatasetRef ref = resolve(arg, a.dataset);
    const H5Input& in = files.open(ref.file);
    Array v = in.read(ref.dataset);
    const std::string name = label(ref);
    if (v.shape.empty() || v.shape.size() > 2)
      throw RuntimeError(name + ": rank " + std::to_string(v.shape.size()) +
                         "; average takes time series [T] or per-frame data [T][R]");
    RunData r;
    r.name = name;
    r.cols = v.shape.size() == 2 ? v.shape[1] : 1;
    r.values = v.data;
    r.t = read_time(in, ref.dataset, v.shape[0], name);
    if (runs.empty()) shape0 = v.shape;
    else if (v.shape.size() != shape0.size())
      throw RuntimeError(name + " has rank " + std::to_string(v.shape.size()) + " but " + runs.front().name +
                         " has rank " + std::to_string(shape0.size()) + "; average the same dataset of every run");
    if (v.shape.size() == 2) {
      for (const char* axis : {"r", "bin_edges"}) {
        const std::string p = parent(ref.dataset) + "/" + axis;
        if (!in.is_dataset(p)) continue;
        auto& keep = std::string(axis) == "r" ? axis_r : axis_edges;
        std::vector<double> x = in.read(p, 1).data;
        if (runs.empty()) keep = x;
        else if (x != keep)
          throw RuntimeError(name + ": its " + axis + " differs from that of " + runs.front().name +
                             "; average runs analysed with the same --grid/--coarse and bins");
      }
    }
    runs.push_back(std::move(r));
    names.push_back(name);
  }
  Ensemble e = common_grid(runs, a.interpolate);
  Average m = average(e);
  const std::size_t T = m.t.size();

  Output out(c.output);
  if (out) {
    if (m.cols == 1) {
      out->write("/average/mean", m.mean);
      out->write("/average/stderr", m.err);
      Array samples{{e.size(), T}, {}};
      for (const auto& run : e.runs) samples.data.insert(samples.data.end(), run.begin(), run.end());
      out->write("/average/samples", samples);
    } else {
      out->write("/average/mean", Array{{T, m.cols}, m.mean});
      out->write("/average/stderr", Array{{T, m.cols}, m.err});
      if (!axis_r.empty()) out->write("/average/r", axis_r);
      if (!axis_edges.empty()) out->write("/average/bin_edges", axis_edges);
    }
    out->write("/average/time", m.t);
    out->write("/average/runs", std::vector<std::int64_t>(T, static_cast<std::int64_t>(m.runs)));
    out->attr("/average", "inputs", names);
    out->attr("/average", "method", std::string("mean and standard error of the mean (s/sqrt(R)) at each time") +
                                        (m.cols > 1 ? ", element by element within each frame" : ""));
    out->attr("/average", "interpolated",
              e.interpolated ? "yes: each run linear in ln t onto the first run's times inside the range all runs cover (" +
                                   std::to_string(e.dropped) + " of its samples outside it dropped)"
                             : std::string("no: the runs share their time grid"));
    // Scene values every run agrees on.
    for (const char* key : kSceneKeys) {
      std::optional<double> v;
      bool same = true;
      for (const H5Input* f : files.all()) {
        auto x = param(*f, key);
        if (!x || (v && *v != *x)) same = false;
        v = x;
      }
      if (same && v) out->attr("/parameters", key, *v);
    }
  }
  out.finish(c.argv, files, "average: " + std::to_string(m.runs) + " runs of " + (names.empty() ? "" : names.front().substr(names.front().rfind(":/") + 1)) +
      ", " + std::to_string(T) + " times" + (m.cols > 1 ? " x " + std::to_string(m.cols) + " columns (frame by frame)" : "") +
      (e.interpolated ? ", interpolated in ln t onto a common grid (" + std::to_string(e.dropped) + " samples dropped)" : ""));
  return 0;
}

// power-law --------------------------------------------------------------------------------------
struct PowerLawArgs {
  std::string input;
  std::vector<double> window;
  bool offset = false;
  std::string errors = "auto";
};

int run_power_law(const Common& c, const PowerLawArgs& a) {
  Files files;
  Loaded in = load_series(files, resolve(a.input, ""));
  const Window w = window_from(a.window, "power-law");
  PowerLawFit f = a.offset ? fit_power_law_offset(in.series, w) : fit_power_law(in.series, w);
  const bool jack = use_jackknife(error_mode(a.errors), {&in});
  if (jack) {
    auto se = jackknife_stderr({*in.runs}, [&](const std::vector<Series>& m) {
      if (a.offset) {
        PowerLawFit g = fit_power_law_offset(m[0], w);
        return std::vector<double>{g.exponent, g.amplitude, g.offset};
      }
      PowerLawFit g = fit_power_law(m[0], w);
      return std::vector<double>{g.exponent, std::log(g.amplitude)};
    });
    f.exponent_stderr = se[0];
    if (a.offset) {
      f.amplitude_stderr = se[1];
      f.log_amplitude_stderr = se[1] / std::abs(f.amplitude);
      f.offset_stderr = se[2];
    } else {
      f.log_amplitude_stderr = se[1];
      f.amplitude_stderr = f.amplitude * se[1];
    }
  }
  const std::string model = a.offset ? "y = y0 + A t^z" : "y = A t^z";
  const std::string method =
      a.offset ? "power-law with offset: nonlinear least squares of ln y = ln(y0 + A t^z) (GSL multifit_nlinear)"
               : "power-law: weighted least squares of ln y on ln t (GSL multifit_wlinear)";
  const std::string errors = errors_text(jack, error_mode(a.errors), in.series, in.runs ? in.runs->size() : 0);
  Output out(c.output);
  if (out) {
    write_estimate(*out, "/fit/exponent", f.exponent, f.exponent_stderr);
    write_estimate(*out, "/fit/amplitude", f.amplitude, f.amplitude_stderr);
    if (a.offset) {
      write_estimate(*out, "/fit/offset", f.offset, f.offset_stderr);
    }
    write_fit_quality(*out, in, f, w, method, model, errors);
    out->attr("/fit", "samples_used", std::vector<double>{f.t_first, f.t_last});
  }
  out.finish(c.argv, files, "power-law: " + in.name + ": " + model + " over t in " + fmt_window(w) + " (" + std::to_string(f.points) +
      " samples): z = " + pm(f.exponent, f.exponent_stderr) + ", A = " + pm(f.amplitude, f.amplitude_stderr) +
      (a.offset ? ", y0 = " + pm(f.offset, f.offset_stderr) : std::string()) + ", " + chi2_text(f.weighted, f.chi2_dof) +
      "; errors: " + errors);
  return 0;
}

// local-exponent ---------------------------------------------------------------------------------
struct LocalArgs {
  std::string input;
  double decades = 0.5;
  std::string errors = "auto";
};

int run_local_exponent(const Common& c, const LocalArgs& a) {
  Files files;
  Loaded in = load_series(files, resolve(a.input, ""));
  LocalExponent z = local_exponent(in.series, a.decades);
  const bool jack = use_jackknife(error_mode(a.errors), {&in});
  if (jack)
    z.err = jackknife_stderr({*in.runs}, [&](const std::vector<Series>& m) { return local_exponent(m[0], a.decades).exponent; });
  const std::string errors = jack ? errors_text(true, error_mode(a.errors), in.series, in.runs->size())
                                  : "covariance of each sliding fit (" + errors_text(false, error_mode(a.errors), in.series, in.runs ? in.runs->size() : 0) + ")";
  Output out(c.output);
  if (out) {
    out->write("/local_exponent/time", z.t);
    out->write("/local_exponent/exponent", z.exponent);
    out->write("/local_exponent/stderr", z.err);
    out->attr("/local_exponent", "method",
              "d ln y / d ln t from least squares of ln y on ln t over +-" + fmt(a.decades / 2) +
                  " decades around each time (only times whose whole window lies inside the data)");
    out->attr("/local_exponent", "input", in.name);
    out->attr("/local_exponent", "window_decades", a.decades);
    out->attr("/local_exponent", "errors", errors);
  }
  const auto [lo, hi] = std::minmax_element(z.exponent.begin(), z.exponent.end());
  out.finish(c.argv, files, "local-exponent: " + in.name + ": " + std::to_string(z.t.size()) + " times in [" + fmt(z.t.front()) + ", " +
      fmt(z.t.back()) + "], window " + fmt(a.decades) + " decades: z from " + fmt(*lo) + " to " + fmt(*hi) +
      ", last z(" + fmt(z.t.back()) + ") = " + pm(z.exponent.back(), z.err.back()) + "; errors: " + errors);
  return 0;
}

// onset ------------------------------------------------------------------------------------------
struct OnsetArgs {
  std::string input;
  OnsetCriterion criterion;
  double asymptote = kNaN;
  std::vector<double> window;
  std::string errors = "auto";
};

int run_onset(const Common& c, const OnsetArgs& a) {
  Files files;
  Loaded in = load_series(files, resolve(a.input, ""));
  double zinf = a.asymptote;
  std::string source = "given (--asymptote)";
  if (!a.window.empty()) {
    PowerLawFit f = fit_power_law(in.series, window_from(a.window, "onset"));
    zinf = f.exponent;
    source = "power-law fit over t in " + fmt_window(window_from(a.window, "onset")) + ": z = " +
             pm(f.exponent, f.exponent_stderr);
  }
  if (!std::isfinite(zinf)) throw UsageError("onset: give the asymptotic exponent, --asymptote Z or --window T1 T2 to fit it");
  const OnsetCriterion& cr = a.criterion;
  PlateauOnset p = plateau_onset(in.series, cr);
  const double ta = asymptote_onset(in.series, zinf, cr);
  double se_p = kNaN, se_a = kNaN;
  const bool jack = use_jackknife(error_mode(a.errors) == ErrorMode::covariance ? ErrorMode::automatic : error_mode(a.errors), {&in});
  if (jack) {
    auto se = jackknife_stderr({*in.runs}, [&](const std::vector<Series>& m) {
      return std::vector<double>{plateau_onset(m[0], cr).time, asymptote_onset(m[0], zinf, cr)};
    });
    se_p = se[0];
    se_a = se[1];
  }
  const std::string errors = jack ? errors_text(true, error_mode(a.errors), in.series, in.runs->size())
                                  : "none (a single series; with >= " + std::to_string(kJackknifeMinRuns) +
                                        " runs averaged by 'gg-fit average' the jackknife over runs gives them)";
  Output out(c.output);
  if (out) {
    out->write_scalar("/onset/plateau", p.plateau);
    write_estimate(*out, "/onset/plateau_time", p.time, se_p);
    out->write_scalar("/onset/asymptote", zinf);
    write_estimate(*out, "/onset/asymptote_time", ta, se_a);
    out->attr("/onset", "criterion_plateau", describe_plateau(cr));
    out->attr("/onset", "criterion_asymptote", describe_asymptote(cr, zinf));
    out->attr("/onset", "asymptote_source", source);
    out->attr("/onset", "input", in.name);
    out->attr("/onset", "errors", errors);
    out->attr("/onset", "note", std::string("NaN time: the criterion is never met in the data"));
  }
  auto when = [](double t, double e) { return std::isnan(t) ? std::string("never") : "t = " + (std::isnan(e) ? fmt(t) : pm(t, e)); };
  out.finish(c.argv, files, "onset: " + in.name + ": leaves the plateau " + fmt(p.plateau) + " at " + when(p.time, se_p) +
      "; local exponent within " + fmt(cr.exponent_tol) + " of " + fmt(zinf) + " from " + when(ta, se_a) + " [" +
      describe_plateau(cr) + "; " + describe_asymptote(cr, zinf) + "; asymptote " + source + "]");
  return 0;
}

// haff -------------------------------------------------------------------------------------------
struct HaffArgs {
  std::string input;
  std::vector<double> window;
  double rho = kNaN, e = kNaN, T0 = kNaN;
  int dim = 0;
  std::string contact = "henderson";
  std::string errors = "auto";
};

int run_haff(const Common& c, const HaffArgs& a) {
  Files files;
  Loaded in = load_series(files, resolve(a.input, ""));
  const H5Input& f = *in.file;
  std::vector<std::string> notes;
  // Flags override the file's /parameters (as flags override a scene).
  auto pick = [&](double flag, const char* key) -> std::optional<double> {
    if (std::isfinite(flag)) return flag;
    if (auto v = param(f, key)) {
      notes.push_back(std::string(key) + " from /parameters");
      return v;
    }
    return std::nullopt;
  };
  int dim = a.dim;
  if (!dim) {
    if (auto d = param(f, "dim")) {
      dim = static_cast<int>(*d);
      notes.push_back("dim from /parameters");
    } else if (f.exists("/particles/all/box")) {
      if (auto d = f.attr_double("/particles/all/box", "dimension")) {
        dim = static_cast<int>(*d);
        notes.push_back("dim from /particles/all/box");
      }
    }
  }
  if (!dim) {
    dim = 2;
    notes.push_back("dim not in the file: assumed 2 (--dim)");
  }
  std::optional<double> rho = pick(a.rho, "rho");
  if (!rho) {
    auto N = param(f, "N"), L = param(f, "L");
    if (N && L && *L > 0) {
      rho = *N / std::pow(*L, dim);
      notes.push_back("rho = N/L^d from /parameters");
    }
  }
  std::optional<double> e = pick(a.e, "e");
  std::optional<double> T0 = pick(a.T0, "T0");
  if (!T0) {
    T0 = 2 * in.series.y.front() / dim;
    notes.push_back("T0 = 2 E/d at the first sample (not in the file; --T0)");
  }
  const Contact contact = a.contact == "luding" ? Contact::luding : Contact::henderson;
  std::optional<HaffPrediction> pred;
  if (rho && e) pred = enskog_haff(dim, *rho, *e, *T0, contact);
  Window w;
  std::string window_note;
  if (!a.window.empty()) {
    w = window_from(a.window, "haff");
  } else if (pred) {
    // Early times only: by t = t0 clustering and the Sonine correction already move T by 4-15%
    // (PHYSICS.md), so the default window ends at half the predicted t0.
    w = {*std::min_element(in.series.t.begin(), in.series.t.end()), 0.5 * pred->t0};
    window_note = " (default: up to half the Enskog t0)";
  } else {
    throw UsageError("haff: no --window given and no rho and e found in " + f.path() +
                     " /parameters to predict t0 from; give --window T1 T2 (or --rho and --e)");
  }
  HaffFit h = fit_haff(in.series, w);
  const bool jack = use_jackknife(error_mode(a.errors), {&in});
  if (jack) {
    auto se = jackknife_stderr({*in.runs}, [&](const std::vector<Series>& m) {
      HaffFit g = fit_haff(m[0], w);
      return std::vector<double>{g.t0, g.E0};
    });
    h.t0_stderr = se[0];
    h.E0_stderr = se[1];
  }
  const std::string errors = errors_text(jack, error_mode(a.errors), in.series, in.runs ? in.runs->size() : 0);
  std::string sources;
  for (const auto& n : notes) sources += (sources.empty() ? "" : "; ") + n;
  Output out(c.output);
  if (out) {
    write_estimate(*out, "/fit/E0", h.E0, h.E0_stderr);
    write_estimate(*out, "/fit/t0", h.t0, h.t0_stderr);
    write_fit_quality(*out, in, h, w,
                      "haff: nonlinear least squares of ln E = ln E0 - 2 ln(1 + t/t0) (GSL multifit_nlinear)",
                      "E(t) = E0 / (1 + t/t0)^2", errors);
    out->attr("/fit", "parameter_sources", sources);
    if (pred) {
      out->write_scalar("/fit/t0_enskog", pred->t0);
      write_estimate(*out, "/fit/t0_ratio", h.t0 / pred->t0, h.t0_stderr / pred->t0);
      out->write_scalar("/fit/E0_expected", pred->E0);
      out->attr("/fit", "enskog", std::string("t0 = 2d/((1 - e^2) omega0), omega0 = 2 pi^((d-1)/2)/Gamma(d/2) rho g sqrt(T0)"));
      out->attr("/fit", "contact_value", pred->g_name);
      out->attr("/fit", "dim", static_cast<std::int64_t>(pred->dim));
      out->attr("/fit", "rho", pred->rho);
      out->attr("/fit", "e", pred->e);
      out->attr("/fit", "T0", pred->T0);
      out->attr("/fit", "phi", pred->phi);
      out->attr("/fit", "g", pred->g);
      out->attr("/fit", "omega0", pred->omega0);
    }
  }
  std::string line = "haff: " + in.name + ": E = E0/(1+t/t0)^2 over t in " + fmt_window(w) + window_note + " (" +
                     std::to_string(h.points) + " samples): t0 = " + pm(h.t0, h.t0_stderr) + ", E0 = " +
                     pm(h.E0, h.E0_stderr) + ", " + chi2_text(h.weighted, h.chi2_dof);
  if (pred)
    line += "; Enskog t0 = " + fmt(pred->t0) + " (d = " + std::to_string(dim) + ", rho = " + fmt(pred->rho) +
            ", e = " + fmt(pred->e) + ", T0 = " + fmt(pred->T0) + ", " + pred->g_name + " = " + fmt(pred->g) +
            ", omega0 = " + fmt(pred->omega0) + "), fit/Enskog = " + pm(h.t0 / pred->t0, h.t0_stderr / pred->t0);
  else
    line += "; no Enskog prediction (give --rho and --e)";
  line += "; errors: " + errors + (sources.empty() ? "" : "; " + sources);
  out.finish(c.argv, files, line);
  return 0;
}

// collapse ---------------------------------------------------------------------------------------
struct CollapseArgs {
  std::vector<std::string> inputs;
  std::vector<double> windows;  // pairs
  double sigmas = 2;
  std::string errors = "auto";
};

int run_collapse(const Common& c, const CollapseArgs& a) {
  Files files;
  std::vector<Loaded> in;
  for (const auto& arg : a.inputs) in.push_back(load_series(files, resolve(arg, "")));
  const std::size_t k = in.size();
  if (a.windows.size() % 2 || a.windows.empty())
    throw UsageError("collapse: --window takes two times, T1 T2 (once for all inputs, or once per input in order)");
  std::vector<Window> w;
  for (std::size_t i = 0; i + 1 < a.windows.size(); i += 2) w.push_back({a.windows[i], a.windows[i + 1]});
  if (w.size() == 1) w.assign(k, w.front());
  if (w.size() != k)
    throw UsageError("collapse: " + std::to_string(w.size()) + " windows for " + std::to_string(k) +
                     " inputs; give --window once (for all) or once per input");
  std::vector<Series> s;
  std::vector<const Loaded*> ptrs;
  for (const auto& l : in) {
    s.push_back(l.series);
    ptrs.push_back(&l);
  }
  CollapseFit f = fit_collapse(s, w, a.sigmas);
  const bool jack = use_jackknife(error_mode(a.errors), ptrs);
  std::size_t fewest = 0;
  if (jack) {
    std::vector<Ensemble> groups;
    for (const auto& l : in) groups.push_back(*l.runs);
    set_collapse_errors(f, jackknife_stderr(groups, [&](const std::vector<Series>& m) {
                          return collapse_parameters(fit_collapse(m, w, a.sigmas));
                        }));
    fewest = groups.front().size();
    for (const auto& g : groups) fewest = std::min(fewest, g.size());
  }
  const std::string errors = jack ? "jackknife over runs, every ensemble (fewest " + std::to_string(fewest) + " runs)"
                                  : errors_text(false, error_mode(a.errors), s.front(), in.front().runs ? in.front().runs->size() : 0);
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
    out->attr("/fit", "agreement", "agree[j] = 1 if |ln(A_j/A_0)| <= " + fmt(a.sigmas) + " stderr of ln(A_j/A_0)");
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

// table ------------------------------------------------------------------------------------------
struct TableArgs {
  std::vector<std::string> inputs;
  bool header = true;
};

std::string num(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.10g", x);
  return buf;
}

struct Column {
  std::string name;
  Array data;
  std::vector<double> time;  // empty: no time axis
  std::vector<double> axis;  // 2-D data: the second axis (sibling `r`, or centres of `bin_edges`)
  std::string axis_name = "index";
};

// The groups and datasets of a file that hold data, depth first: not /parameters and /h5md (metadata).
std::vector<std::string> data_objects(const H5Input& in) {
  auto under = [](const std::string& p, const std::string& group) { return (p + "/").rfind(group + "/", 0) == 0; };
  std::vector<std::string> out;
  for (const auto& p : in.objects_below("/"))
    if (!under(p, "/parameters") && !under(p, "/h5md")) out.push_back(p);
  return out;
}

// Groups with a `time` dataset, depth first (the data of every analysis tool and H5MD observable).
std::vector<std::string> time_groups(const H5Input& in) {
  std::vector<std::string> out;
  if (in.is_dataset("/time")) out.push_back("/");
  for (const auto& p : data_objects(in))
    if (!in.is_dataset(p) && in.is_dataset(p + "/time")) out.push_back(p);
  return out;
}

// Datasets of rank 0 and 1 (fit results), depth first.
void untimed_datasets(const H5Input& in, std::vector<std::string>& scalars,
                      std::map<std::size_t, std::vector<std::string>>& vectors) {
  for (const auto& p : data_objects(in)) {
    if (!in.is_dataset(p)) continue;
    const auto shape = in.shape(p);
    if (shape.empty()) scalars.push_back(p);
    else if (shape.size() == 1 && basename(p) != "window") vectors[shape[0]].push_back(p);
  }
}

void print_block(const std::vector<Column>& cols, bool header, const std::string& title) {
  // All scalars: one row. All 1-D of one length: a column each (time first if they share one).
  // One 2-D [T][R]: gnuplot blocks, "time x value" rows, a blank line between times.
  bool scalars = true;
  for (const auto& c : cols) scalars = scalars && c.data.shape.empty();
  std::ostringstream o;
  if (!title.empty() && header) o << "# " << title << '\n';
  if (scalars) {
    if (header) {
      o << '#';
      for (std::size_t i = 0; i < cols.size(); ++i) o << (i ? "\t" : " ") << cols[i].name;
      o << '\n';
    }
    for (std::size_t i = 0; i < cols.size(); ++i) o << (i ? "\t" : "") << num(cols[i].data.data[0]);
    o << '\n';
    std::cout << o.str();
    return;
  }
  if (cols.size() == 1 && cols[0].data.shape.size() == 2) {
    const Column& c = cols[0];
    const std::size_t T = c.data.shape[0], R = c.data.shape[1];
    if (header) o << "# time\t" << c.axis_name << '\t' << c.name << '\n';
    for (std::size_t k = 0; k < T; ++k) {
      if (k) o << '\n';
      for (std::size_t r = 0; r < R; ++r)
        o << (c.time.empty() ? num(static_cast<double>(k)) : num(c.time[k])) << '\t'
          << (c.axis.size() == R ? num(c.axis[r]) : std::to_string(r)) << '\t' << num(c.data.data[k * R + r]) << '\n';
    }
    std::cout << o.str();
    return;
  }
  const std::size_t n = cols[0].data.data.size();
  for (const auto& c : cols) {
    if (c.data.shape.size() != 1)
      throw RuntimeError("table: " + c.name + " has rank " + std::to_string(c.data.shape.size()) +
                         "; print scalars together, 1-D datasets together, or one 2-D dataset alone");
    if (c.data.data.size() != n)
      throw RuntimeError("table: " + c.name + " has " + std::to_string(c.data.data.size()) + " rows but " + cols[0].name +
                         " has " + std::to_string(n) + "; print datasets of the same length together");
  }
  bool with_time = !cols[0].time.empty();
  for (const auto& c : cols) {
    if (c.time.empty()) with_time = false;
    else if (with_time)
      for (std::size_t k = 0; k < n; ++k)
        if (std::abs(c.time[k] - cols[0].time[k]) > 1e-9 * std::max(1.0, std::abs(c.time[k])))
          throw RuntimeError("table: " + c.name + " and " + cols[0].name +
                             " are on different time grids; print them separately (or 'gg-fit average --interpolate')");
  }
  // A dataset that is itself the time axis is not repeated.
  if (header) {
    o << '#';
    bool first = true;
    if (with_time) {
      o << " time";
      first = false;
    }
    for (const auto& c : cols) {
      o << (first ? " " : "\t") << c.name;
      first = false;
    }
    o << '\n';
  }
  for (std::size_t k = 0; k < n; ++k) {
    bool first = true;
    if (with_time) {
      o << num(cols[0].time[k]);
      first = false;
    }
    for (const auto& c : cols) {
      o << (first ? "" : "\t") << num(c.data.data[k]);
      first = false;
    }
    o << '\n';
  }
  std::cout << o.str();
}

Column read_column(const H5Input& in, const std::string& file, const std::string& dataset) {
  Column c;
  c.name = (file == "-" ? std::string("<stdin>") : file) + ":" + dataset;
  c.data = in.read(dataset);
  if (!c.data.shape.empty() && basename(dataset) != "time") {
    try {
      const std::string tp = paired_time(in, dataset);
      Array t = in.read(tp, 1);
      if (t.data.size() == c.data.shape[0]) c.time = t.data;
    } catch (const RuntimeError&) {
      // no time axis: printed without one
    }
  }
  if (c.data.shape.size() == 2) {
    const std::size_t R = c.data.shape[1];
    const std::string g = parent(dataset);
    if (in.is_dataset(g + "/r") && in.shape(g + "/r") == std::vector<std::size_t>{R}) {
      c.axis = in.read(g + "/r").data;
      c.axis_name = "r";
    } else if (in.is_dataset(g + "/bin_edges") && in.shape(g + "/bin_edges") == std::vector<std::size_t>{R + 1}) {
      const auto e = in.read(g + "/bin_edges").data;
      for (std::size_t i = 0; i < R; ++i) c.axis.push_back(0.5 * (e[i] + e[i + 1]));
      c.axis_name = "bin_centre";
    }
  }
  return c;
}

int run_table(const TableArgs& a) {
  Files files;
  std::vector<Column> cols;
  bool blocks_printed = false;
  for (const auto& arg : a.inputs) {
    if (arg.find(":/") != std::string::npos) {
      DatasetRef ref = parse_dataset_ref(arg);
      cols.push_back(read_column(files.open(ref.file), ref.file, ref.dataset));
      continue;
    }
    // A whole file: every group with a time axis, one gnuplot `index` block each.
    const H5Input& in = files.open(arg);
    const std::vector<std::string> groups = time_groups(in);
    if (groups.empty()) {
      // No time axis anywhere (e.g. a fit's output): its scalars as one row, then its 1-D datasets
      // (e.g. one amplitude per ensemble) as columns, one block per length.
      std::vector<std::string> scalars;
      std::map<std::size_t, std::vector<std::string>> vectors;
      untimed_datasets(in, scalars, vectors);
      if (scalars.empty() && vectors.empty())
        throw RuntimeError("table: " + in.path() + " has neither a group with a 'time' dataset nor scalar or 1-D "
                           "datasets; name datasets as FILE.h5:/group/dataset");
      std::vector<std::vector<std::string>> blocks;
      if (!scalars.empty()) blocks.push_back(scalars);
      for (const auto& [n, v] : vectors) blocks.push_back(v);
      for (const auto& b : blocks) {
        std::vector<Column> block;
        for (const auto& p : b) block.push_back(read_column(in, arg, p));
        if (blocks_printed) std::cout << "\n\n";
        print_block(block, a.header, "");
        blocks_printed = true;
      }
      continue;
    }
    for (const auto& g : groups) {
      std::vector<Column> block;
      const auto n = in.shape(g + "/time");
      for (const auto& m : in.members(g)) {
        const std::string p = g + "/" + m;
        if (m == "time" || !in.is_dataset(p)) continue;
        const auto shp = in.shape(p);
        if (shp.size() == 1 && !n.empty() && shp[0] == n[0]) block.push_back(read_column(in, arg, p));
      }
      if (block.empty()) continue;
      if (blocks_printed) std::cout << "\n\n";
      print_block(block, a.header, g);
      blocks_printed = true;
    }
  }
  if (!cols.empty()) {
    if (blocks_printed) std::cout << "\n\n";
    print_block(cols, a.header, "");
  }
  std::cout.flush();
  if (!std::cout) throw RuntimeError("table: writing to stdout failed");
  return 0;
}

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

// What every fit subcommand takes last: --errors and an optional -o.
void add_errors_and_output(CLI::App* sub, std::string& mode, std::string& output) {
  sub->add_option("--errors", mode,
                  "Error bars: 'covariance' of the fit (weighted by the ensemble stderr and scaled by max(1, chi2/dof); "
                  "unweighted: scaled by chi2/dof), 'jackknife' over the runs behind an ensemble average (needs the "
                  "/average/samples written by 'gg-fit average'; includes correlations between times), or 'auto' = "
                  "jackknife when >= " + std::to_string(kJackknifeMinRuns) + " runs are available, else covariance")
      ->check(CLI::IsMember({"auto", "covariance", "jackknife"}))
      ->capture_default_str();
  sub->add_option("-o,--output", output, "Output HDF5 file, '-' = stdout (default: none, only the printed line)");
}

}  // namespace

int gg_fit_main(int argc, char** argv) {
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
    auto* o_as = s_on->add_option("--asymptote", on.asymptote, "Asymptotic exponent (e.g. 0.6)");
    auto* o_win = add_window(s_on, on.window, "Or fit the asymptotic exponent over this window");
    o_as->excludes(o_win);
    add_errors_and_output(s_on, on.errors, common.output);

    HaffArgs hf;
    auto* s_hf = app.add_subcommand(
        "haff", "Fit E(t) = E0/(1+t/t0)^2 over an early window and compare t0 with Enskog: t0 = 4/((1-e^2) omega0), "
                "omega0 = 2 sqrt(pi) rho g sqrt(T0) in 2D (1D: t0 = 2/((1-e^2) omega0), omega0 = (2/sqrt(pi)) rho g "
                "sqrt(T0), g = 1/(1-rho)). rho, e, T0, dim come from the input's /parameters unless given as flags");
    s_hf->add_option("input", hf.input, "FILE.h5:/group/dataset, e.g. sim.h5:/observables/kinetic_energy/value")->required();
    add_window(s_hf, hf.window, "Fit window (default: from the first sample to half the Enskog t0)");
    s_hf->add_option("--rho", hf.rho, "Number density (default: /parameters rho, or N/L^d)");
    s_hf->add_option("--e", hf.e, "Coefficient of restitution (default: /parameters e)");
    s_hf->add_option("--T0", hf.T0, "Initial temperature (default: /parameters T0, else 2 E/d at the first sample)");
    s_hf->add_option("--dim", hf.dim, "Dimension 1 or 2 (default: /parameters dim, else the H5MD box, else 2)")
        ->check(CLI::IsMember({1, 2}));
    s_hf->add_option("--contact", hf.contact,
                     "2D pair correlation at contact: henderson = (1 - 7 phi/16)/(1 - phi)^2, luding = henderson - "
                     "phi^3/(128 (1 - phi)^4); phi = pi rho/4")
        ->check(CLI::IsMember({"henderson", "luding"}))
        ->capture_default_str();
    add_errors_and_output(s_hf, hf.errors, common.output);

    CollapseArgs co;
    auto* s_co = app.add_subcommand("collapse", "Several ensembles (e.g. one per e): one common exponent, one amplitude "
                                                "each (ln y_j = ln A_j + z ln t), amplitude ratios A_j/A_0 with errors "
                                                "and whether they agree within --sigmas");
    s_co->add_option("inputs", co.inputs, "FILE.h5:/group/dataset, one per ensemble (first = reference)")->required();
    add_window(s_co, co.windows, "Fit window: once for all inputs, or once per input in order")->required();
    s_co->add_option("--sigmas", co.sigmas, "Amplitudes agree when |ln(A_j/A_0)| <= this many standard errors")
        ->capture_default_str();
    add_errors_and_output(s_co, co.errors, common.output);

    TableArgs tb;
    bool no_header = false;
    auto* s_tb = app.add_subcommand("table", "Datasets as a tab-separated table on stdout (time first when they share "
                                             "one). A bare FILE.h5 or '-' prints every group with a time axis as its own "
                                             "block (gnuplot 'index'); a 2-D [T][R] dataset prints 'time index value' "
                                             "rows, a blank line between times; scalars print as one row");
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
    if (s_av->parsed()) return run_average(common, av);
    if (s_pl->parsed()) return run_power_law(common, pl);
    if (s_le->parsed()) return run_local_exponent(common, le);
    if (s_on->parsed()) return run_onset(common, on);
    if (s_hf->parsed()) return run_haff(common, hf);
    if (s_co->parsed()) return run_collapse(common, co);
    if (s_tb->parsed()) {
      tb.header = !no_header;
      return run_table(tb);
    }
    return kExitUsage;
  });
}

}  // namespace gg::fit
