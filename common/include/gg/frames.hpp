#pragma once
// Particle frames from any file the analyses read (docs/DESIGN.md "Frames from other codes"): H5MD
// (gg-sim's), GSD in the HOOMD schema, LAMMPS text dumps and extended XYZ, whatever program wrote
// them, told apart by their content, never by their name. open_frames() is the one entry point;
// every analysis tool reads its frames through it, one frame in memory at a time.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace gg {
class H5Input;
class H5Output;
struct Provenance;

// One snapshot in the toolkit's terms: positions in [0, L) per axis of a rectangular periodic box
// with its corner at the origin, in the file's own units of length and time.
struct ParticleFrame {
  int dim = 2;
  std::vector<double> edges;      // [dim]
  std::size_t n = 0;
  double time = 0;
  std::int64_t step = 0;
  std::vector<double> position;   // [n][dim]
  std::vector<double> velocity;   // [n][dim], or empty: the file has none
  // [n], or empty: every particle is the toolkit's default one (diameter 1, mass 1); then the density
  // grids count particles, else they weight each by its area (volume in 3D).
  std::vector<double> radius;
  std::vector<double> mass;       // [n], or empty (mass 1)
};

enum class FrameFormat { kH5md, kGsd, kLammpsDump, kExtendedXyz };
const char* to_string(FrameFormat f);

class FrameSource {
 public:
  virtual ~FrameSource() = default;
  FrameFormat format() const { return format_; }
  const std::string& path() const { return path_; }  // "<stdin>" for "-"
  virtual std::size_t frames() const = 0;
  // Frame k (0 <= k < frames()); throws RuntimeError naming the file and the frame when it lacks
  // what the analyses need (a periodic rectangular box, finite positions).
  virtual ParticleFrame read(std::size_t k) const = 0;
  // The H5MD file behind the frames, whose provenance an output copies; null for other formats.
  virtual const H5Input* h5() const { return nullptr; }

 protected:
  FrameSource(FrameFormat format, std::string path) : format_(format), path_(std::move(path)) {}

 private:
  FrameFormat format_;
  std::string path_;
};

// The frames a --frames list names, as indices 0..total-1 in its order (negative from the end, -1 the
// last), or every frame when it names none. A frame out of range or named twice (it would repeat its
// time in every output series) is a UsageError naming it and `path`'s frames.
std::vector<long> chosen_frames(const std::vector<long>& frames, long total, const std::string& path);

// Opens `path` ("-": an HDF5 file piped on stdin, as the tools' pipes carry) and recognises its
// format from its first bytes: the HDF5 signature, the GSD magic number, a line "ITEM: TIMESTEP"
// (LAMMPS) or a count line followed by a comment line with Lattice= (extended XYZ). Throws
// RuntimeError naming the file and the formats read when it is none of them.
std::unique_ptr<FrameSource> open_frames(const std::string& path);

// Frame k of `source`, with velocities: a RuntimeError naming the file and the remedy when it has none
// (require_velocities, for a frame already read).
ParticleFrame read_with_velocities(const FrameSource& source, std::size_t k);
void require_velocities(const FrameSource& source, const ParticleFrame& frame);

// write_provenance(out, p, inputs) with the frames' file as input 0: an H5MD file's provenance is
// copied; any other is named with its format under /parameters/provenance/inputs/0.
void write_provenance(H5Output& out, const Provenance& p, const FrameSource& input);

}  // namespace gg
