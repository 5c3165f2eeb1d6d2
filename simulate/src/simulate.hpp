#pragma once
// One engine variant's run: the engine compiled with the effects Fx, from a fresh start or a
// checkpoint to the output. Declared here for the dispatch (run.cpp); defined in simulate_impl.hpp
// and compiled once per variant in a translation unit of its own (simulate/CMakeLists.txt).
#include <string>
#include <vector>

#include "ggsim/config.hpp"
#include "start.hpp"

namespace ggsim {

// Runs the engine from `st` (a fresh start) or from the checkpoint `saved` (st == nullptr),
// checkpointing every cfg.checkpoint_every seconds and on SIGINT/SIGTERM; writes the output and
// returns the exit status.
template <int D, class Fx>
int simulate(const SimConfig& cfg, State<D>* st, SavedRun* saved, const InitFile& init,
             const std::vector<std::string>& argv, bool show_progress);

}  // namespace ggsim
