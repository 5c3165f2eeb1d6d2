#pragma once
// A stop asked for from outside the run: SIGINT or SIGTERM (Ctrl-C, kill, a batch system's time
// limit). The signal handler only sets a flag; the engine's observer polls it between events
// (every 65536), so the run stops in a clean state, writes its checkpoint and its output, and
// keeps everything recorded so far.
#include <csignal>

namespace ggsim {

inline volatile std::sig_atomic_t g_stop_requested = 0;

// The handler to install for SIGINT and SIGTERM.
inline void request_stop(int) { g_stop_requested = 1; }

inline bool stop_requested() { return g_stop_requested != 0; }

}  // namespace ggsim
