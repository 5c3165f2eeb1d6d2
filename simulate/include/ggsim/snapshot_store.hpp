#pragma once
// The snapshots of a run, kept on disk until the output is written: a run's memory must not grow
// with the number of snapshots (16 bytes per disk and frame in 2D, 32 with velocities; 20 frames of
// 1e7 disks would be 3.2 GB on top of the engine's ~110 bytes per disk). Frame times and steps are
// small and stay in memory.
#include <cstdint>
#include <string>
#include <vector>

#include <sys/types.h>  // off_t

#include "gg/scratch_file.hpp"
#include "gg/trajectory.hpp"

namespace ggsim {

// What a frame holds beyond positions.
struct SnapshotFields {
  bool velocities = false;
  bool images = false;  // periodic images, integers kept as doubles (gg-sim --unwrapped)
  bool sizes = false;   // a mass and a radius per particle (aggregates, aggregation.hpp)
  bool spins = false;   // angular velocities of rough particles (one component in 2D, three in 3D)
};

// One frame's values, by particle number; those not kept may be null.
struct FrameValues {
  const double* position;
  const double* velocity = nullptr;
  const double* image = nullptr;
  const double* mass = nullptr;
  const double* radius = nullptr;
  const double* spin = nullptr;
};

class SnapshotStore {
 public:
  // Frames of n particles in `dim` dimensions (with the fields asked for) for a run that writes
  // `output`: they go to a temporary file in the output's directory, or in $TMPDIR (else /tmp) for
  // "-". Throws gg::UsageError if that directory is missing or not writable, gg::RuntimeError for
  // other failures, naming the directory.
  SnapshotStore(const std::string& output, std::size_t n, int dim, const std::vector<double>& edges,
                const SnapshotFields& fields);

  // One frame: positions, and the fields kept (velocities, images, masses, radii, spins), each by
  // particle number ([N][d], masses and radii [N], spins as spins()). Throws gg::RuntimeError naming the file if
  // the disk is full.
  void append(double time, std::int64_t step, const FrameValues& values);

  // Box, particle count, and the time and step of every frame; its position and velocity are empty.
  const gg::Snapshots& index() const { return index_; }
  // Frame k read back from the file, for gg::write_snapshots and checkpoints; velocities() and
  // images() are empty readers without velocities or images.
  gg::FrameReader positions() const;
  gg::FrameReader velocities() const;
  gg::FrameReader images() const;
  // Frame k's masses or radii, [N] (empty readers without sizes).
  gg::FrameReader masses() const;
  gg::FrameReader radii() const;
  // Frame k's angular velocities, [N] in 2D, [N][3] in 3D (an empty reader without spins).
  gg::FrameReader spins() const;

 private:
  // The fields of a frame in the file, in this order (those it holds).
  enum Field { kPositions, kVelocities, kImages, kMasses, kRadii, kSpins };
  static constexpr Field kFields[] = {kPositions, kVelocities, kImages, kMasses, kRadii, kSpins};
  void read(std::size_t k, Field field, double* values) const;
  std::size_t field_bytes(Field field) const;
  bool holds(Field field) const;
  off_t offset(std::size_t k, Field field) const;

  gg::Snapshots index_;
  SnapshotFields fields_;
  gg::ScratchFile file_;
};

}  // namespace ggsim
