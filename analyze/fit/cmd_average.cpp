// gg-fit average: mean and standard error over runs at each time, for time series and per-frame data.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "fit/ensemble.hpp"
#include "fit/subcommands.hpp"
#include "gg/errors.hpp"

namespace gg::fit::cli {
namespace {

// Scene values (docs/DESIGN.md: gg-sim writes them as attributes of /parameters) carried over when every
// run agrees on them, so that e.g. `haff` can predict t0 from an averaged energy.
const char* const kSceneKeys[] = {"dim", "N", "L", "rho", "e", "T0", "delta", "tc"};

}  // namespace

int run_average(const Common& c, const AverageArgs& a) {
  Files files;
  std::vector<RunData> runs;
  std::vector<std::string> names;
  std::vector<std::size_t> shape0;
  std::vector<double> axis_r, axis_edges;  // 2-D data: the second axis, if stored beside it
  std::vector<DatasetRef> refs;
  for (const std::string& arg : a.inputs) {
    DatasetRef ref = resolve(arg, a.dataset);
    const std::string name = label(ref);
    // One quantity of different runs: the same file twice would count one run twice (and shrink the
    // error), another dataset would mix quantities.
    for (const DatasetRef& before : refs) {
      if (ref.file != kStdinName && before.file != kStdinName && same_file(before.file, ref.file))
        throw UsageError(name + ": " + ref.file + " is given twice; an ensemble averages different runs");
      if (before.dataset != ref.dataset)
        throw UsageError(name + " and " + label(before) + " are different datasets; average one quantity over runs");
    }
    refs.push_back(ref);
    const H5Input& in = files.open(ref.file);
    Array v = in.read(ref.dataset);
    if (v.shape.empty() || v.shape.size() > 2)
      throw RuntimeError(name + ": rank " + std::to_string(v.shape.size()) +
                         "; average takes time series [T] or per-frame data [T][R]");
    RunData r;
    r.name = name;
    r.cols = v.shape.size() == 2 ? v.shape[1] : 1;
    r.values = v.data;
    r.t = read_time(in, ref.dataset, v.shape[0], name);
    // --from: the samples before it are left out (e.g. a mean cluster mass still undefined there).
    std::size_t first = 0;
    while (first < r.t.size() && r.t[first] < a.from) ++first;
    if (first == r.t.size())
      throw RuntimeError(name + " has no sample at or after --from " + fmt(a.from) + "; lower --from");
    r.t.erase(r.t.begin(), r.t.begin() + static_cast<long>(first));
    r.values.erase(r.values.begin(), r.values.begin() + static_cast<long>(first * r.cols));
    v.shape[0] -= first;
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
  // Runs of one scene: a dimension or a restitution that differs between two runs' /parameters is
  // another scene (the other scene values may differ on purpose, e.g. the seed's T0).
  for (const char* key : {"dim", "e"}) {
    std::optional<double> first;
    std::size_t first_at = 0;
    for (std::size_t k = 0; k < files.all().size(); ++k) {
      const auto x = param(*files.all()[k], key);
      if (x && first && *x != *first)
        throw RuntimeError(names[k] + " has " + key + " = " + fmt(*x) + " but " + names[first_at] + " has " + fmt(*first) +
                           " (/parameters); average the runs of each scene on their own");
      if (x && !first) first = x, first_at = k;
    }
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

}  // namespace gg::fit::cli
