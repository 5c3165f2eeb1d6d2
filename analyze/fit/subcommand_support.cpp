#include "fit/subcommand_support.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "gg/errors.hpp"

namespace gg::fit::cli {

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

std::string chi2_text(bool weighted, double chi2_dof) {
  return weighted ? "chi2/dof = " + fmt(chi2_dof) : "residual variance of ln y = " + fmt(chi2_dof);
}

std::string pm(double v, double e) { return fmt(v) + " +/- " + fmt(e); }

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

std::vector<Window> windows_per_input(const std::vector<double>& times, std::size_t inputs, const std::string& what) {
  if (times.size() % 2 || times.empty())
    throw UsageError(what + ": --window takes two times, T1 T2 (once for all inputs, or once per input in order)");
  std::vector<Window> w;
  for (std::size_t i = 0; i + 1 < times.size(); i += 2) w.push_back({times[i], times[i + 1]});
  if (w.size() == 1) w.assign(inputs, w.front());
  if (w.size() != inputs)
    throw UsageError(what + ": " + std::to_string(w.size()) + " windows for " + std::to_string(inputs) +
                     " inputs; give --window once (for all) or once per input");
  return w;
}

}  // namespace gg::fit::cli
