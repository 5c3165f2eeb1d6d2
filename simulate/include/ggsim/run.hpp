#pragma once
// gg-sim as a library call: scene in, H5MD file out, exit status back.
#include <string>
#include <vector>

#include "ggsim/config.hpp"

namespace ggsim {

class SavedRun;

// Builds the initial state, equilibrates if asked, runs the engine the scene calls for and
// writes the output atomically. Returns the exit status (0, or 1 after a collapse or an
// interrupt, with everything recorded so far written). Throws gg::UsageError/RuntimeError.
// With cfg.resume, continues that checkpoint: `saved` if the caller has opened it already (gg-sim
// reads its scene first), else opened here.
int run(const SimConfig& cfg, const std::vector<std::string>& argv, bool show_progress, SavedRun* saved = nullptr);

}  // namespace ggsim
