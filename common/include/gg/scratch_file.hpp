#pragma once
// A temporary file that lives as an open descriptor: created in a directory with a name, which
// is removed as soon as nothing needs it (drop_name), so that afterwards no end of the process (not
// even SIGKILL or the OOM killer) leaves it behind. Data too large to hold in memory goes there
// (gg-sim's snapshots while it runs, HDF5 files passing through a pipe). HDF5 opens files by
// name and resolves it (realpath), so it must open one before its name is dropped; meanwhile
// the name is removed on SIGINT, SIGTERM and SIGHUP too (temp_files.hpp).
#include <cstddef>
#include <string>

#include <sys/types.h>  // off_t

namespace gg {

class ScratchFile {
 public:
  // Creates the file in directory `dir`, its name starting with `stem`. If that fails, throws
  // one line that ends with `fix` (what the user can do); a UsageError if the directory is
  // missing or not writable, else a RuntimeError.
  ScratchFile(const std::string& dir, const std::string& stem, const std::string& fix);
  ~ScratchFile();
  ScratchFile(const ScratchFile&) = delete;
  ScratchFile& operator=(const ScratchFile&) = delete;

  // $TMPDIR, or /tmp if it is not set.
  static std::string temp_dir();
  // A file in temp_dir(), for data that has no output directory to go to (stdin, stdout).
  static ScratchFile in_temp_dir(const std::string& stem);

  // The file's name until drop_name(), then where it was (for messages).
  const std::string& path() const { return path_; }
  // Removes the name; the file lives on until this object is destroyed.
  void drop_name();
  int fd() const { return fd_; }

  // `bytes` bytes at `offset`; 0 on success, else the errno value (ENOSPC if the disk took
  // nothing; for read_at, -1 if the file ends first).
  int write_at(const void* data, std::size_t bytes, off_t offset) const;
  int read_at(void* data, std::size_t bytes, off_t offset) const;

 private:
  std::string path_;
  int fd_ = -1;
  bool named_ = true;
};

}  // namespace gg
