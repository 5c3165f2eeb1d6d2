#pragma once
// What a run will need, estimated before it starts, against what the machine has: a run that would
// end in the kernel's OOM killer (no message, exit 137) or on a full disk after hours is refused
// with one line naming the value that asks for it. --no-resource-check runs it anyway.
#include <cstddef>
#include <string>

#include "ggsim/config.hpp"

namespace ggsim {

// `n` particles (the scene's, the --init file's or the checkpoint's); `scratch_dir`: where the
// snapshots wait for the output (gg::scratch_dir_for_output). Throws gg::RuntimeError.
void require_resources(const SimConfig& cfg, std::size_t n, const std::string& scratch_dir);

}  // namespace ggsim
