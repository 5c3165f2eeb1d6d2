#include "temp_files.hpp"

#include <atomic>
#include <csignal>
#include <cstring>
#include <mutex>

#include <limits.h>
#include <unistd.h>

namespace gg::detail {
namespace {

// The signal handler may only touch memory that is never reallocated and only call
// async-signal-safe functions (unlink, signal, raise), hence a fixed table of C strings.
constexpr int kSlots = 16;
char g_paths[kSlots][PATH_MAX];
std::atomic<bool> g_used[kSlots];
std::mutex g_mutex;  // serialises track/untrack; never taken by the handler

constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP};

extern "C" void remove_temp_files_and_die(int sig) {
  for (int i = 0; i < kSlots; ++i)
    if (g_used[i].load()) unlink(g_paths[i]);
  std::signal(sig, SIG_DFL);  // die of the same signal, so the exit status tells the caller
  std::raise(sig);
}

// Only replaces the default disposition: a tool's own handler, or SIG_IGN under nohup, stays.
void install_handlers_once() {
  static const bool installed = [] {
    for (int sig : kSignals) {
      struct sigaction old {};
      if (sigaction(sig, nullptr, &old) == 0 && old.sa_handler == SIG_DFL) std::signal(sig, remove_temp_files_and_die);
    }
    return true;
  }();
  (void)installed;
}

}  // namespace

bool track_temp_file(const std::string& path) {
  if (path.size() >= PATH_MAX) return false;
  std::lock_guard lock(g_mutex);
  install_handlers_once();
  for (int i = 0; i < kSlots; ++i) {
    if (g_used[i].load()) continue;
    std::memcpy(g_paths[i], path.c_str(), path.size() + 1);
    g_used[i].store(true);  // published after the path is complete
    return true;
  }
  return false;
}

void untrack_temp_file(const std::string& path) {
  std::lock_guard lock(g_mutex);
  for (int i = 0; i < kSlots; ++i)
    if (g_used[i].load() && path == g_paths[i]) {
      g_used[i].store(false);
      return;
    }
}

}  // namespace gg::detail
