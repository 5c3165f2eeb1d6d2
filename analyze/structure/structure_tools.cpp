#include "structure_tools.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>

#include "correlation.hpp"
#include "pair_correlation.hpp"
#include "velocity.hpp"
#include "gg/cli.hpp"
#include "gg/errors.hpp"
#include "gg/fmt.hpp"
#include "gg/frames.hpp"
#include "gg/h5file.hpp"
#include "gg/particle_volume.hpp"
#include "gg/progress.hpp"
#include "gg/provenance.hpp"
#include "gg/trajectory.hpp"

namespace gg {

namespace {

// What gg-velocity shares with the density tools: IN, -o OUT, --grid, --coarse, --frames.
void add_grid_options(CLI::App& app, StructureConfig& c) {
  app.add_option("input", c.input, "Particle file: H5MD (gg-sim), GSD (HOOMD schema), LAMMPS text dump or extended XYZ, "
                 "told apart by content ('-' = H5MD on stdin)")->required();
  app.add_option("-o,--output", c.output, "Output HDF5 file ('-' = stdout)")->required();
  app.add_option("--grid", c.grain.grid,
                 "Target cell spacing; the box gets n = max(1, round(L/grid)) cells per side")
      ->capture_default_str();
  app.add_option("--coarse", c.grain.coarse,
                 "w: rho_loc of a cell = particles in the (2w+1)^d block of cells around it / block volume; "
                 "at most (n-1)/2 for n cells per side, so the block never counts a cell twice")
      ->capture_default_str();
  gg::add_list_option(app, "--frames", c.frames,
                      "Comma-separated snapshot indices to analyse, each once (negative counts from the end, -1 = "
                      "last; default: every snapshot)");
}

void add_structure_options(CLI::App& app, StructureConfig& c) {
  add_grid_options(app, c);
  app.add_option("--rho-c", c.grain.rho_c,
                 "Threshold density: psi = +1 where rho_loc > rho_c, -1 elsewhere (rho_loc = rho_c counts as -1)")
      ->capture_default_str();
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

// One frame as an analysis sees it: the grid, the particles, and their masses (nullptr: all 1).
struct Frame {
  const FrameSource& source;
  const DensityGrid& grid;
  const ParticleFrame& particles;
  const double* mass;
  bool weighted;  // the file has radii (the grid is weighted by particle volume)
};
using PerFrame = std::function<void(const Frame&)>;

FrameSeries coarse_grain_frames(const FrameSource& in, const StructureConfig& c, const std::string& program,
                                const CommonFlags& flags, const PerFrame& per_frame) {
  const long total = static_cast<long>(in.frames());
  if (total == 0)
    throw RuntimeError("'" + in.path() + "' holds no snapshots (0 frames)" +
                       (in.format() == FrameFormat::kH5md ? "; run gg-sim with --snapshots or --snapshots-per-decade" : ""));
  FrameSeries out;
  out.index = chosen_frames(c.frames, total, in.path());

  ParticleFrame s = in.read(static_cast<std::size_t>(out.index.front()));
  out.edges = s.edges;
  DensityGrid grid(s.edges, c.grain);  // checks grid <= L and a block no wider than the grid
  out.cells_per_side.assign(grid.cells_per_side().begin(), grid.cells_per_side().end());
  out.cell_spacing = grid.spacing();
  Progress progress(flags.show_progress(), program);
  std::vector<double> weights;
  for (std::size_t j = 0; j < out.index.size(); ++j) {
    if (j > 0) s = in.read(static_cast<std::size_t>(out.index[j]));
    if (s.edges != out.edges)
      throw RuntimeError("'" + in.path() + "' frame " + std::to_string(out.index[j]) + ": the box differs from frame " +
                         std::to_string(out.index.front()) + "'s; the analyses need a box fixed in time");
    // A file with radii (a mixture's, aggregates', particles of other sizes) is coarse-grained by the
    // area (volume in 3D) of its particles, the local packing fraction, instead of their number
    // (docs/DESIGN.md "Coarse-grained density").
    const bool sized = !s.radius.empty();
    if (sized) {
      weights = s.radius;
      for (double& w : weights) w = particle_volume(w, s.dim);
    }
    grid.assign(s.position.data(), s.n, sized ? weights.data() : nullptr);
    per_frame(Frame{in, grid, s, s.mass.empty() ? nullptr : s.mass.data(), sized});
    out.time.push_back(s.time);
    out.step.push_back(s.step);
    progress.update(static_cast<double>(j + 1) / static_cast<double>(out.index.size()),
                    "frame " + std::to_string(j + 1) + " of " + std::to_string(out.index.size()));
  }
  return out;
}

// time, step and the coarse-graining parameters shared by the three groups.
void write_common(H5Output& out, const std::string& group, const StructureConfig& c, const FrameSeries& f,
                  bool order_parameter) {
  out.write(group + "/time", f.time);
  out.write(group + "/step", f.step);
  out.attr(group, "input", c.input == "-" ? std::string("<stdin>") : c.input);
  out.attr(group, "frames", std::vector<std::int64_t>(f.index.begin(), f.index.end()));
  out.attr(group, "grid", c.grain.grid);
  out.attr(group, "coarse", static_cast<std::int64_t>(c.grain.coarse));
  out.attr(group, "box_edges", f.edges);
  out.attr(group, "cells_per_side", f.cells_per_side);
  out.attr(group, "cell_spacing", f.cell_spacing);
  if (order_parameter) {
    out.attr(group, "rho_c", c.grain.rho_c);
    out.attr(group, "psi", std::string("+1 where rho_loc > rho_c, -1 elsewhere"));
  }
}

// What the three tools share around their analysis: read IN, hand every selected coarse-grained frame
// to `per_frame`, then write `group` of OUT: time, step and the coarse-graining (write_common), what
// `write_results` adds, and the provenance; OUT is committed atomically, so it must not be IN (the
// commit would replace the snapshots with the analysis). Returns the exit status (0).
int run_structure_tool(const StructureConfig& c, const std::string& program, const std::string& group,
                       const CommonFlags& flags, const std::vector<std::string>& argv,
                       const PerFrame& per_frame,
                       const std::function<void(H5Output&, const std::string&, const FrameSeries&)>& write_results) {
  require_output_is_not_an_input(c.output, {c.input});
  const std::unique_ptr<FrameSource> in = open_frames(c.input);
  H5Output out(c.output);
  const FrameSeries f = coarse_grain_frames(*in, c, program, flags, per_frame);
  write_common(out, group, c, f, group != "/velocity");
  out.attr(group, "input_format", std::string(to_string(in->format())));
  write_results(out, group, f);
  write_provenance(out, Provenance{program, argv, std::nullopt}, *in);
  out.commit();
  return 0;
}

void add_cluster_options(CLI::App& app, ClusterConfig& c) {
  add_structure_options(app, c);
  app.add_option("--connectivity", c.connectivity,
                 "Cells that touch: sharing a face (4 in 2D, 6 in 3D; the default) or also an edge or a corner "
                 "(8 in 2D, 26 in 3D); 1D: left/right either way");
  app.add_option("--min-size", c.min_size,
                 "Clusters with fewer particles are left out of every statistic (mean_mass ... rest_mean_mass, wraps)")
      ->transform(gg::whole_number())
      ->capture_default_str();
  app.add_flag("--histogram", c.histogram,
               "Also write /cluster/mass_histogram [T][B] (clusters per log2 mass bin) and mass_bin_edges");
  app.add_flag("--particle-clusters", c.particle_clusters,
               "Also write /cluster/particle_cluster [T][N]: each particle's cluster, 0 = the largest, every cluster "
               "numbered by mass whatever --min-size (ties: smallest cell first), -1 = in no cluster (large: use with "
               "--frames)");
}

void add_correlate_options(CLI::App& app, CorrelateConfig& c) {
  add_structure_options(app, c);
  app.add_option("--a", c.a, "l_C is the first r where C(r) falls to a (linear interpolation), -1 < a < 1")
      ->capture_default_str();
  app.add_flag("--pairs", c.pairs,
               "Also the radial distribution g(r) of the particles and its contact value g(sigma+) (off by default: "
               "a pair search per frame, the cost of the rest twice over)");
  app.add_flag("--density", c.density,
               "Also the structure factor S_rho(k) of the particles counted per cell (a second FFT per frame)");
  app.add_option("--g-max", c.g_max, "With --pairs: g(r) up to this r (cut to half the shortest box edge)")
      ->capture_default_str();
  app.add_option("--g-bin", c.g_bin, "With --pairs: width of the bins of g(r)")->capture_default_str();
  app.add_option("--g-contact", c.g_contact,
                 "With --pairs: g(sigma+) is the least-squares line through the g(r) bins whose centres lie within this of "
                 "sigma = 1, at r = 1 (NaN for a file with radii)")
      ->capture_default_str();
}

void add_velocity_options(CLI::App& app, VelocityConfig& c) {
  add_grid_options(app, c);
  app.add_option("--a", c.a,
                 "The correlation lengths of the flow are the first r where C_L(r), C_T(r) fall to a, -1 < a < 1")
      ->capture_default_str();
  app.add_option("--dc", c.dc, "Width of the linear bins of c = |v - V| / v_T, from 0 to --body-max")
      ->capture_default_str();
  app.add_option("--body-max", c.body_max, "Where the linear bins of c end and the log-spaced ones begin")
      ->capture_default_str();
  app.add_option("--per-decade", c.per_decade, "Log-spaced bins of c per decade beyond --body-max")
      ->capture_default_str();
  app.add_option("--c-top", c.c_top, "The last bin of c ends at the first edge >= this")->capture_default_str();
  app.add_option("--tail-from", c.tail_from,
                 "The fit ln f = ln f0 - A c^b uses the bins at c >= this, up to the first with fewer than 10 particles")
      ->capture_default_str();
  app.add_flag("--fields", c.fields,
               "Also write the flow field u [T][cells...][d], its vorticity and rho_loc of every analysed frame "
               "(large: use with --frames)");
  CLI::Option* profile =
      app.add_option("--profile", c.profile,
                     "Also the profiles along this axis (x, y or z; for a walled run the walls' axis) in equal slabs of "
                     "the box edge: number density, mean velocity u and temperature relative to u, mean and standard "
                     "error over the analysed frames (/velocity/profile)");
  CLI::Option* bins = app.add_option("--bins", c.bins, "With --profile: the number of slabs (default: from --bin-width)")
                          ->transform(gg::whole_number())
                          ->needs(profile);
  app.add_option("--bin-width", c.bin_width,
                 "With --profile: target slab width (1 = one diameter); the edge L gets max(1, round(L / width)) slabs")
      ->capture_default_str()
      ->needs(profile)
      ->excludes(bins);
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
  if (!(c.g_bin > 0 && std::isfinite(c.g_bin)))
    throw UsageError("--g-bin " + fmt(c.g_bin) + " must be a positive width (default 0.02)");
  if (!(c.g_max >= c.g_bin && std::isfinite(c.g_max)))
    throw UsageError("--g-max " + fmt(c.g_max) + " must be at least --g-bin (" + fmt(c.g_bin) + "; default 5)");
  // The histogram of g(r) holds g_max / g_bin bins: a million is far finer than any pair count fills.
  if (c.g_max / c.g_bin > 1e6)
    throw UsageError("--g-bin " + fmt(c.g_bin) + " makes " + fmt(c.g_max / c.g_bin) + " bins up to --g-max " + fmt(c.g_max) +
                     "; give at most 1e6 (default 0.02 up to 5: 250)");
  if (!(c.g_contact >= 2 * c.g_bin && c.g_contact < c.g_max))
    throw UsageError("--g-contact " + fmt(c.g_contact) + " must hold two bins of g(r) (>= 2 --g-bin) and be less "
                     "than --g-max (default 0.1)");
}

void validate(const VelocityConfig& c) {
  validate_common(c);
  if (!(c.a > -1 && c.a < 1))
    throw UsageError("--a " + fmt(c.a) + " must lie between -1 and 1 (C_L(0) = C_T(0) = 1; default 0.5)");
  if (!(c.body_max > 0 && c.body_max < c.c_top && std::isfinite(c.c_top)))
    throw UsageError("--body-max " + fmt(c.body_max) + " and --c-top " + fmt(c.c_top) +
                     " must satisfy 0 < body-max < c-top (defaults 3 and 12)");
  if (!(c.dc > 0 && c.dc <= c.body_max))
    throw UsageError("--dc " + fmt(c.dc) + " must be positive and at most --body-max (" + fmt(c.body_max) + ")");
  // f(c) holds body_max / dc bins below body_max: a million is far finer than any snapshot fills.
  if (c.body_max / c.dc > 1e6)
    throw UsageError("--dc " + fmt(c.dc) + " makes " + fmt(c.body_max / c.dc) + " bins of f(c) up to --body-max " +
                     fmt(c.body_max) + "; give at most 1e6 (default 0.1 up to 3: 30)");
  if (c.per_decade < 1 || c.per_decade > 1000)
    throw UsageError("--per-decade " + std::to_string(c.per_decade) + " must lie in 1..1000 (default 20)");
  if (!(c.tail_from >= 0 && c.tail_from < c.c_top))
    throw UsageError("--tail-from " + fmt(c.tail_from) + " must lie in [0, --c-top) (default 1.5)");
  if (!c.profile.empty() && c.profile != "x" && c.profile != "y" && c.profile != "z")
    throw UsageError("--profile " + c.profile + " must be an axis: x, y or z");
  if (c.profile.empty() && c.bins) throw UsageError("--bins needs --profile AXIS (the axis of the slabs)");
  if (c.bins && *c.bins < 1) throw UsageError("--bins " + std::to_string(*c.bins) + " must be at least 1 slab");
  if (!(c.bin_width > 0 && std::isfinite(c.bin_width)))
    throw UsageError("--bin-width " + fmt(c.bin_width) + " must be a positive width (default 1)");
}

void validate(const DomainsConfig& c) {
  validate_common(c);
  parse_phase(c.phase);
}

int run_cluster(const ClusterConfig& c, const CommonFlags& flags, const std::vector<std::string>& argv) {
  validate(c);
  Connectivity conn = Connectivity::face;
  std::int64_t neighbours = 0;  // the --connectivity of the file's dimension, once it is known
  std::vector<double> mean, weight, hist, share, share_clustered, rest_mean;
  std::vector<std::int64_t> count, largest;
  std::vector<double> edges;
  std::vector<std::uint8_t> wraps;            // [T] bit masks (Cluster::wraps)
  std::vector<std::int32_t> particle_cluster;  // [T][N] with --particle-clusters
  std::size_t dim = 0, n_particles = 0;
  const auto per_frame = [&](const Frame& frame) {
    const DensityGrid& grid = frame.grid;
    if (neighbours == 0) {
      neighbours = cluster_neighbours(c.connectivity, grid.dim());
      conn = neighbours == 4 || neighbours == 6 || neighbours == 2 ? Connectivity::face : Connectivity::full;
      dim = static_cast<std::size_t>(grid.dim());
      n_particles = grid.n_particles();
    }
    const ClusterResult r = find_clusters(grid, conn);
    const ClusterStats s = summarize(r.clusters, c.min_size);
    mean.push_back(s.mean_mass);
    weight.push_back(s.weight_mass);
    count.push_back(s.count);
    largest.push_back(s.largest);
    const GiantCluster g = giant_cluster(r.clusters, static_cast<std::int64_t>(grid.n_particles()), c.min_size);
    share.push_back(g.share);
    share_clustered.push_back(g.share_of_clustered);
    rest_mean.push_back(g.rest_mean_mass);
    wraps.push_back(g.wraps);
    if (c.histogram) {
      if (edges.empty()) edges = mass_bin_edges(static_cast<std::int64_t>(grid.n_particles()));
      const auto h = mass_histogram(r.clusters, c.min_size, edges);
      hist.insert(hist.end(), h.begin(), h.end());
    }
    if (c.particle_clusters) {
      if (grid.n_particles() != n_particles)
        throw RuntimeError("'" + frame.source.path() + "': frames hold " + std::to_string(n_particles) + " and " +
                           std::to_string(grid.n_particles()) + " particles; --particle-clusters needs a fixed N");
      const auto p = gg::particle_clusters(grid, r, frame.particles.position.data(), grid.n_particles());
      particle_cluster.insert(particle_cluster.end(), p.begin(), p.end());
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
    out.write(g + "/largest_share", share);
    out.write(g + "/largest_share_of_clustered", share_clustered);
    out.write(g + "/rest_mean_mass", rest_mean);
    out.write_int_rows(g + "/wraps", {f.time.size(), dim}, [&](std::size_t k, double* v) {
      for (std::size_t a = 0; a < dim; ++a) v[a] = (wraps[k] >> a) & 1u;
    });
    out.attr(g + "/wraps", "meaning", std::string("1 where the largest cluster wraps the periodic box along the axis "
                                                  "(a path through it winds around the box), else 0"));
    // Along any axis, as a series of its own: what an ensemble average (gg-fit average) reads, whose
    // mean is then the fraction of runs in which the largest cluster wraps the box.
    std::vector<double> wraps_any(wraps.size());
    for (std::size_t k = 0; k < wraps.size(); ++k) wraps_any[k] = wraps[k] != 0 ? 1.0 : 0.0;
    out.write(g + "/largest_wraps", wraps_any);
    if (c.histogram) {
      out.write(g + "/mass_histogram", Array{{f.time.size(), edges.size() - 1}, hist});
      out.write(g + "/mass_bin_edges", edges);
    }
    if (c.particle_clusters)
      out.write_int_rows(g + "/particle_cluster", {f.time.size(), n_particles}, [&](std::size_t k, double* v) {
        std::copy_n(particle_cluster.begin() + static_cast<std::ptrdiff_t>(k * n_particles), n_particles, v);
      });
  };
  return run_structure_tool(c, "gg-cluster", "/cluster", flags, argv, per_frame, write);
}

int run_correlate(const CorrelateConfig& c, const CommonFlags& flags, const std::vector<std::string>& argv) {
  validate(c);
  std::unique_ptr<Correlator> correlator;  // plans made on the first frame, reused for the rest
  std::vector<double> C, length, S, S_rho, k1, g, g_r, g_contact;
  const auto per_frame = [&](const Frame& frame) {
    const DensityGrid& grid = frame.grid;
    if (!correlator) correlator = std::make_unique<Correlator>(grid);
    const CorrelationResult r = correlator->compute(grid, c.a);
    C.insert(C.end(), r.C.begin(), r.C.end());
    length.push_back(r.length);
    S.insert(S.end(), r.S.begin(), r.S.end());
    k1.push_back(r.k1);
    if (c.density) {
      const std::vector<double> s_rho = correlator->density_structure_factor(grid);
      S_rho.insert(S_rho.end(), s_rho.begin(), s_rho.end());
    }
    if (c.pairs) {
      const ParticleFrame& p = frame.particles;
      const RadialDistribution rd = radial_distribution(p.position.data(), p.n, p.edges, c.g_max, c.g_bin);
      if (g_r.empty()) g_r = rd.r;
      g.insert(g.end(), rd.g.begin(), rd.g.end());
      // Contact at sigma = 1 only where every particle has diameter 1.
      g_contact.push_back(frame.weighted ? std::numeric_limits<double>::quiet_NaN()
                                         : contact_value(rd, 1.0, c.g_contact));
    }
  };
  const auto write = [&](H5Output& out, const std::string& g_name, const FrameSeries& f) {
    out.attr(g_name, "a", c.a);
    out.attr(g_name, "C", std::string("C(r) = C_o(r)/C_o(0), C_o = <psi(x)psi(x+r)> - <psi>^2, shells |r|/h rounded; "
                                      "NaN when psi is uniform"));
    out.attr(g_name, "S", std::string("S(k) = |FFT(psi - <psi>)|^2 / cells, shells |k|/dk rounded, dk = 2 pi / L_max; "
                                      "k1 = sum k S / sum S over k > 0"));
    if (c.density)
      out.attr(g_name, "S_rho", std::string("S_rho(k) = |FFT(n)|^2 / N of the particles counted per cell, the shells "
                                            "of S (NaN at k = 0)"));
    if (c.pairs) {
      out.attr(g_name, "g", std::string("g(r) of the particles, bins of g_bin up to g_max (cut to L_min/2), at their "
                                        "centres g_r; g_contact = g(sigma+), a line through the bins within g_contact "
                                        "of sigma = 1 (NaN for a file with radii)"));
      out.attr(g_name, "g_bin", c.g_bin);
      out.attr(g_name, "g_max", c.g_max);
      out.attr(g_name, "g_contact_width", c.g_contact);
    }
    const std::vector<double>& r = correlator->radii();
    const std::vector<double>& k = correlator->wave_numbers();
    const std::size_t T = f.time.size();
    out.write(g_name + "/r", r);
    out.write(g_name + "/C", Array{{T, r.size()}, C});
    out.write(g_name + "/length", length);
    out.write(g_name + "/k", k);
    out.write(g_name + "/S", Array{{T, k.size()}, S});
    out.write(g_name + "/k1", k1);
    if (c.density) out.write(g_name + "/S_rho", Array{{T, k.size()}, S_rho});
    if (c.pairs) {
      out.write(g_name + "/g_r", g_r);
      out.write(g_name + "/g", Array{{T, g_r.size()}, g});
      out.write(g_name + "/g_contact", g_contact);
    }
  };
  return run_structure_tool(c, "gg-correlate", "/correlation", flags, argv, per_frame, write);
}

namespace {

// The axis --profile names, checked against the file's dimension.
int profile_axis(const std::string& name, int dim) {
  const int axis = name.at(0) - 'x';
  if (axis >= dim)
    throw UsageError("--profile " + name + ": the input is " + std::to_string(dim) + "D, with axes " +
                     (dim == 1 ? "x" : "x and y") + " only");
  return axis;
}

// The slabs of --bins, or of --bin-width over the edge L, capped like the density grid's cells (a
// width meant for another box would otherwise allocate gigabytes).
std::size_t profile_bins(const VelocityConfig& c, double L) {
  const double bins = c.bins ? static_cast<double>(*c.bins) : std::max(1.0, std::round(L / c.bin_width));
  if (bins > kMaxCells)
    throw UsageError(c.bins ? "--bins " + fmt(bins) + " is more than " + fmt(kMaxCells) + " slabs; give fewer"
                            : "--bin-width " + fmt(c.bin_width) + " cuts the edge " + fmt(L) + " into " + fmt(bins) +
                                  " slabs, more than " + fmt(kMaxCells) + "; give a wider --bin-width");
  return static_cast<std::size_t>(bins);
}

// --profile: each frame's slabs (slab_profile) averaged over the frames as they come, so that memory
// holds one frame's slabs whatever the number of frames.
class ProfileSeries {
 public:
  // The axis and the slabs, from the box of the first frame; UsageError for an axis the file lacks.
  ProfileSeries(const VelocityConfig& c, const std::vector<double>& edges)
      : edges_(edges), axis_(profile_axis(c.profile, static_cast<int>(edges.size()))),
        bins_(profile_bins(c, edges[axis_])) {}

  void add(const ParticleFrame& p, const double* mass) {
    const SlabProfile s = slab_profile(p.position.data(), p.velocity.data(), mass, p.n, edges_, axis_, bins_);
    density_.add(s.density), velocity_.add(s.velocity), temperature_.add(s.temperature);
  }

  void write(H5Output& out, const std::string& g) const {
    const std::size_t d = edges_.size();
    const double width = edges_[axis_] / static_cast<double>(bins_);
    std::vector<double> centre(bins_);
    for (std::size_t b = 0; b < bins_; ++b) centre[b] = (static_cast<double>(b) + 0.5) * width;
    out.write(g + "/position", centre);
    out.attr(g + "/position", "unit", kUnitLength);
    write_mean(out, g + "/density", density_, {bins_}, kUnitLength + "-" + std::to_string(d));
    write_mean(out, g + "/velocity", velocity_, {bins_, d}, kUnitVelocity);
    write_mean(out, g + "/temperature", temperature_, {bins_}, kUnitEnergy);
    out.write(g + "/velocity_frames", whole(velocity_.frames(), d));
    out.write(g + "/temperature_frames", whole(temperature_.frames(), 1));
    out.attr(g, "axis", std::string(1, static_cast<char>('x' + axis_)));
    out.attr(g, "bins", bins_);
    out.attr(g, "bin_width", width);
    out.attr(g, "profile",
             std::string("slabs of the edge along axis at centres position; per frame density = particles / slab "
                         "volume, velocity u = sum m v / sum m (NaN if empty), temperature = sum m |v - u|^2 / "
                         "(d (N_slab - 1)) (unbiased for the slab's own u; NaN below 2 particles); mean over the "
                         "frames where defined (velocity_frames, temperature_frames), _stderr = sample standard "
                         "deviation / sqrt(frames)"));
  }

 private:
  // `name` and `name`_stderr, of shape `shape`.
  static void write_mean(H5Output& out, const std::string& name, const FrameAverage& a,
                         const std::vector<std::size_t>& shape, const std::string& unit) {
    out.write(name, Array{shape, a.mean()});
    out.write(name + "_stderr", Array{shape, a.standard_error()});
    out.attr(name, "unit", unit);
    out.attr(name + "_stderr", "unit", unit);
  }

  // Every `stride`-th frame count (the slab's; the components of u share it) as integers.
  static std::vector<std::int64_t> whole(const std::vector<double>& frames, std::size_t stride) {
    std::vector<std::int64_t> out;
    for (std::size_t j = 0; j < frames.size(); j += stride) out.push_back(static_cast<std::int64_t>(frames[j]));
    return out;
  }

  std::vector<double> edges_;
  int axis_;
  std::size_t bins_;
  FrameAverage density_, velocity_, temperature_;
};

}  // namespace

int run_velocity(const VelocityConfig& c, const CommonFlags& flags, const std::vector<std::string>& argv) {
  validate(c);
  const std::vector<double> edges = speed_bin_edges(c.dc, c.body_max, c.per_decade, c.c_top);
  std::unique_ptr<FlowAnalyzer> flow;
  int d = 0;
  std::vector<double> temperature, T, a2, a2_err, a3, a3_err, f, tail_A, tail_b, tail_f0, fraction, empty, C_L, C_T,
      length_L, length_T, enstrophy, u, omega, rho;
  std::vector<std::int64_t> tail_bins;
  std::vector<std::size_t> grid_shape;
  std::unique_ptr<ProfileSeries> profile;
  const auto per_frame = [&](const Frame& frame) {
    const ParticleFrame& p = frame.particles;
    const DensityGrid& grid = frame.grid;
    // A file without velocities is refused at its first frame, once the positions have passed the
    // checks every tool makes (so a damaged file is named for its damage).
    require_velocities(frame.source, p);
    if (!flow) {
      flow = std::make_unique<FlowAnalyzer>(grid);
      d = p.dim;
      grid_shape.assign(grid.cells_per_side().begin(), grid.cells_per_side().end());
      if (!c.profile.empty()) profile = std::make_unique<ProfileSeries>(c, p.edges);
    }
    if (profile) profile->add(p, frame.mass);
    const double* v = p.velocity.data();
    const SonineResult s = sonine_coefficients(v, frame.mass, p.n, d);
    temperature.insert(temperature.end(), s.temperature.begin(), s.temperature.end());
    T.push_back(s.T), a2.push_back(s.a2), a2_err.push_back(s.a2_stderr), a3.push_back(s.a3), a3_err.push_back(s.a3_stderr);
    const SpeedDistribution dist = speed_distribution(v, frame.mass, p.n, d, edges, c.tail_from);
    f.insert(f.end(), dist.f.begin(), dist.f.end());
    tail_A.push_back(dist.tail_A), tail_b.push_back(dist.tail_b), tail_f0.push_back(dist.tail_f0);
    tail_bins.push_back(dist.tail_bins);
    const FlowResult r = flow->compute(grid, p.position.data(), v, frame.mass, p.n, c.a);
    fraction.push_back(r.energy_fraction), empty.push_back(r.empty_fraction);
    C_L.insert(C_L.end(), r.C_L.begin(), r.C_L.end());
    C_T.insert(C_T.end(), r.C_T.begin(), r.C_T.end());
    length_L.push_back(r.length_L), length_T.push_back(r.length_T), enstrophy.push_back(r.enstrophy);
    if (c.fields) {
      u.insert(u.end(), flow->flow().begin(), flow->flow().end());
      omega.insert(omega.end(), flow->vorticity().begin(), flow->vorticity().end());
      for (std::size_t cell = 0; cell < grid.size(); ++cell) rho.push_back(grid.rho_loc(cell));
    }
  };
  const auto write = [&](H5Output& out, const std::string& g, const FrameSeries& fs) {
    const std::size_t n = fs.time.size(), dd = static_cast<std::size_t>(d);
    out.attr(g, "a", c.a);
    out.attr(g, "tail_from", c.tail_from);
    out.attr(g, "velocities", std::string("relative to the centre-of-mass velocity V = sum m v / sum m"));
    out.attr(g, "sonine", std::string("a2 = d/(d+2) <w^2>/<w>^2 - 1, a3 = 1 + 3 a2 - d^2/((d+2)(d+4)) <w^3>/<w>^3, "
                                      "w = m |v - V|^2; stderr by the delta method over independent particles"));
    out.attr(g, "distribution", std::string("f(c) per unit c-space volume, c = |v - V| / sqrt(2 T / m) (Maxwellian: "
                                            "pi^(-d/2) exp(-c^2)); tail fit ln f = ln f0 - A c^b"));
    out.attr(g, "flow", std::string("u = momentum / mass in the (2w+1)^d block of each cell (V removed), 0 where the "
                                    "block holds no particle (empty_fraction of the cells); flow_energy_fraction = "
                                    "sum M_cell |u|^2 / sum m |v - V|^2"));
    out.attr(g, "correlation", std::string("C_L, C_T: longitudinal and transverse <u_i(x) u_j(x+r)> r_i r_j of the "
                                           "fluctuations of u, shell averages, normalised by tr C(0) / d; lengths "
                                           "where they first fall to a; enstrophy = <|curl u|^2> / 2 by central "
                                           "differences (C_T, length_T, enstrophy NaN in 1D)"));
    out.write(g + "/temperature", T);
    out.write(g + "/temperature_component", Array{{n, dd}, temperature});
    out.write(g + "/a2", a2);
    out.write(g + "/a2_stderr", a2_err);
    out.write(g + "/a3", a3);
    out.write(g + "/a3_stderr", a3_err);
    out.write(g + "/c_bin_edges", edges);
    out.write(g + "/distribution", Array{{n, edges.size() - 1}, f});
    out.write(g + "/tail_A", tail_A);
    out.write(g + "/tail_b", tail_b);
    out.write(g + "/tail_f0", tail_f0);
    out.write(g + "/tail_bins", tail_bins);
    out.write(g + "/flow_energy_fraction", fraction);
    out.write(g + "/empty_fraction", empty);
    const std::vector<double>& r = flow->radii();
    out.write(g + "/r", r);
    out.write(g + "/C_L", Array{{n, r.size()}, C_L});
    out.write(g + "/C_T", Array{{n, r.size()}, C_T});
    out.write(g + "/length_L", length_L);
    out.write(g + "/length_T", length_T);
    out.write(g + "/enstrophy", enstrophy);
    if (c.fields) {
      std::vector<std::size_t> shape{n};
      shape.insert(shape.end(), grid_shape.begin(), grid_shape.end());
      out.write(g + "/rho_loc", Array{shape, rho});
      std::vector<std::size_t> vshape = shape;
      vshape.push_back(dd);
      out.write(g + "/flow", Array{vshape, u});
      if (const int nw = flow->vorticity_components(); nw > 0) {
        std::vector<std::size_t> wshape = shape;
        if (nw > 1) wshape.push_back(static_cast<std::size_t>(nw));
        out.write(g + "/vorticity", Array{wshape, omega});
      }
    }
    if (profile) profile->write(out, g + "/profile");
  };
  return run_structure_tool(c, "gg-velocity", "/velocity", flags, argv, per_frame, write);
}

int run_domains(const DomainsConfig& c, const CommonFlags& flags, const std::vector<std::string>& argv) {
  validate(c);
  const Phase phase = parse_phase(c.phase);
  std::vector<double> hist, length, edges;
  std::vector<std::int64_t> count;
  const auto per_frame = [&](const Frame& frame) {
    const DensityGrid& grid = frame.grid;
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

int velocity_main(int argc, char** argv, const std::string& description) {
  return structure_main(argc, argv, "gg-velocity", description, add_velocity_options, run_velocity);
}

}  // namespace gg
