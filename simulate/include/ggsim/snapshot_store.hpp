#pragma once
// The snapshots of a run, kept on disk until the output is written: a run's memory must not grow
// with the number of snapshots (16 bytes per disk and frame in 2D, 32 with velocities; 20 frames of
// 1e7 disks would be 3.2 GB on top of the engine's ~110 bytes per disk). Frame times and steps are
// small and stay in memory.
#include <cstdint>
#include <string>
#include <vector>

#include "gg/scratch_file.hpp"
#include "gg/trajectory.hpp"
#include "ggsim/effects/effect_state.hpp"

namespace ggsim {

// What a frame holds beyond positions: velocities, periodic images, and per-particle fields of
// the effects and of aggregates (masses and radii, angular velocities), each a name and
// `components` values per particle.
struct SnapshotFields {
  bool velocities = false;
  bool images = false;  // periodic images, integers kept as doubles (gg-sim --unwrapped)
  std::vector<FrameField> more = {};
};

// One frame's values, by particle number; those not kept may be null. `more`: one array per
// field of SnapshotFields::more, in its order.
struct FrameValues {
  const double* position;
  const double* velocity = nullptr;
  const double* image = nullptr;
  std::vector<const double*> more = {};
};

class SnapshotStore {
 public:
  // Frames of n particles in `dim` dimensions (with the fields asked for) for a run that writes
  // `output`: they go to a temporary file in the output's directory, or in $TMPDIR (else /tmp) for
  // "-". Throws gg::UsageError if that directory is missing or not writable, gg::RuntimeError for
  // other failures, naming the directory.
  SnapshotStore(const std::string& output, std::size_t n, int dim, const std::vector<double>& edges,
                const SnapshotFields& fields);

  // One frame: positions, and the fields kept (velocities, images, the more fields), each by
  // particle number ([N][d], a more field [N][components]). Throws gg::RuntimeError naming the file
  // if the disk is full.
  void append(double time, std::int64_t step, const FrameValues& values);

  // Box, particle count, and the time and step of every frame; its position and velocity are empty.
  const gg::Snapshots& index() const { return index_; }
  // The more fields, in the order of SnapshotFields::more.
  const std::vector<FrameField>& more_fields() const { return fields_.more; }
  // Frame k read back from the file, for gg::write_snapshots and checkpoints; velocities() and
  // images() are empty readers without velocities or images.
  gg::FrameReader positions() const;
  gg::FrameReader velocities() const;
  gg::FrameReader images() const;
  // Frame k of the more field m.
  gg::FrameReader more(std::size_t m) const;

 private:
  // Frame k is its stored fields one after the other: positions, velocities and images if kept,
  // then the more fields; each with its values per particle.
  struct Stored {
    std::size_t components;
    std::size_t offset;  // bytes from the start of a frame
  };
  enum : std::size_t { kPositions, kVelocities, kImages, kMore };
  void read(std::size_t k, std::size_t field, double* values) const;
  gg::FrameReader reader(std::size_t field) const;
  std::size_t bytes(std::size_t field) const;

  gg::Snapshots index_;
  SnapshotFields fields_;
  std::vector<Stored> stored_;  // by kPositions, kVelocities, kImages, kMore + m; components 0: not kept
  std::size_t frame_bytes_ = 0;
  gg::ScratchFile file_;
};

}  // namespace ggsim
