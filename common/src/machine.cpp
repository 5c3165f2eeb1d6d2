#include "gg/machine.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <limits>
#include <sstream>

#include <sys/resource.h>
#include <sys/statvfs.h>

namespace gg {
namespace {

constexpr std::uint64_t kUnknown = std::numeric_limits<std::uint64_t>::max();

// The value of `key` in a "Key:   123 kB" file (/proc/meminfo, /proc/self/status), in bytes.
std::uint64_t kb_field(const char* file, const std::string& key) {
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line))
    if (line.rfind(key + ":", 0) == 0) {
      std::istringstream s(line.substr(key.size() + 1));
      std::uint64_t kb = 0;
      if (s >> kb) return kb * 1024;
    }
  return kUnknown;
}

std::uint64_t number_in(const std::string& file) {
  std::ifstream in(file);
  std::uint64_t v = 0;
  return in >> v ? v : kUnknown;  // "max" (no limit) reads as unknown
}

// cgroup v2: the line "0::/path" of /proc/self/cgroup; the tightest limit on the way up.
std::uint64_t cgroup_room() {
  std::ifstream in("/proc/self/cgroup");
  std::string line, path;
  while (std::getline(in, line))
    if (line.rfind("0::", 0) == 0) path = line.substr(3);
  if (path.empty()) return kUnknown;
  std::uint64_t room = kUnknown;
  for (;;) {
    const std::string dir = "/sys/fs/cgroup" + (path == "/" ? std::string() : path);
    const std::uint64_t max = number_in(dir + "/memory.max"), used = number_in(dir + "/memory.current");
    if (max != kUnknown && used != kUnknown) room = std::min(room, max > used ? max - used : 0);
    if (path == "/" || path.empty()) break;
    path = path.substr(0, path.find_last_of('/'));
    if (path.empty()) path = "/";
  }
  return room;
}

std::uint64_t address_space_room() {
  rlimit lim{};
  if (getrlimit(RLIMIT_AS, &lim) != 0 || lim.rlim_cur == RLIM_INFINITY) return kUnknown;
  const std::uint64_t mapped = kb_field("/proc/self/status", "VmSize");
  if (mapped == kUnknown) return lim.rlim_cur;
  return lim.rlim_cur > mapped ? lim.rlim_cur - mapped : 0;
}

}  // namespace

std::uint64_t available_memory() {
  return std::min({kb_field("/proc/meminfo", "MemAvailable"), cgroup_room(), address_space_room()});
}

std::uint64_t free_disk_space(const std::string& dir) {
  struct statvfs st {};
  if (statvfs(dir.c_str(), &st) != 0) return kUnknown;
  return static_cast<std::uint64_t>(st.f_bavail) * st.f_frsize;
}

std::string size_text(double bytes) {
  const char* units[] = {"bytes", "kB", "MB", "GB", "TB", "PB"};
  int u = 0;
  while (bytes >= 1000 && u < 5) bytes /= 1000, ++u;
  char text[32];
  std::snprintf(text, sizeof text, bytes >= 100 || u == 0 ? "%.0f %s" : "%.2g %s", bytes, units[u]);
  return text;
}

}  // namespace gg
