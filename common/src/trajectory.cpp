// H5MD 1.1 particle files (https://www.nongnu.org/h5md/h5md.html), as docs/DESIGN.md "Files" lays out.
#include "gg/trajectory.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

#include "gg/errors.hpp"
#include "gg/h5file.hpp"
#include "gg/version.hpp"

namespace gg {
namespace {

const std::string kBox = "/particles/all/box";
const std::string kPosition = "/particles/all/position";
const std::string kVelocity = "/particles/all/velocity";
const std::string kImage = "/particles/all/image";

std::string named(const H5Input& in) { return "'" + in.path() + "'"; }

// H5MD time-dependent element: step [T], time [T], value [T][N][d] written frame by frame.
void write_element(H5Output& out, const std::string& group, const Snapshots& s, const FrameReader& frame,
                   const std::string& unit, bool single_precision) {
  out.write(group + "/step", s.step);
  out.write(group + "/time", s.time);
  out.attr(group + "/time", "unit", kUnitTime);
  out.write_rows(group + "/value", {s.frames(), s.n_particles, static_cast<std::size_t>(s.dim)}, frame,
                 single_precision);
  out.attr(group + "/value", "unit", unit);
}

// image: whole numbers of box edges, no unit, with position's step and time (hard links: H5MD 1.1
// requires them to be the same datasets).
void write_image(H5Output& out, const Snapshots& s, const FrameReader& frame) {
  out.link(kPosition + "/step", kImage + "/step");
  out.link(kPosition + "/time", kImage + "/time");
  out.write_int_rows(kImage + "/value", {s.frames(), s.n_particles, static_cast<std::size_t>(s.dim)}, frame);
}

// id (the particle's number in the start, which is its row in every frame) and species (one kind
// of particle unless given), fixed in time: H5MD readers pair rows across frames by id.
void write_identity(H5Output& out, std::size_t n, const std::vector<std::int64_t>& species) {
  std::vector<std::int64_t> id(n);
  for (std::size_t i = 0; i < n; ++i) id[i] = static_cast<std::int64_t>(i);
  out.write("/particles/all/id", id);
  out.write("/particles/all/species", species.empty() ? std::vector<std::int64_t>(n, 0) : species);
}

// float32 rounds a coordinate just below L up to L or beyond; step such values back below the
// largest float under L, so files we write always pass read_snapshots' box check.
void positions_for_float(const std::vector<double>& edges, double* x, std::size_t n) {
  const std::size_t d = edges.size();
  for (std::size_t i = 0; i < n; ++i) {
    const double L = edges[i % d];
    float f = static_cast<float>(x[i]);
    while (static_cast<double>(f) >= L) f = std::nextafter(f, 0.0f);
    x[i] = f;
  }
}

// In 1D and 2D a fixed [d] dataset (the box never changes). In 3D a time-dependent element with
// position's step and time and one [d][d] matrix of box vectors per frame (diagonal: the box is
// rectangular), the form MDAnalysis's H5MD reader requires (it reads box/edges/value[frame] as three
// box vectors); box_edges() below reads every form. Without frames there is no matrix to write, and
// the fixed form holds the box.
void write_edges(H5Output& out, const Snapshots& s) {
  if (s.dim != 3 || s.frames() == 0) {
    out.write(kBox + "/edges", s.edges);
    out.attr(kBox + "/edges", "unit", kUnitLength);
    return;
  }
  const std::size_t d = s.edges.size();
  Array rows{{s.frames(), d, d}, std::vector<double>(s.frames() * d * d, 0.0)};
  for (std::size_t k = 0; k < s.frames(); ++k)
    for (std::size_t a = 0; a < d; ++a) rows.data[(k * d + a) * d + a] = s.edges[a];
  out.write(kBox + "/edges/step", s.step);
  out.write(kBox + "/edges/time", s.time);
  out.attr(kBox + "/edges/time", "unit", kUnitTime);
  out.write(kBox + "/edges/value", rows);
  out.attr(kBox + "/edges/value", "unit", kUnitLength);
}

int box_dimension(const H5Input& in) {
  const std::optional<double> d = in.attr_double(kBox, "dimension");
  if (!d) throw RuntimeError(named(in) + ": no attribute 'dimension' on " + kBox + "; not an H5MD particle file");
  if (*d != 1 && *d != 2 && *d != 3) {
    std::ostringstream given;
    given << *d;
    throw RuntimeError(named(in) + ": box dimension " + given.str() + " is invalid (1, 2 or 3)");
  }
  return static_cast<int>(*d);
}

// box/edges is either a fixed [d] dataset or, as H5MD also allows, a time-dependent element whose
// value is [T][d] edge lengths or [T][d][d] box vectors (the form MDAnalysis requires in 3D), which
// must form a diagonal matrix (a rectangular box); the box of a run never changes, so every frame's
// box must be the same.
std::vector<double> box_edges(const H5Input& in, int dim) {
  Array edges;
  if (in.exists(kBox + "/edges/value")) {
    const std::string dataset = kBox + "/edges/value";
    Array series = in.read(dataset, in.shape(dataset).size() == 3 ? 3 : 2);
    if (series.shape.size() == 3) {  // box vectors: keep the diagonal of each frame's matrix
      const std::size_t d = series.shape[1];
      if (series.shape[2] != d)
        throw RuntimeError(named(in) + ": " + dataset + " holds " + std::to_string(series.shape[1]) + " x " +
                           std::to_string(series.shape[2]) + " box vectors; H5MD wants a square matrix");
      std::vector<double> diagonal;
      for (std::size_t i = 0; i < series.data.size(); ++i) {
        const std::size_t a = i / d % d, b = i % d;
        if (a == b) diagonal.push_back(series.data[i]);
        else if (series.data[i] != 0)
          throw RuntimeError(named(in) + ": " + dataset + " is not a rectangular box (box vectors with "
                             "off-diagonal components); only rectangular periodic boxes are supported");
      }
      series.shape = {series.shape[0], d};
      series.data = std::move(diagonal);
    }
    edges.data.assign(series.data.begin(), series.data.begin() + static_cast<long>(std::min(series.data.size(), series.shape[1])));
    for (std::size_t i = 0; i < series.data.size(); ++i)
      if (series.data[i] != edges.data[i % edges.data.size()])
        throw RuntimeError(named(in) + ": " + kBox + "/edges/value changes in time; only a fixed box is supported");
  } else {
    edges = in.read(kBox + "/edges", 1);
  }
  if (edges.data.size() != static_cast<std::size_t>(dim))
    throw RuntimeError(named(in) + ": " + kBox + "/edges has " + std::to_string(edges.data.size()) +
                       " entries for a " + std::to_string(dim) + "D box");
  for (double L : edges.data)
    if (!std::isfinite(L) || L <= 0) throw RuntimeError(named(in) + ": box edge " + std::to_string(L) + " is not positive");
  return edges.data;
}

// boundary: one string per axis, "periodic" or "none" (H5MD 1.1 "Simulation box"); a file without
// it (H5MD requires it, not every writer gives it) is read as periodic along every axis.
std::vector<bool> box_boundary(const H5Input& in, int dim) {
  const std::vector<std::string> given = in.attr_strings(kBox, "boundary");
  std::vector<bool> periodic(static_cast<std::size_t>(dim), true);
  if (given.empty()) return periodic;
  const bool valid = given.size() == periodic.size() &&
                     std::all_of(given.begin(), given.end(), [](const std::string& b) { return b == "periodic" || b == "none"; });
  if (!valid)
    throw RuntimeError(named(in) + ": attribute 'boundary' of " + kBox + " must hold " + std::to_string(dim) +
                       " values, each \"periodic\" or \"none\" (H5MD)");
  for (std::size_t a = 0; a < periodic.size(); ++a) periodic[a] = given[a] == "periodic";
  return periodic;
}

// Negative indices count from the end (-1 = last); an empty selection means every frame.
std::vector<std::size_t> frame_indices(const H5Input& in, const std::vector<long>& frames, std::size_t total) {
  std::vector<std::size_t> idx;
  if (frames.empty()) {
    for (std::size_t k = 0; k < total; ++k) idx.push_back(k);
    return idx;
  }
  const long n = static_cast<long>(total);
  for (long f : frames) {
    const long k = f < 0 ? n + f : f;
    if (k < 0 || k >= n)
      throw UsageError("frame " + std::to_string(f) + " does not exist: " + named(in) + " has " + std::to_string(n) +
                       " frames (0.." + std::to_string(n - 1) + ", or -" + std::to_string(n) + "..-1)");
    idx.push_back(static_cast<std::size_t>(k));
  }
  return idx;
}

void require_finite(const H5Input& in, const std::string& dataset, const std::vector<double>& v) {
  for (std::size_t i = 0; i < v.size(); ++i)
    if (!std::isfinite(v[i]))
      throw RuntimeError(named(in) + ": " + dataset + " holds a non-finite value (NaN or inf) at element " +
                         std::to_string(i) + "; the run that wrote it went wrong, rerun it");
}

// Positions must lie in [0, L); a coordinate off by rounding (1e-9 L) is wrapped back in.
void wrap_into_box(const H5Input& in, Snapshots& s, const std::vector<std::size_t>& frames) {
  const auto d = static_cast<std::size_t>(s.dim);
  for (std::size_t i = 0; i < s.position.size(); ++i) {
    const double L = s.edges[i % d];
    double& x = s.position[i];
    if (x >= 0 && x < L) continue;
    const double tol = 1e-9 * L;
    if (x < -tol || x >= L + tol) {
      const std::size_t frame = frames[i / (d * s.n_particles)];
      throw RuntimeError(named(in) + ": particle " + std::to_string(i / d % s.n_particles) + " of frame " +
                         std::to_string(frame) + " is outside the box (coordinate " + std::to_string(x) +
                         ", edge " + std::to_string(L) + "); positions must lie in [0, L)");
    }
    x = x < 0 ? x + L : x - L;
    if (x >= L || x < 0) x = 0;  // -1e-17 + L rounds to L; 0 is the same place
  }
}

std::vector<double> read_time(const H5Input& in, const std::string& group, std::size_t frames) {
  const Array time = in.read(group + "/time", 1);
  if (time.data.size() != frames)
    throw RuntimeError(named(in) + ": " + group + "/time has " + std::to_string(time.data.size()) + " entries but " +
                       group + "/value has " + std::to_string(frames) + " frames");
  require_finite(in, group + "/time", time.data);
  return time.data;
}

}  // namespace

Snapshots read_snapshots(const H5Input& in, const std::vector<long>& frames) {
  if (!in.exists("/h5md"))
    throw RuntimeError(named(in) + ": not an H5MD file (no /h5md group); give a particle file written by gg-sim");
  if (!in.is_dataset(kPosition + "/value"))
    throw RuntimeError(named(in) + ": no particle positions (" + kPosition + "/value); give a gg-sim output with snapshots");
  Snapshots s;
  s.dim = box_dimension(in);
  s.edges = box_edges(in, s.dim);
  s.periodic = box_boundary(in, s.dim);
  const std::vector<std::size_t> shape = in.shape(kPosition + "/value");
  if (shape.size() != 3 || shape[2] != static_cast<std::size_t>(s.dim))
    throw RuntimeError(named(in) + ": " + kPosition + "/value must be [frames][particles][" + std::to_string(s.dim) +
                       "] for a " + std::to_string(s.dim) + "D box, but has rank " + std::to_string(shape.size()) +
                       (shape.size() == 3 ? " and last dimension " + std::to_string(shape[2]) : std::string()));
  s.n_particles = shape[1];
  const std::vector<double> all_time = read_time(in, kPosition, shape[0]);
  const std::vector<std::int64_t> all_step = in.read_int(kPosition + "/step");
  if (all_step.size() != shape[0])
    throw RuntimeError(named(in) + ": " + kPosition + "/step has " + std::to_string(all_step.size()) +
                       " entries for " + std::to_string(shape[0]) + " frames");

  const std::vector<std::size_t> idx = frame_indices(in, frames, shape[0]);
  for (std::size_t k : idx) {
    s.time.push_back(all_time[k]);
    s.step.push_back(all_step[k]);
  }
  s.position = in.read_rows(kPosition + "/value", idx).data;
  require_finite(in, kPosition + "/value", s.position);
  wrap_into_box(in, s, idx);

  if (in.exists(kVelocity + "/value")) {
    if (in.shape(kVelocity + "/value") != shape)
      throw RuntimeError(named(in) + ": " + kVelocity + "/value and " + kPosition + "/value differ in shape");
    s.velocity = in.read_rows(kVelocity + "/value", idx).data;
    require_finite(in, kVelocity + "/value", s.velocity);
  }
  if (in.exists(kImage + "/value")) {
    if (in.shape(kImage + "/value") != shape)
      throw RuntimeError(named(in) + ": " + kImage + "/value and " + kPosition + "/value differ in shape");
    s.image = in.read_rows(kImage + "/value", idx).data;
    for (double a : s.image)
      if (a != std::trunc(a))  // NaN too
        throw RuntimeError(named(in) + ": " + kImage + "/value holds " + std::to_string(a) +
                           ", not a whole number of box edges; the file is damaged");
  }
  return s;
}

TimeSeries read_observable(const H5Input& in, const std::string& name) {
  const std::string group = "/observables/" + name;
  if (!in.exists(group + "/value"))
    throw RuntimeError(named(in) + ": no observable '" + name + "' (" + group + "/value); was it asked for in the run?");
  TimeSeries ts;
  ts.value = in.read(group + "/value", 1).data;
  ts.time = read_time(in, group, ts.value.size());
  ts.step = in.read_int(group + "/step");
  if (ts.step.size() != ts.value.size())
    throw RuntimeError(named(in) + ": " + group + "/step and " + group + "/value differ in length");
  return ts;
}

void write_snapshots(H5Output& out, const Snapshots& s, const std::string& program, bool single_precision) {
  const std::size_t per_frame = s.n_particles * static_cast<std::size_t>(s.dim);
  if (s.position.size() != s.frames() * per_frame || (!s.velocity.empty() && s.velocity.size() != s.position.size()) ||
      (!s.image.empty() && s.image.size() != s.position.size()))
    throw std::invalid_argument("write_snapshots: inconsistent Snapshots (position, velocity, image)");
  const auto frames_of = [per_frame](const std::vector<double>& a) -> FrameReader {
    return [&a, per_frame](std::size_t k, double* values) {
      std::copy_n(a.data() + k * per_frame, per_frame, values);
    };
  };
  write_snapshots(out, s, frames_of(s.position), s.velocity.empty() ? FrameReader() : frames_of(s.velocity),
                  s.image.empty() ? FrameReader() : frames_of(s.image), program, single_precision);
}

void write_snapshots(H5Output& out, const Snapshots& s, const FrameReader& position, const FrameReader& velocity,
                     const FrameReader& image, const std::string& program, bool single_precision) {
  const auto d = static_cast<std::size_t>(s.dim);
  if (s.dim < 1 || s.dim > 3 || s.edges.size() != d || (!s.periodic.empty() && s.periodic.size() != d) ||
      s.step.size() != s.frames())
    throw std::invalid_argument("write_snapshots: inconsistent Snapshots (dim, edges, periodic, step, time)");

  out.attr("/h5md", "version", std::vector<std::int64_t>{1, 1});
  out.attr("/h5md/author", "name", s.author.empty() ? h5md_author("") : s.author);
  out.attr("/h5md/creator", "name", program);
  out.attr("/h5md/creator", "version", std::string(kVersion));
  // The units module (H5MD 1.1 "Units"): every element with a unit carries a `unit` attribute.
  out.attr("/h5md/modules/units", "version", std::vector<std::int64_t>{1, 0});
  out.attr("/h5md/modules/units", "system",
           std::string("reduced: sigma = particle diameter, m = particle mass, k_B = 1, tau = sqrt(m sigma^2 / "
                       "epsilon) with epsilon the energy unit in which T0 is given (tau = sqrt(m sigma^2 / T0) "
                       "for the default T0 = 1)"));

  out.attr(kBox, "dimension", s.dim);
  std::vector<std::string> boundary(d, "periodic");
  for (std::size_t a = 0; a < s.periodic.size(); ++a)
    if (!s.periodic[a]) boundary[a] = "none";
  out.attr(kBox, "boundary", boundary);
  write_edges(out, s);
  write_identity(out, s.n_particles, s.species);

  const std::size_t per_frame = s.n_particles * d;
  const FrameReader float_position = [&](std::size_t k, double* values) {
    position(k, values);
    positions_for_float(s.edges, values, per_frame);
  };
  write_element(out, kPosition, s, single_precision ? float_position : position, kUnitLength, single_precision);
  if (velocity) write_element(out, kVelocity, s, velocity, kUnitVelocity, single_precision);
  if (image) write_image(out, s, image);
}

void write_observable(H5Output& out, const std::string& name, const TimeSeries& ts, const std::string& unit,
                      std::size_t width) {
  if (ts.step.size() != ts.time.size() || ts.time.size() * width != ts.value.size())
    throw std::invalid_argument("write_observable " + name + ": step, time and value differ in length");
  const std::string group = "/observables/" + name;
  out.write(group + "/step", ts.step);
  out.write(group + "/time", ts.time);
  out.attr(group + "/time", "unit", kUnitTime);
  if (width == 1) out.write(group + "/value", ts.value);
  else out.write(group + "/value", Array{{ts.time.size(), width}, ts.value});
  if (!unit.empty()) out.attr(group + "/value", "unit", unit);
}

std::string h5md_author(const std::string& given) {
  if (!given.empty()) return given;
  for (const char* variable : {"GG_AUTHOR", "USER"})
    if (const char* v = std::getenv(variable); v && *v) return v;
  return "unknown";
}

// Energy per d-dimensional volume: m sigma^(2 - d) tau^-2.
std::string pressure_unit(int dim) {
  if (dim == 2) return "m tau-2";
  return dim == 1 ? "m sigma tau-2" : "m sigma" + std::to_string(2 - dim) + " tau-2";
}

}  // namespace gg
