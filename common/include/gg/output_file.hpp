#pragma once
// A non-HDF5 output (GSD, text) published whole, as H5Output publishes HDF5: written under a hidden
// temporary name in the target's directory and renamed onto it by commit() (onto the file a symbolic
// link names, the link kept); "-", a device or a FIFO is written to an anonymous temporary file and
// copied to it by commit(), never replaced. A file never committed (an error, a signal) is removed,
// and an existing file of that name is left as it was.
#include <cstdint>
#include <cstdio>
#include <string>

namespace gg {

class OutputFile {
 public:
  // Throws UsageError where resolve_output (output_target.hpp) does: the directory of `path` missing
  // or not writable, `path` a directory; a terminal only when `binary`.
  OutputFile(const std::string& path, bool binary);
  ~OutputFile();
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  void write(const void* data, std::size_t bytes);
  void write(const std::string& text) { write(text.data(), text.size()); }
  // Overwrites `bytes` at `offset` (a header whose values are known at the end).
  void write_at(std::uint64_t offset, const void* data, std::size_t bytes);
  std::uint64_t size() const { return size_; }
  void commit();

 private:
  std::string path_, tmp_, final_;  // final_: the file tmp_ replaces
  std::string stream_to_;             // a device or FIFO written through
  std::FILE* file_ = nullptr;
  std::uint64_t size_ = 0;
  bool committed_ = false;
};

}  // namespace gg
