#pragma once
// H5MD 1.1 particle files (docs/DESIGN.md "Files"): plain structs plus the reader and writer.
// Positions are [T][N][d], row-major, always held as double in memory.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace gg {
class H5Input;
class H5Output;

struct Snapshots {
  int dim = 2;
  std::vector<double> edges;               // box edge per dimension [d]
  // [d] whether the box is periodic along each axis (H5MD box `boundary`: "periodic" or "none"),
  // or empty: along every axis.
  std::vector<bool> periodic;
  std::size_t n_particles = 0;
  std::vector<double> time;                // [T]
  std::vector<std::int64_t> step;          // [T] collisions so far
  std::vector<double> position;            // [T][N][d]
  std::vector<double> velocity;            // [T][N][d] or empty
  // [T][N][d] whole numbers, or empty: the periodic image of each particle (H5MD `image`), with
  // which position + image x edges is its unwrapped position (gg-sim --unwrapped).
  std::vector<double> image;
  // [N] the species of each particle (H5MD `species`, fixed in time; a mixture of gg-sim --radii,
  // --masses), or empty: every particle species 0. Written, not read.
  std::vector<std::int64_t> species;
  // /h5md/author name; empty: h5md_author("") (the environment).
  std::string author;
  std::size_t frames() const { return time.size(); }
  const double* frame_position(std::size_t k) const { return position.data() + k * n_particles * dim; }
};

// A scalar observable sampled in time: /observables/<name>/{step,time,value}.
struct TimeSeries {
  std::vector<std::int64_t> step;
  std::vector<double> time;
  std::vector<double> value;
};

// Reads /particles/all (box with its boundary, position, velocity and image if present). `frames`
// selects frame indices (empty = all; negative counts from the end, -1 = last). Throws RuntimeError
// with a clear message if the file is not H5MD, has no positions, has the wrong rank or non-finite
// values, a boundary other than d values "periodic" or "none" (a file without one is read as
// periodic along every axis), or positions lie outside the box (coordinates within 1e-9 L of it are
// wrapped back in), or an image is not whole numbers.
// A frame index out of range is a UsageError (a bad --frames value), naming the valid range.
Snapshots read_snapshots(const H5Input& in, const std::vector<long>& frames = {});

TimeSeries read_observable(const H5Input& in, const std::string& name);

// Writes /h5md (version {1,1}, author, creator = program/version, the units module) and
// /particles/all (box with dimension, boundary per axis = "periodic" or, where s.periodic says it is
// not, "none", edges; position; velocity if non-empty; image if non-empty, its step and time hard
// links to position's; id and species, fixed in time), each element with its H5MD `unit` attribute
// in the reduced units of docs/PHYSICS.md (see kUnit*). `single_precision` stores position/velocity
// values as float32.
void write_snapshots(H5Output& out, const Snapshots& s, const std::string& program, bool single_precision = false);

// Frame k's positions (or velocities), [N][d], copied into `values`.
using FrameReader = std::function<void(std::size_t k, double* values)>;

// The same file from frames read one at a time, so that only one is in memory (gg-sim keeps its
// snapshots on disk): `s` gives the box, n_particles, time and step, and its position, velocity
// and image are not used; an empty `velocity` or `image` reader writes no velocities or images.
void write_snapshots(H5Output& out, const Snapshots& s, const FrameReader& position, const FrameReader& velocity,
                     const FrameReader& image, const std::string& program, bool single_precision = false);

// /observables/<name>; `unit` (an H5MD unit string, empty for a dimensionless value) goes on
// value, and the time unit on time. `width` values per time (an array, such as a mixture's
// temperature of each species) are written [T][width].
void write_observable(H5Output& out, const std::string& name, const TimeSeries& ts, const std::string& unit = "",
                      std::size_t width = 1);

// The author written into /h5md/author: `given` (an --author option) if not empty, else
// $GG_AUTHOR, else $USER, else "unknown".
std::string h5md_author(const std::string& given);

// H5MD unit strings (space-separated symbols with integer powers, as "nm ps-1") of the reduced
// units: sigma (the diameter), m (the mass), tau = sqrt(m sigma^2 / epsilon) with k_B = 1 and
// epsilon the energy unit of T0 (so tau = sqrt(m sigma^2 / T0) for the default T0 = 1).
inline const std::string kUnitLength = "sigma";
inline const std::string kUnitTime = "tau";
inline const std::string kUnitVelocity = "sigma tau-1";
inline const std::string kUnitEnergy = "m sigma2 tau-2";
// Pressure: energy per d-dimensional volume.
std::string pressure_unit(int dim);

}  // namespace gg
