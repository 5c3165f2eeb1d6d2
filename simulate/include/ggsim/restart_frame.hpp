#pragma once
// The last frame of a gg-sim output at full precision, for a run to start from (--init FILE,
// --continue). With --float-snapshots every frame is stored in single precision, whose rounding
// (2^-24 relative: 8e-6 diameters at L = 128) puts disks that touch inside a cluster closer than a
// diameter, and a start from such a frame is refused as overlapping. Such an output therefore also
// holds its last frame in double: /restart/{time, step, position [1][N][d], velocity} (velocity if
// recorded). Outputs in double need no copy: their last frame is exact already.
#include "gg/h5file.hpp"
#include "gg/trajectory.hpp"
#include "ggsim/snapshot_store.hpp"

namespace ggsim {

// Writes /restart from the store's last frame (nothing if it has none).
void write_restart_frame(gg::H5Output& out, const SnapshotStore& snaps);

// If `in` has a /restart copy of the frame `last` holds (read_snapshots(in, {-1})), puts its
// positions and velocities into `last` and returns true. Throws gg::RuntimeError naming the file
// if the copy is damaged.
bool use_restart_frame(const gg::H5Input& in, gg::Snapshots& last);

}  // namespace ggsim
