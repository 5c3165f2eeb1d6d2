#pragma once
// Where an output goes, decided before anything is written (H5Output, OutputFile, require_writable_output).
//  - kFile: a regular file, or a name not yet taken. It is built under a hidden temporary name in
//    `dir` and renamed over `path` when complete (atomic). A symbolic link is followed: `path` is
//    the file it points to (which the link keeps pointing to), not the link.
//  - kStream: an existing device, FIFO or other file that is not regular (/dev/null, a named pipe,
//    /dev/fd/N of a process substitution). It is written through, once the HDF5 file is complete,
//    and never replaced: a rename would put a regular file where the device node was.
//  - kStdout: "-".
#include <string>

namespace gg::detail {

struct OutputTarget {
  enum Kind { kFile, kStream, kStdout } kind = kFile;
  std::string path;  // kFile: the file the output replaces; kStream: the name to open
  std::string dir;   // kFile: the directory of `path`
};

// Throws UsageError naming `name` when it cannot be an output: a directory, a missing or
// non-directory parent, a closed stdout, a stream that cannot be opened for writing, a terminal
// (unless the output is text: `binary` false).
OutputTarget resolve_output(const std::string& name, bool binary = true);

}  // namespace gg::detail
