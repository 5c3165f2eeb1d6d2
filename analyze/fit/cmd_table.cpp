// gg-fit table: datasets as tab-separated text on stdout, in blocks gnuplot reads with `index`.
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "fit/subcommands.hpp"
#include "gg/dataset_ref.hpp"
#include "gg/errors.hpp"
#include "gg/h5file.hpp"

namespace gg::fit::cli {
namespace {

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
  const char* axis_name = "index";  // or "r", "bin_centre"
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
  c.name = label(DatasetRef{file, dataset});
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

}  // namespace

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
  if (!std::cout) throw RuntimeError(std::string("table: writing to stdout failed (") + std::strerror(errno) +
                                      "); check the disk or the pipe stdout goes to");
  return 0;
}

}  // namespace gg::fit::cli
