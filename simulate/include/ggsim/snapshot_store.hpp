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

class SnapshotStore {
 public:
  // Frames of n particles in `dim` dimensions (with velocities, and periodic images, if asked) for a run that writes
  // `output`: they go to a temporary file in the output's directory, or in $TMPDIR (else /tmp) for
  // "-". Throws gg::UsageError if that directory is missing or not writable, gg::RuntimeError for
  // other failures, naming the directory.
  SnapshotStore(const std::string& output, std::size_t n, int dim, const std::vector<double>& edges,
                bool velocities, bool images = false);

  // One frame: positions, velocities (if kept) and images (if kept, integers), each [N][d] by
  // particle number. Throws gg::RuntimeError naming the file if the disk is full.
  void append(double time, std::int64_t step, const double* position, const double* velocity,
              const double* image = nullptr);

  // Box, particle count, and the time and step of every frame; its position and velocity are empty.
  const gg::Snapshots& index() const { return index_; }
  // Frame k read back from the file, for gg::write_snapshots and checkpoints; velocities() and
  // images() are empty readers without velocities or images.
  gg::FrameReader positions() const;
  gg::FrameReader velocities() const;
  gg::FrameReader images() const;

 private:
  // A frame's fields in the file: positions, then velocities and images, those kept.
  void read(std::size_t k, std::size_t field, double* values) const;
  std::size_t field_bytes() const;
  std::size_t fields() const { return 1 + velocities_ + images_; }
  off_t offset(std::size_t k, std::size_t field) const;

  gg::Snapshots index_;
  bool velocities_, images_;
  gg::ScratchFile file_;
};

}  // namespace ggsim
