// The one entry point for particle frames (gg/frames.hpp): the format told from the content, H5MD
// through read_snapshots, and what the GSD and text sources share (frames_internal.hpp).
#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "frames_internal.hpp"
#include "gg/errors.hpp"
#include "gg/gsd_file.hpp"
#include "gg/h5file.hpp"
#include "gg/provenance.hpp"
#include "gg/trajectory.hpp"

namespace gg {
namespace {

const std::string kPositions = "/particles/all/position/value";
const std::string kRadii = "/particles/all/radius/value";
const std::string kMasses = "/particles/all/mass/value";

class H5mdSource : public FrameSource {
 public:
  explicit H5mdSource(const std::string& path) : FrameSource(FrameFormat::kH5md, path), in_(path) {
    // A file with an empty series has no frame 0 to check; any other is checked (H5MD, box, shape)
    // by reading its first frame.
    if (in_.is_dataset(kPositions) && !in_.shape(kPositions).empty() && in_.shape(kPositions)[0] == 0) return;
    read_snapshots(in_, {0});
    frames_ = in_.shape(kPositions).at(0);
  }
  std::size_t frames() const override { return frames_; }
  const H5Input* h5() const override { return &in_; }

  ParticleFrame read(std::size_t k) const override {
    Snapshots s = read_snapshots(in_, {static_cast<long>(k)});
    ParticleFrame f{s.dim, std::move(s.edges), s.n_particles, s.time.at(0), s.step.at(0), std::move(s.position),
                    std::move(s.velocity), {}, {}};
    // A mixture's or aggregates' sizes (docs/DESIGN.md "Mixtures", "Aggregates").
    for (auto [dataset, values] : {std::pair{&kRadii, &f.radius}, std::pair{&kMasses, &f.mass}}) {
      if (!in_.is_dataset(*dataset)) continue;
      *values = in_.read_rows(*dataset, {k}).data;
      if (values->size() != f.n)
        throw RuntimeError("'" + in_.path() + "': " + *dataset + " does not hold one value per particle");
    }
    return f;
  }

 private:
  H5Input in_;
  std::size_t frames_ = 0;
};

// The first bytes of `path`, or "" when it cannot be read (H5Input then says why).
std::string first_bytes(const std::string& path, std::size_t count) {
  std::ifstream file(path, std::ios::binary);
  std::string bytes(count, '\0');
  file.read(bytes.data(), static_cast<std::streamsize>(count));
  bytes.resize(static_cast<std::size_t>(std::max<std::streamsize>(file.gcount(), 0)));
  return bytes;
}

bool looks_like_lammps_dump(const std::string& head) {
  const std::size_t start = head.find_first_not_of(" \t\r\n");
  return start != std::string::npos && head.compare(start, 5, "ITEM:") == 0;
}

// A count alone on the first line, then a comment line: XYZ (the box comes from Lattice=).
bool looks_like_xyz(const std::string& head) {
  std::istringstream lines(head);
  std::string first, second;
  if (!std::getline(lines, first) || !std::getline(lines, second)) return false;
  std::istringstream count(first);
  long n = -1;
  std::string rest;
  return static_cast<bool>(count >> n) && n >= 0 && !(count >> rest);
}

}  // namespace

const char* to_string(FrameFormat f) {
  switch (f) {
    case FrameFormat::kH5md: return "H5MD";
    case FrameFormat::kGsd: return "GSD (HOOMD schema)";
    case FrameFormat::kLammpsDump: return "LAMMPS text dump";
    case FrameFormat::kExtendedXyz: return "extended XYZ";
  }
  return "?";
}

std::unique_ptr<FrameSource> open_frames(const std::string& path) {
  if (path == "-") return std::make_unique<H5mdSource>(path);
  const std::string head = first_bytes(path, 4096);
  if (gsd::is_gsd(head)) return frames::open_gsd(path);
  if (looks_like_lammps_dump(head)) return frames::open_lammps_dump(path);
  if (looks_like_xyz(head)) return frames::open_extended_xyz(path);
  const std::string hdf5_signature("\x89HDF\r\n\x1a\n", 8);
  try {
    return std::make_unique<H5mdSource>(path);
  } catch (const RuntimeError&) {
    if (head.empty() || head.starts_with(hdf5_signature)) throw;  // missing, empty, or damaged HDF5: its own words
    throw RuntimeError("'" + path + "': not an HDF5 file (H5MD), nor GSD, a LAMMPS text dump or extended XYZ; give a "
                       "particle file in one of these formats");
  }
}

void require_velocities(const FrameSource& source, const ParticleFrame& frame) {
  if (frame.velocity.empty() && frame.n > 0)
    throw RuntimeError("'" + source.path() + "' (" + to_string(source.format()) + ") holds no velocities; " +
                       (source.format() == FrameFormat::kH5md ? "run gg-sim with --velocities"
                                                              : "write the velocities into the file (LAMMPS vx vy vz, "
                                                                "GSD particles/velocity, XYZ velo)"));
}

ParticleFrame read_with_velocities(const FrameSource& source, std::size_t k) {
  ParticleFrame f = source.read(k);
  require_velocities(source, f);
  return f;
}

void write_provenance(H5Output& out, const Provenance& p, const FrameSource& input) {
  if (const H5Input* in = input.h5()) return write_provenance(out, p, std::vector<const H5Input*>{in});
  write_provenance(out, p, std::vector<const H5Input*>{});
  const std::string dest = "/parameters/provenance/inputs/0";
  out.attr(dest, "file", input.path());
  out.attr(dest, "format", std::string(to_string(input.format())));
}

namespace frames {

int used_axes(const RawFrame& f) {
  const auto constant = [&f](int a) {
    for (std::size_t i = 1; i < f.n; ++i)
      if (f.position[3 * i + a] != f.position[static_cast<std::size_t>(a)]) return false;
    return true;
  };
  if (f.n < 2 || !constant(2)) return 3;
  return constant(1) ? 1 : 2;
}

ParticleFrame to_particle_frame(RawFrame&& f, int dim, const std::string& where) {
  static const char* const kAxis[] = {"x", "y", "z"};
  ParticleFrame out;
  out.dim = dim;
  out.n = f.n;
  out.time = f.time;
  out.step = f.step;
  for (int a = 0; a < dim; ++a) {
    if (!f.periodic[a])
      throw RuntimeError(where + ": the box is not periodic along " + kAxis[a] + ", where the particles move; "
                         "the analyses need a periodic box (write the file from a periodic run)");
    if (!(std::isfinite(f.edges[a]) && f.edges[a] > 0))
      throw RuntimeError(where + ": the box edge along " + kAxis[a] + " is not a positive number");
    out.edges.push_back(f.edges[a]);
  }
  const auto require_finite = [&](const std::vector<double>& values, const char* what) {
    for (double v : values)
      if (!std::isfinite(v)) throw RuntimeError(where + ": a particle's " + std::string(what) + " is not finite (NaN or inf)");
  };
  require_finite(f.position, "position");
  require_finite(f.velocity, "velocity");
  require_finite(f.radius, "radius");
  require_finite(f.mass, "mass");
  out.position.resize(f.n * static_cast<std::size_t>(dim));
  for (std::size_t i = 0; i < f.n; ++i)
    for (int a = 0; a < dim; ++a) {
      const double L = f.edges[a];
      double x = f.position[3 * i + a] - f.lower[a];
      if (x < 0 || x >= L) x -= std::floor(x / L) * L;
      if (x >= L || x < 0) x = 0;  // -1e-17 + L rounds to L; 0 is the same place
      out.position[i * dim + a] = x;
    }
  if (!f.velocity.empty()) {
    out.velocity.resize(out.position.size());
    for (std::size_t i = 0; i < f.n; ++i)
      for (int a = 0; a < dim; ++a) out.velocity[i * dim + a] = f.velocity[3 * i + a];
  }
  if (std::any_of(f.radius.begin(), f.radius.end(), [](double r) { return r != 0.5; })) out.radius = std::move(f.radius);
  out.mass = std::move(f.mass);
  return out;
}

}  // namespace frames
std::vector<long> chosen_frames(const std::vector<long>& frames, long total, const std::string& path) {
  std::vector<long> index;
  if (frames.empty()) {
    for (long k = 0; k < total; ++k) index.push_back(k);
    return index;
  }
  for (long f : frames) {
    const long k = f < 0 ? total + f : f;
    if (k < 0 || k >= total)
      throw UsageError("--frames: frame " + std::to_string(f) + " does not exist: '" + path + "' has " +
                       std::to_string(total) + " frames (0.." + std::to_string(total - 1) + ", or -" +
                       std::to_string(total) + "..-1)");
    if (const auto seen = std::find(index.begin(), index.end(), k); seen != index.end()) {
      const long earlier = frames[static_cast<std::size_t>(seen - index.begin())];
      const std::string which = earlier == f ? std::to_string(f) + " twice"
                                             : std::to_string(k) + " twice (as " + std::to_string(earlier) + " and " +
                                                   std::to_string(f) + ")";
      throw UsageError("--frames names frame " + which + "; give each frame once");
    }
    index.push_back(k);
  }
  return index;
}

}  // namespace gg
