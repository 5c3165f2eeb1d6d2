#pragma once
// The end of a run, the same for every engine variant: the output file, and the message and exit
// status that say how the run ended.
#include <string>
#include <vector>

#include "ggsim/config.hpp"
#include "ggsim/engine.hpp"
#include "ggsim/recorder.hpp"
#include "ggsim/run_pieces.hpp"
#include "start.hpp"

namespace ggsim {

// Writes the H5MD output atomically (docs/DESIGN.md "Output"): snapshots, observables, every
// scene value and the provenance, with every piece of the run.
void write_output(const SimConfig& cfg, const std::vector<std::string>& argv, const Recorder& rec,
                  const InitFile& init, StopReason why, const RunPieces& pieces);

// Says on stderr how a run that stopped for `why` at t = now ended, removes the checkpoint of a
// complete run, and returns the exit status.
int report_end(const SimConfig& cfg, const std::vector<std::string>& argv, StopReason why, double now,
               double collisions_per_particle, bool keep_checkpoint);

// Why a stall right at the start (disks in contact) is not an inelastic collapse.
std::string stalled_start_message(const SimConfig& cfg, double t);

}  // namespace ggsim
