#include "structure_tools.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <sstream>

#include "correlation.hpp"
#include "gg/cli.hpp"
#include "gg/errors.hpp"
#include "gg/h5file.hpp"
#include "gg/particle_volume.hpp"
#include "gg/progress.hpp"
#include "gg/provenance.hpp"
#include "gg/trajectory.hpp"

namespace gg {

namespace {

const std::string kPositions = "/particles/all/position/value";
const std::string kRadii = "/particles/all/radius/value";

std::string fmt(double x) {
  std::ostringstream s;
  s << x;
  return s.str();
}

void add_structure_options(CLI::App& app, StructureConfig& c) {
  app.add_option("input", c.input, "H5MD particle file written by gg-sim ('-' = stdin)")->required();
  app.add_option("-o,--output", c.output, "Output HDF5 file ('-' = stdout)")->required();
  app.add_option("--grid", c.grain.grid,
                 "Target cell spacing; the box gets n = max(1, round(L/grid)) cells per side")
      ->capture_default_str();
  app.add_option("--coarse", c.grain.coarse,
                 "w: rho_loc of a cell = particles in the (2w+1)^d block of cells around it / block volume; "
                 "at most (n-1)/2 for n cells per side, so the block never counts a cell twice")
      ->capture_default_str();
  app.add_option("--rho-c", c.grain.rho_c,
                 "Threshold density: psi = +1 where rho_loc > rho_c, -1 elsewhere (rho_loc = rho_c counts as -1)")
      ->capture_default_str();
  gg::add_list_option(app, "--frames", c.frames,
                      "Comma-separated snapshot indices to analyse, each once (negative counts from the end, -1 = "
                      "last; default: every snapshot)");
}

void validate_common(const StructureConfig& c) {
  // The box-independent part of gg::validate (grid <= L and the block width are checked once the box
  // is read).
  validate(c.grain, {});
}

// One selected frame at a time: the memory held is one snapshot, whatever the file's length.
struct FrameSeries {
  std::vector<long> index;  // file frame indices, in the order analysed
  std::vector<double> time;
  std::vector<std::int64_t> step;
  std::vector<double> edges;
  std::vector<std::int64_t> cells_per_side;
  std::vector<double> cell_spacing;
};

FrameSeries coarse_grain_frames(const H5Input& in, const StructureConfig& c, const std::string& program,
                                const CommonFlags& flags, const std::function<void(const DensityGrid&)>& per_frame) {
  if (in.is_dataset(kPositions) && !in.shape(kPositions).empty() && in.shape(kPositions)[0] == 0)
    throw RuntimeError("'" + in.path() + "' holds no snapshots (" + kPositions +
                       " has 0 frames); run gg-sim with --snapshots or --snapshots-per-decade");
  // The first read checks that the file is H5MD with 1D, 2D or 3D positions (clear errors otherwise).
  Snapshots s = read_snapshots(in, {c.frames.empty() ? 0L : c.frames.front()});
  const long total = static_cast<long>(in.shape(kPositions).at(0));
  FrameSeries out;
  out.edges = s.edges;
  if (c.frames.empty()) {
    for (long k = 0; k < total; ++k) out.index.push_back(k);
  } else {
    for (long f : c.frames) {
      const long k = f < 0 ? total + f : f;
      if (k < 0 || k >= total)
        throw UsageError("--frames: frame " + std::to_string(f) + " does not exist: '" + in.path() + "' has " +
                         std::to_string(total) + " frames (0.." + std::to_string(total - 1) + ", or -" +
                         std::to_string(total) + "..-1)");
      // A frame analysed twice would repeat its time in every output series.
      if (const auto seen = std::find(out.index.begin(), out.index.end(), k); seen != out.index.end()) {
        const long earlier = c.frames[static_cast<std::size_t>(seen - out.index.begin())];
        const std::string which = earlier == f ? std::to_string(f) + " twice"
                                               : std::to_string(k) + " twice (as " + std::to_string(earlier) +
                                                     " and " + std::to_string(f) + ")";
        throw UsageError("--frames names frame " + which + "; give each frame once");
      }
      out.index.push_back(k);
    }
  }

  DensityGrid grid(s.edges, c.grain);  // checks grid <= L and a block no wider than the grid
  out.cells_per_side.assign(grid.cells_per_side().begin(), grid.cells_per_side().end());
  out.cell_spacing = grid.spacing();
  Progress progress(flags.show_progress(), program);
  // A file with radii (a mixture's, or aggregates') is coarse-grained by the area (volume in 3D) of
  // its particles, the local packing fraction, instead of their number (docs/DESIGN.md "Coarse-grained
  // density").
  const bool sized = in.is_dataset(kRadii);
  std::vector<double> weights;
  for (std::size_t j = 0; j < out.index.size(); ++j) {
    if (j > 0) s = read_snapshots(in, {out.index[j]});
    if (sized) {
      weights = in.read_rows(kRadii, {static_cast<std::size_t>(out.index[j])}).data;
      if (weights.size() != s.n_particles)
        throw RuntimeError("'" + in.path() + "': " + kRadii + " does not hold one radius per particle");
      for (double& w : weights) w = particle_volume(w, s.dim);
    }
    grid.assign(s.position.data(), s.n_particles, sized ? weights.data() : nullptr);
    per_frame(grid);
    out.time.push_back(s.time.at(0));
    out.step.push_back(s.step.at(0));
    progress.update(static_cast<double>(j + 1) / static_cast<double>(out.index.size()),
                    "frame " + std::to_string(j + 1) + " of " + std::to_string(out.index.size()));
  }
  return out;
}

// time, step and the coarse-graining parameters shared by the three groups.
void write_common(H5Output& out, const std::string& group, const StructureConfig& c, const FrameSeries& f) {
  out.write(group + "/time", f.time);
  out.write(group + "/step", f.step);
  out.attr(group, "input", c.input == "-" ? std::string("<stdin>") : c.input);
  out.attr(group, "frames", std::vector<std::int64_t>(f.index.begin(), f.index.end()));
  out.attr(group, "grid", c.grain.grid);
  out.attr(group, "coarse", static_cast<std::int64_t>(c.grain.coarse));
  out.attr(group, "rho_c", c.grain.rho_c);
  out.attr(group, "box_edges", f.edges);
  out.attr(group, "cells_per_side", f.cells_per_side);
  out.attr(group, "cell_spacing", f.cell_spacing);
  out.attr(group, "psi", std::string("+1 where rho_loc > rho_c, -1 elsewhere"));
}

// What the three tools share around their analysis: read IN, hand every selected coarse-grained frame
// to `per_frame`, then write `group` of OUT: time, step and the coarse-graining (write_common), what
// `write_results` adds, and the provenance; OUT is committed atomically, so it must not be IN (the
// commit would replace the snapshots with the analysis). Returns the exit status (0).
int run_structure_tool(const StructureConfig& c, const std::string& program, const std::string& group,
                       const CommonFlags& flags, const std::vector<std::string>& argv,
                       const std::function<void(const DensityGrid&)>& per_frame,
                       const std::function<void(H5Output&, const std::string&, const FrameSeries&)>& write_results) {
  require_output_is_not_an_input(c.output, {c.input});
  H5Input in(c.input);
  H5Output out(c.output);
  const FrameSeries f = coarse_grain_frames(in, c, program, flags, per_frame);
  write_common(out, group, c, f);
  write_results(out, group, f);
  write_provenance(out, Provenance{program, argv, std::nullopt}, {&in});
  out.commit();
  return 0;
}

void add_cluster_options(CLI::App& app, ClusterConfig& c) {
  add_structure_options(app, c);
  app.add_option("--connectivity", c.connectivity,
                 "Cells that touch: sharing a face (4 in 2D, 6 in 3D; the default) or also an edge or a corner "
                 "(8 in 2D, 26 in 3D); 1D: left/right either way");
  app.add_option("--min-size", c.min_size,
                 "Clusters with fewer particles are left out of mean_mass, weight_mass, count and largest")
      ->transform(gg::whole_number())
      ->capture_default_str();
  app.add_flag("--histogram", c.histogram,
               "Also write /cluster/mass_histogram [T][B] (clusters per log2 mass bin) and mass_bin_edges");
}

void add_correlate_options(CLI::App& app, CorrelateConfig& c) {
  add_structure_options(app, c);
  app.add_option("--a", c.a, "l_C is the first r where C(r) falls to a (linear interpolation), -1 < a < 1")
      ->capture_default_str();
}

void add_domains_options(CLI::App& app, DomainsConfig& c) {
  add_structure_options(app, c);
  app.add_option("--phase", c.phase, "Which domains count: both, rich (psi = +1) or poor (psi = -1)")
      ->capture_default_str();
}

// What to reduce when a tool runs out of memory (guarded_main's memory_hint): the grid is what grows.
const char* const kMemoryHint = "the grid's cells (a larger --grid)";

template <class Config>
int structure_main(int argc, char** argv, const std::string& program, const std::string& description,
                   void (*add_options)(CLI::App&, Config&),
                   int (*run)(const Config&, const CommonFlags&, const std::vector<std::string>&)) {
  Config config;
  CommonFlags flags;
  CLI::App app{description};
  app.name(program);
  add_common_flags(app, flags);
  add_options(app, config);
  if (const int status = parse_cli(app, argc, argv); status >= 0) return status;
  return guarded_main(program, [&] { return run(config, flags, argv_strings(argc, argv)); }, kMemoryHint);
}

}  // namespace

std::int64_t cluster_neighbours(int connectivity, int dim) {
  if (dim == 1) return connectivity == 0 ? 2 : connectivity;  // left and right, whatever was asked
  const int faces = 2 * dim, full = dim == 2 ? 8 : 26;
  if (connectivity == 0 || connectivity == faces) return faces;
  if (connectivity == full) return full;
  throw UsageError("--connectivity " + std::to_string(connectivity) + " does not fit a " + std::to_string(dim) +
                   "D grid: give " + std::to_string(faces) + " (faces) or " + std::to_string(full) +
                   " (faces, edges and corners)");
}

void validate(const ClusterConfig& c) {
  validate_common(c);
  if (c.connectivity != 0 && c.connectivity != 4 && c.connectivity != 8 && c.connectivity != 6 && c.connectivity != 26)
    throw UsageError("--connectivity " + std::to_string(c.connectivity) +
                     " must be 4 (faces) or 8 (faces and corners) in 2D, 6 or 26 in 3D");
  if (c.min_size < 0) throw UsageError("--min-size " + std::to_string(c.min_size) + " must be >= 0 particles");
}

void validate(const CorrelateConfig& c) {
  validate_common(c);
  if (!(c.a > -1 && c.a < 1))
    throw UsageError("--a " + fmt(c.a) + " must lie between -1 and 1 (C(0) = 1; default 0.5)");
}

void validate(const DomainsConfig& c) {
  validate_common(c);
  parse_phase(c.phase);
}

int run_cluster(const ClusterConfig& c, const CommonFlags& flags, const std::vector<std::string>& argv) {
  validate(c);
  Connectivity conn = Connectivity::face;
  std::int64_t neighbours = 0;  // the --connectivity of the file's dimension, once it is known
  std::vector<double> mean, weight, hist;
  std::vector<std::int64_t> count, largest;
  std::vector<double> edges;
  const auto per_frame = [&](const DensityGrid& grid) {
    if (neighbours == 0) {
      neighbours = cluster_neighbours(c.connectivity, grid.dim());
      conn = neighbours == 4 || neighbours == 6 || neighbours == 2 ? Connectivity::face : Connectivity::full;
    }
    const ClusterResult r = find_clusters(grid, conn);
    const ClusterStats s = summarize(r.clusters, c.min_size);
    mean.push_back(s.mean_mass);
    weight.push_back(s.weight_mass);
    count.push_back(s.count);
    largest.push_back(s.largest);
    if (c.histogram) {
      if (edges.empty()) edges = mass_bin_edges(static_cast<std::int64_t>(grid.n_particles()));
      const auto h = mass_histogram(r.clusters, c.min_size, edges);
      hist.insert(hist.end(), h.begin(), h.end());
    }
  };
  const auto write = [&](H5Output& out, const std::string& g, const FrameSeries& f) {
    out.attr(g, "connectivity", neighbours);
    out.attr(g, "min_size", c.min_size);
    out.attr(g, "mass", std::string("particles in the cluster's cells; averages over clusters of mass >= min_size, "
                                    "NaN when there is none"));
    out.write(g + "/mean_mass", mean);
    out.write(g + "/weight_mass", weight);
    out.write(g + "/count", count);
    out.write(g + "/largest", largest);
    if (c.histogram) {
      out.write(g + "/mass_histogram", Array{{f.time.size(), edges.size() - 1}, hist});
      out.write(g + "/mass_bin_edges", edges);
    }
  };
  return run_structure_tool(c, "gg-cluster", "/cluster", flags, argv, per_frame, write);
}

int run_correlate(const CorrelateConfig& c, const CommonFlags& flags, const std::vector<std::string>& argv) {
  validate(c);
  std::unique_ptr<Correlator> correlator;  // plans made on the first frame, reused for the rest
  std::vector<double> C, length;
  const auto per_frame = [&](const DensityGrid& grid) {
    if (!correlator) correlator = std::make_unique<Correlator>(grid);
    const CorrelationResult r = correlator->compute(grid, c.a);
    C.insert(C.end(), r.C.begin(), r.C.end());
    length.push_back(r.length);
  };
  const auto write = [&](H5Output& out, const std::string& g, const FrameSeries& f) {
    out.attr(g, "a", c.a);
    out.attr(g, "C", std::string("C(r) = C_o(r)/C_o(0), C_o = <psi(x)psi(x+r)> - <psi>^2, shells |r|/h rounded; "
                                 "NaN when psi is uniform"));
    const std::vector<double>& r = correlator->radii();
    out.write(g + "/r", r);
    out.write(g + "/C", Array{{f.time.size(), r.size()}, C});
    out.write(g + "/length", length);
  };
  return run_structure_tool(c, "gg-correlate", "/correlation", flags, argv, per_frame, write);
}

int run_domains(const DomainsConfig& c, const CommonFlags& flags, const std::vector<std::string>& argv) {
  validate(c);
  const Phase phase = parse_phase(c.phase);
  std::vector<double> hist, length, edges;
  std::vector<std::int64_t> count;
  const auto per_frame = [&](const DensityGrid& grid) {
    const DomainResult r = measure_domains(grid, phase);
    if (edges.empty()) edges = r.bin_edges;
    hist.insert(hist.end(), r.histogram.begin(), r.histogram.end());
    length.push_back(r.length);
    count.push_back(r.count);
  };
  const auto write = [&](H5Output& out, const std::string& g, const FrameSeries& f) {
    out.attr(g, "phase", std::string(to_string(phase)));
    out.attr(g, "histogram", std::string("P(l_d) as a density (sum P dl = 1), bins of one cell spacing; "
                                         "length = first moment, NaN when no line has an interface"));
    out.write(g + "/length", length);
    out.write(g + "/count", count);
    out.write(g + "/histogram", Array{{f.time.size(), edges.size() - 1}, hist});
    out.write(g + "/bin_edges", edges);
  };
  return run_structure_tool(c, "gg-domains", "/domains", flags, argv, per_frame, write);
}

int cluster_main(int argc, char** argv, const std::string& description) {
  return structure_main(argc, argv, "gg-cluster", description, add_cluster_options, run_cluster);
}

int correlate_main(int argc, char** argv, const std::string& description) {
  return structure_main(argc, argv, "gg-correlate", description, add_correlate_options, run_correlate);
}

int domains_main(int argc, char** argv, const std::string& description) {
  return structure_main(argc, argv, "gg-domains", description, add_domains_options, run_domains);
}

}  // namespace gg
