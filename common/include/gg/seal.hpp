#pragma once
// A whole-file checksum for the files only gg tools read back (gg-sim's checkpoints): HDF5 checks
// its own metadata but not the data, nor the strings in its global heap, so a flipped bit there
// would resume a different run without a word. The seal lives in the file's first kSealBytes (an
// HDF5 user block, which HDF5 leaves alone): a signature, the file's length and a 64-bit checksum
// of every byte after these three.
#include <cstddef>
#include <string>

namespace gg {

inline constexpr std::size_t kSealBytes = 512;

// Seals the finished file open as `fd` (created with a user block of kSealBytes); `name` is for
// messages. Throws RuntimeError if it cannot be read or written.
void write_seal(int fd, const std::string& name);

enum class SealState { kNone, kIntact, kBroken };

// kNone: no seal (a file written without one); kBroken: sealed, but its bytes are no longer the
// ones sealed (or the file cannot be read to the end).
SealState read_seal(const std::string& path);

// The same 64-bit checksum of every byte of a file, as 16 hex digits (e.g. of a program's own
// executable, to tell one build from another); empty if the file cannot be read.
std::string file_checksum(const std::string& path);

}  // namespace gg
