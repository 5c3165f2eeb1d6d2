#pragma once
// What the machine has left for the work to come, for the checks a tool makes before it starts
// (a run that needs more memory than there is must be refused with a line that says so, not end
// hours later in the kernel's OOM killer with no message at all).
#include <cstdint>
#include <string>

namespace gg {

// Bytes this process can still allocate: the least of the kernel's MemAvailable, the room left
// under its cgroup's memory.max, and its address-space limit (RLIMIT_AS) less what it has mapped.
// UINT64_MAX if none of them can be read.
std::uint64_t available_memory();

// Bytes an unprivileged writer may still put on the file system of `dir` (statvfs); UINT64_MAX if
// it cannot be read.
std::uint64_t free_disk_space(const std::string& dir);

// "288 GB", "1.5 MB": a size for a message (decimal units, 2 significant digits at least).
std::string size_text(double bytes);

}  // namespace gg
