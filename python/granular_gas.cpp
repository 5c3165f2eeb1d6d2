// The Python module granular_gas: the toolkit's C++ libraries on numpy arrays (pybind11). Frames of
// any format the tools read (gg/frames.hpp), the coarse-grained density (gg/density_grid.hpp), clusters,
// C(r) and domains (analyze/structure) and the fits (analyze/fit), with the definitions of
// docs/DESIGN.md: the numbers are the command-line tools' own.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <memory>
#include <optional>
#include <string>

#include "cluster.hpp"
#include "correlation.hpp"
#include "domains.hpp"
#include "velocity.hpp"
#include "fit/power_law.hpp"
#include "gg/density_grid.hpp"
#include "gg/errors.hpp"
#include "gg/frames.hpp"
#include "gg/particle_volume.hpp"

namespace py = pybind11;

namespace {

using Doubles = py::array_t<double, py::array::c_style | py::array::forcecast>;

py::array_t<double> to_array(const std::vector<double>& v, std::vector<py::ssize_t> shape) {
  py::array_t<double> out(shape);
  std::copy(v.begin(), v.end(), out.mutable_data());
  return out;
}

py::object optional_array(const std::vector<double>& v, std::vector<py::ssize_t> shape) {
  if (v.empty()) return py::none();
  return to_array(v, std::move(shape));
}

// The grid's shape as numpy wants it: cells per side, the last axis fastest.
std::vector<py::ssize_t> grid_shape(const gg::DensityGrid& grid) {
  return {grid.cells_per_side().begin(), grid.cells_per_side().end()};
}

// Positions [N][d], the box [d] and optional radii [N], checked, as a density grid of `grain`.
gg::DensityGrid coarse_grain(const Doubles& position, const Doubles& box, const gg::CoarseGrain& grain,
                             const std::optional<Doubles>& radius) {
  if (box.ndim() != 1 || box.shape(0) < 1 || box.shape(0) > 3)
    throw py::value_error("box must be the d box edges (1 <= d <= 3), a 1-D array");
  const auto d = box.shape(0);
  if (position.ndim() != 2 || position.shape(1) != d)
    throw py::value_error("position must be an N x " + std::to_string(d) + " array for a box of " +
                          std::to_string(d) + " edges");
  const std::vector<double> edges(box.data(), box.data() + d);
  gg::DensityGrid grid(edges, grain);
  const auto n = static_cast<std::size_t>(position.shape(0));
  std::vector<double> weights;
  if (radius) {
    if (radius->ndim() != 1 || static_cast<std::size_t>(radius->shape(0)) != n)
      throw py::value_error("radius must hold one radius per particle");
    for (std::size_t i = 0; i < n; ++i) weights.push_back(gg::particle_volume(radius->data()[i], static_cast<int>(d)));
  }
  grid.assign(position.data(), n, radius ? weights.data() : nullptr);
  return grid;
}

struct Field {
  py::array_t<double> rho;
  py::array_t<std::int8_t> psi;
  py::array_t<std::int32_t> counts;
  std::vector<double> spacing;
};

struct Clusters {
  double mean_mass, weight_mass;
  std::int64_t count, largest;
  double largest_share, largest_share_of_clustered, rest_mean_mass;
  py::array_t<std::int32_t> wraps;
  py::array_t<std::int64_t> masses;
  py::array_t<std::int32_t> cluster_wraps;
  py::array_t<std::int32_t> labels;
  py::array_t<std::int32_t> cluster_idx;
};

// Cluster::wraps bits as 0/1 per axis (gg-cluster's /cluster/wraps row).
void put_wraps(std::uint8_t bits, int dim, std::int32_t* out) {
  for (int a = 0; a < dim; ++a) out[a] = (bits >> a) & 1u;
}

struct Correlation {
  py::array_t<double> r, C;
  double length;
  py::array_t<double> k, S;
  double k1;
};

struct Domains {
  double length;
  std::int64_t count;
  py::array_t<double> histogram, bin_edges;
};

template <class T>
py::array_t<T> grid_array(const std::vector<T>& values, const gg::DensityGrid& grid) {
  py::array_t<T> out(grid_shape(grid));
  std::copy(values.begin(), values.end(), out.mutable_data());
  return out;
}

gg::Connectivity connectivity_of(int connectivity, int dim) {
  const int faces = 2 * dim, full = dim == 1 ? 2 : dim == 2 ? 8 : 26;
  if (connectivity == 0 || connectivity == faces || dim == 1) return gg::Connectivity::face;
  if (connectivity == full) return gg::Connectivity::full;
  throw py::value_error("connectivity " + std::to_string(connectivity) + " does not fit a " + std::to_string(dim) +
                        "D grid: give " + std::to_string(faces) + " (faces) or " + std::to_string(full) +
                        " (faces, edges and corners)");
}

gg::fit::Series series(const Doubles& t, const Doubles& y, const std::optional<Doubles>& err) {
  if (t.ndim() != 1 || y.ndim() != 1 || t.shape(0) != y.shape(0))
    throw py::value_error("t and y must be 1-D arrays of the same length");
  gg::fit::Series s{{t.data(), t.data() + t.shape(0)}, {y.data(), y.data() + y.shape(0)}, {}};
  if (err) {
    if (err->ndim() != 1 || err->shape(0) != t.shape(0)) throw py::value_error("err must match t and y");
    s.err.assign(err->data(), err->data() + err->shape(0));
  }
  return s;
}

const char* const kGridArgs =
    "position: N x d array of particle centres; box: the d edges of the periodic box (positions outside "
    "it are wrapped in). grid: target cell spacing (n = max(1, round(L/grid)) cells per side); coarse: w, "
    "rho_loc of a cell = particles in the (2w+1)^d block around it / the block's volume; rho_c: psi = +1 "
    "where rho_loc > rho_c; radius: optional N radii, then particles are weighted by their area (volume in "
    "3D) and rho_loc is the local packing fraction. The same coarse-graining as gg-cluster, gg-correlate "
    "and gg-domains (--grid, --coarse, --rho-c).";

std::string with_grid_args(const std::string& what) { return what + "\n\n" + kGridArgs; }

}  // namespace

PYBIND11_MODULE(granular_gas, m) {
  m.doc() =
      "The granular-gas toolkit's analyses on numpy arrays: read frames of H5MD (gg-sim), GSD (HOOMD), LAMMPS "
      "text dumps and extended XYZ (read_frames, Trajectory); coarse-grain (density), clusters, the "
      "correlation C(r) with S(k), domains and velocity statistics of one configuration; power-law fits and the local exponent of a "
      "time series. The numbers are those of the command-line tools (gg-cluster, gg-correlate, gg-domains, "
      "gg-fit), computed by the same C++ code.";

  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const gg::UsageError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const gg::RuntimeError& e) {
      PyErr_SetString(PyExc_OSError, e.what());
    }
  });

  py::class_<gg::ParticleFrame>(m, "Frame",
                                "One snapshot: positions in [0, L) of a rectangular periodic box with its corner at "
                                "the origin, in the file's units.")
      .def_readonly("dim", &gg::ParticleFrame::dim, "dimension d (1, 2 or 3)")
      .def_readonly("n", &gg::ParticleFrame::n, "number of particles N")
      .def_readonly("time", &gg::ParticleFrame::time, "simulated time (a GSD or XYZ file without one: its step)")
      .def_readonly("step", &gg::ParticleFrame::step, "step (gg-sim: collisions so far)")
      .def_property_readonly("box", [](const gg::ParticleFrame& f) { return to_array(f.edges, {f.dim}); },
                             "box edges [d]")
      .def_property_readonly(
          "position", [](const gg::ParticleFrame& f) { return to_array(f.position, {static_cast<py::ssize_t>(f.n), f.dim}); },
          "positions [N][d]; a LAMMPS dump's rows sorted by atom id")
      .def_property_readonly(
          "velocity",
          [](const gg::ParticleFrame& f) { return optional_array(f.velocity, {static_cast<py::ssize_t>(f.n), f.dim}); },
          "velocities [N][d], or None")
      .def_property_readonly(
          "radius", [](const gg::ParticleFrame& f) { return optional_array(f.radius, {static_cast<py::ssize_t>(f.n)}); },
          "radii [N], or None: every particle of diameter 1, counted rather than weighted by area")
      .def_property_readonly(
          "mass", [](const gg::ParticleFrame& f) { return optional_array(f.mass, {static_cast<py::ssize_t>(f.n)}); },
          "masses [N], or None (mass 1)")
      .def("__repr__", [](const gg::ParticleFrame& f) {
        return "<Frame " + std::to_string(f.dim) + "D, " + std::to_string(f.n) + " particles, time " +
               std::to_string(f.time) + ">";
      });

  py::class_<gg::FrameSource, std::shared_ptr<gg::FrameSource>>(
      m, "Trajectory",
      "The frames of a particle file, read one at a time: H5MD (gg-sim), GSD (HOOMD schema), a LAMMPS text dump "
      "or extended XYZ, told apart by content. len(t) frames; t[k] is frame k (negative from the end).")
      .def(py::init([](const std::string& path) { return std::shared_ptr<gg::FrameSource>(gg::open_frames(path)); }),
           py::arg("path"))
      .def_property_readonly("format", [](const gg::FrameSource& s) { return std::string(gg::to_string(s.format())); },
                             "the format recognised: 'H5MD', 'GSD (HOOMD schema)', 'LAMMPS text dump', 'extended XYZ'")
      .def_property_readonly("path", &gg::FrameSource::path)
      .def("__len__", &gg::FrameSource::frames)
      .def("__getitem__", [](const gg::FrameSource& s, long k) {
        const long n = static_cast<long>(s.frames());
        if (k < -n || k >= n) throw py::index_error("frame " + std::to_string(k) + " of " + std::to_string(n));
        return s.read(static_cast<std::size_t>(k < 0 ? k + n : k));
      });

  m.def(
      "read_frames",
      [](const std::string& path, std::optional<std::vector<long>> frames) {
        const std::unique_ptr<gg::FrameSource> s = gg::open_frames(path);
        const long n = static_cast<long>(s->frames());
        std::vector<gg::ParticleFrame> out;
        if (!frames) {
          for (long k = 0; k < n; ++k) out.push_back(s->read(static_cast<std::size_t>(k)));
          return out;
        }
        for (long k : *frames) {
          if (k < -n || k >= n) throw py::index_error("frame " + std::to_string(k) + " of " + std::to_string(n));
          out.push_back(s->read(static_cast<std::size_t>(k < 0 ? k + n : k)));
        }
        return out;
      },
      py::arg("path"), py::arg("frames") = py::none(),
      "The frames of a particle file (all, or the listed indices, negative from the end) as a list of Frame.");

  py::class_<Field>(m, "Density", "A coarse-grained configuration: arrays of the grid's shape (cells per side).")
      .def_readonly("rho", &Field::rho, "rho_loc of each cell")
      .def_readonly("psi", &Field::psi, "order parameter: +1 where rho_loc > rho_c, else -1")
      .def_readonly("counts", &Field::counts, "particles whose centre lies in each cell")
      .def_readonly("spacing", &Field::spacing, "cell spacing per axis");
  m.def(
      "density",
      [](const Doubles& position, const Doubles& box, double grid, int coarse, double rho_c,
         std::optional<Doubles> radius) {
        const gg::DensityGrid g = coarse_grain(position, box, {grid, coarse, rho_c}, radius);
        std::vector<double> rho(g.size());
        for (std::size_t c = 0; c < g.size(); ++c) rho[c] = g.rho_loc(c);
        return Field{grid_array(rho, g), grid_array(g.psi(), g), grid_array(g.counts(), g), g.spacing()};
      },
      py::arg("position"), py::arg("box"), py::arg("grid") = 1.0, py::arg("coarse") = 1, py::arg("rho_c") = 0.5,
      py::arg("radius") = py::none(), with_grid_args("The coarse-grained density and order parameter.").c_str());

  py::class_<Clusters>(m, "Clusters", "Clusters of the psi = +1 cells (gg-cluster's numbers for one frame).")
      .def_readonly("mean_mass", &Clusters::mean_mass, "number-average mass m (clusters of mass >= min_size; NaN if none)")
      .def_readonly("weight_mass", &Clusters::weight_mass, "weight-average mass sum m^2 / sum m")
      .def_readonly("count", &Clusters::count, "clusters of mass >= min_size")
      .def_readonly("largest", &Clusters::largest, "largest mass")
      .def_readonly("largest_share", &Clusters::largest_share,
                    "largest / N, the largest cluster's share of all particles (0 with no cluster)")
      .def_readonly("largest_share_of_clustered", &Clusters::largest_share_of_clustered,
                    "largest / the particles in clusters of mass >= min_size (NaN with no cluster)")
      .def_readonly("rest_mean_mass", &Clusters::rest_mean_mass,
                    "number-average mass of the clusters of mass >= min_size other than the largest (NaN if none)")
      .def_readonly("wraps", &Clusters::wraps,
                    "[d] 1 where the largest cluster wraps the periodic box along the axis (a path through it "
                    "winds around the box; touching a face is not wrapping), else 0")
      .def_readonly("masses", &Clusters::masses,
                    "every cluster's mass (particles), largest first, ties by the smallest cell index")
      .def_readonly("cluster_wraps", &Clusters::cluster_wraps, "[clusters][d] wraps of every cluster, in the order of masses")
      .def_readonly("labels", &Clusters::labels, "per cell: index into masses, -1 for psi = -1 cells")
      .def_readonly("cluster_idx", &Clusters::cluster_idx,
                    "per particle: index into masses of the cluster holding its cell (0 = the largest, as freud's "
                    "cluster_idx), -1 for a particle in a psi = -1 cell")
      .def("__repr__", [](const Clusters& c) {
        return "<Clusters count=" + std::to_string(c.count) + " mean_mass=" + std::to_string(c.mean_mass) +
               " largest=" + std::to_string(c.largest) + ">";
      });
  m.def(
      "clusters",
      [](const Doubles& position, const Doubles& box, double grid, int coarse, double rho_c,
         std::optional<Doubles> radius, int connectivity, std::int64_t min_size) {
        const gg::DensityGrid g = coarse_grain(position, box, {grid, coarse, rho_c}, radius);
        const gg::ClusterResult r = gg::find_clusters(g, connectivity_of(connectivity, g.dim()));
        const gg::ClusterStats s = gg::summarize(r.clusters, min_size);
        const gg::GiantCluster giant =
            gg::giant_cluster(r.clusters, static_cast<std::int64_t>(g.n_particles()), min_size);
        const auto n_clusters = static_cast<py::ssize_t>(r.clusters.size());
        py::array_t<std::int64_t> masses(n_clusters);
        py::array_t<std::int32_t> cluster_wraps({n_clusters, static_cast<py::ssize_t>(g.dim())});
        for (std::size_t i = 0; i < r.clusters.size(); ++i) {
          masses.mutable_data()[i] = r.clusters[i].mass;
          put_wraps(r.clusters[i].wraps, g.dim(), cluster_wraps.mutable_data() + i * g.dim());
        }
        py::array_t<std::int32_t> wraps(g.dim());
        put_wraps(giant.wraps, g.dim(), wraps.mutable_data());
        const auto idx = gg::particle_clusters(g, r, position.data(), g.n_particles());
        py::array_t<std::int32_t> cluster_idx(static_cast<py::ssize_t>(idx.size()));
        std::copy(idx.begin(), idx.end(), cluster_idx.mutable_data());
        return Clusters{s.mean_mass, s.weight_mass, s.count, s.largest, giant.share, giant.share_of_clustered,
                        giant.rest_mean_mass, wraps, masses, cluster_wraps, grid_array(r.label, g), cluster_idx};
      },
      py::arg("position"), py::arg("box"), py::arg("grid") = 1.0, py::arg("coarse") = 1, py::arg("rho_c") = 0.5,
      py::arg("radius") = py::none(), py::arg("connectivity") = 0, py::arg("min_size") = 1,
      with_grid_args("Clusters of the coarse-grained density (docs/DESIGN.md \"Cluster\"), the largest one "
                     "against the rest and whether it wraps the box, and each particle's cluster. connectivity: 0 "
                     "or 4 (6 in 3D) for cells sharing a face, 8 (26) also edges and corners; min_size: clusters "
                     "lighter than this are left out of the statistics (not of masses, labels and cluster_idx).")
          .c_str());

  py::class_<Correlation>(m, "Correlation", "C(r) of the order parameter (gg-correlate's numbers for one frame).")
      .def_readonly("r", &Correlation::r, "shell radii")
      .def_readonly("C", &Correlation::C, "C(r) = C_o(r) / C_o(0), C(0) = 1 (NaN if psi is uniform)")
      .def_readonly("length", &Correlation::length, "l_C: the first r where C falls to a (NaN if never)")
      .def_readonly("k", &Correlation::k, "wave numbers of the shells of S")
      .def_readonly("S", &Correlation::S, "structure factor of psi, |FFT(psi - <psi>)|^2 / cells per shell")
      .def_readonly("k1", &Correlation::k1, "first moment of S over k > 0");
  m.def(
      "correlation",
      [](const Doubles& position, const Doubles& box, double grid, int coarse, double rho_c,
         std::optional<Doubles> radius, double a) {
        if (!(a > -1 && a < 1)) throw py::value_error("a must lie between -1 and 1");
        const gg::DensityGrid g = coarse_grain(position, box, {grid, coarse, rho_c}, radius);
        gg::Correlator correlator(g);
        const gg::CorrelationResult r = correlator.compute(g, a);
        const auto n = static_cast<py::ssize_t>(r.r.size()), nk = static_cast<py::ssize_t>(r.S.size());
        return Correlation{to_array(r.r, {n}), to_array(r.C, {n}), r.length,
                           to_array(correlator.wave_numbers(), {nk}), to_array(r.S, {nk}), r.k1};
      },
      py::arg("position"), py::arg("box"), py::arg("grid") = 1.0, py::arg("coarse") = 1, py::arg("rho_c") = 0.5,
      py::arg("radius") = py::none(), py::arg("a") = 0.5,
      with_grid_args("The order parameter's correlation C(r) by FFT, shell-averaged (paper eq. 8), its length "
                     "l_C where C first falls to a, and the structure factor S(k) with its first moment k1 "
                     "(gg-correlate's numbers).")
          .c_str());

  py::class_<Domains>(m, "Domains", "Domain lengths along the grid's lines (gg-domains' numbers for one frame).")
      .def_readonly("length", &Domains::length, "mean domain length l (first moment of P; NaN if none)")
      .def_readonly("count", &Domains::count, "domains counted")
      .def_readonly("histogram", &Domains::histogram, "P(l_d), a density")
      .def_readonly("bin_edges", &Domains::bin_edges, "its bin edges");
  m.def(
      "domains",
      [](const Doubles& position, const Doubles& box, double grid, int coarse, double rho_c,
         std::optional<Doubles> radius, const std::string& phase) {
        const gg::DensityGrid g = coarse_grain(position, box, {grid, coarse, rho_c}, radius);
        const gg::DomainResult r = gg::measure_domains(g, gg::parse_phase(phase));
        return Domains{r.length, r.count, to_array(r.histogram, {static_cast<py::ssize_t>(r.histogram.size())}),
                       to_array(r.bin_edges, {static_cast<py::ssize_t>(r.bin_edges.size())})};
      },
      py::arg("position"), py::arg("box"), py::arg("grid") = 1.0, py::arg("coarse") = 1, py::arg("rho_c") = 0.5,
      py::arg("radius") = py::none(), py::arg("phase") = "both",
      with_grid_args("Domain lengths between sign changes of psi along every grid line (paper eq. 10); phase: "
                     "'both', 'rich' (psi = +1) or 'poor'.")
          .c_str());

  py::class_<gg::SonineResult>(m, "VelocityStatistics", "Temperature and Sonine coefficients (gg-velocity's numbers).")
      .def_readonly("T", &gg::SonineResult::T, "temperature, the mean of the components")
      .def_readonly("temperature", &gg::SonineResult::temperature, "T per component, sum m (v_k - V_k)^2 / N")
      .def_readonly("a2", &gg::SonineResult::a2, "a2 = d/(d+2) <w^2>/<w>^2 - 1, w = m |v - V|^2")
      .def_readonly("a2_stderr", &gg::SonineResult::a2_stderr)
      .def_readonly("a3", &gg::SonineResult::a3)
      .def_readonly("a3_stderr", &gg::SonineResult::a3_stderr);
  m.def(
      "velocity_statistics",
      [](const Doubles& velocity, std::optional<Doubles> mass) {
        if (velocity.ndim() != 2 || velocity.shape(1) < 1 || velocity.shape(1) > 3)
          throw py::value_error("velocity must be an N x d array, 1 <= d <= 3");
        const auto n = static_cast<std::size_t>(velocity.shape(0));
        if (mass && (mass->ndim() != 1 || static_cast<std::size_t>(mass->shape(0)) != n))
          throw py::value_error("mass must hold one mass per particle");
        return gg::sonine_coefficients(velocity.data(), mass ? mass->data() : nullptr, n,
                                       static_cast<int>(velocity.shape(1)));
      },
      py::arg("velocity"), py::arg("mass") = py::none(),
      "The temperature and the Sonine coefficients a2, a3 of N x d velocities relative to the centre-of-mass "
      "velocity (masses 1 unless given).");

  py::class_<gg::fit::PowerLawFit>(m, "PowerLawFit", "y = A t^z (or y0 + A t^z) fitted over a window (gg-fit power-law).")
      .def_readonly("exponent", &gg::fit::PowerLawFit::exponent)
      .def_readonly("exponent_stderr", &gg::fit::PowerLawFit::exponent_stderr)
      .def_readonly("amplitude", &gg::fit::PowerLawFit::amplitude, "A, the value at t = 1")
      .def_readonly("amplitude_stderr", &gg::fit::PowerLawFit::amplitude_stderr)
      .def_readonly("offset", &gg::fit::PowerLawFit::offset, "y0 (offset=True only)")
      .def_readonly("offset_stderr", &gg::fit::PowerLawFit::offset_stderr)
      .def_readonly("chi2_dof", &gg::fit::PowerLawFit::chi2_dof, "residual variance of ln y, or chi2/dof when weighted")
      .def_readonly("points", &gg::fit::PowerLawFit::points, "samples used")
      .def("__repr__", [](const gg::fit::PowerLawFit& f) {
        return "<PowerLawFit z=" + std::to_string(f.exponent) + " +/- " + std::to_string(f.exponent_stderr) +
               " A=" + std::to_string(f.amplitude) + ">";
      });
  m.def(
      "fit_power_law",
      [](const Doubles& t, const Doubles& y, std::pair<double, double> window, std::optional<Doubles> err, bool offset) {
        const gg::fit::Series s = series(t, y, err);
        const gg::fit::Window w{window.first, window.second};
        return offset ? gg::fit::fit_power_law_offset(s, w) : gg::fit::fit_power_law(s, w);
      },
      py::arg("t"), py::arg("y"), py::arg("window"), py::arg("err") = py::none(), py::arg("offset") = false,
      "Least squares of ln y = ln A + z ln t over t in window = (t1, t2) (at least 3 samples, y > 0), weighted "
      "by err / y when err (standard errors) is given; offset=True fits y = y0 + A t^z instead. The numbers of "
      "gg-fit power-law.");

  py::class_<gg::fit::LocalExponent>(m, "LocalExponent", "d ln y / d ln t at each time (gg-fit local-exponent).")
      .def_property_readonly("t", [](const gg::fit::LocalExponent& z) { return to_array(z.t, {static_cast<py::ssize_t>(z.t.size())}); })
      .def_property_readonly("exponent", [](const gg::fit::LocalExponent& z) {
        return to_array(z.exponent, {static_cast<py::ssize_t>(z.exponent.size())});
      })
      .def_property_readonly("err", [](const gg::fit::LocalExponent& z) { return to_array(z.err, {static_cast<py::ssize_t>(z.err.size())}); },
                             "standard error of each exponent");
  m.def(
      "local_exponent",
      [](const Doubles& t, const Doubles& y, double decades, std::optional<Doubles> err) {
        return gg::fit::local_exponent(series(t, y, err), decades);
      },
      py::arg("t"), py::arg("y"), py::arg("decades") = 0.5, py::arg("err") = py::none(),
      "The local exponent z(t_i) = d ln y / d ln t: a fit of ln y on ln t over the samples within +- decades/2 "
      "(in log10 t) of each t_i; only times whose whole window lies inside the data and holds >= 3 samples.");
}
