#pragma once
// What the frame sources of common/src/frames*.cpp share: the GSD and text formats hold three axes
// whatever the system's dimension; RawFrame is a frame as they hold it, and to_particle_frame makes
// it a ParticleFrame of the axes the system uses.
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "gg/frames.hpp"

namespace gg::frames {

struct RawFrame {
  std::array<double, 3> lower{0, 0, 0};  // the box's lower corner
  std::array<double, 3> edges{0, 0, 0};
  std::array<bool, 3> periodic{true, true, true};
  std::size_t n = 0;
  double time = 0;
  std::int64_t step = 0;
  std::vector<double> position;  // [n][3]
  std::vector<double> velocity;  // [n][3] or empty
  std::vector<double> radius;    // [n] or empty
  std::vector<double> mass;      // [n] or empty
};

// The axes a system uses: 3, or 2 when every particle has the same z (a 2D run, as LAMMPS and
// extended XYZ hold it), or 1 when y is the same too.
int used_axes(const RawFrame& f);

// The first `dim` axes of `f` as a ParticleFrame: `where` ("'run.dump' frame 3") heads the one-line
// RuntimeError for an axis in use that is not periodic, a box edge that is not positive, or a value
// that is not finite. Positions are wrapped into [0, L) from the lower corner (unwrapped coordinates
// are welcome); radii that are all 1/2 are dropped (the default particle, counted rather than weighted).
ParticleFrame to_particle_frame(RawFrame&& f, int dim, const std::string& where);

std::unique_ptr<FrameSource> open_gsd(const std::string& path);
std::unique_ptr<FrameSource> open_lammps_dump(const std::string& path);
std::unique_ptr<FrameSource> open_extended_xyz(const std::string& path);

}  // namespace gg::frames
