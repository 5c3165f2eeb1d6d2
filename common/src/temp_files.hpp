#pragma once
// Temporary output files that must not survive the process (docs/DESIGN.md: a killed tool never
// leaves a half file). Destructors remove them on the normal paths; this registry also removes
// them when SIGINT, SIGTERM or SIGHUP ends the program (e.g. a Slurm time limit).
#include <string>

namespace gg::detail {

// Registers `path` for removal on a fatal signal. Returns false if the registry is full (the
// file is then only removed by its owner's destructor).
bool track_temp_file(const std::string& path);
void untrack_temp_file(const std::string& path);

}  // namespace gg::detail
