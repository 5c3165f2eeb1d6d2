#pragma once
// A non-HDF5 output (GSD, text) published whole, as H5Output publishes HDF5: written under a hidden
// temporary name in the target's directory and renamed onto it by commit(); "-" is written to an
// anonymous temporary file and copied to stdout by commit(). A file never committed (an error, a
// signal) is removed, and an existing file of that name is left as it was.
#include <cstdint>
#include <cstdio>
#include <string>

namespace gg {

class OutputFile {
 public:
  // Throws UsageError if the directory of `path` does not exist or is not writable, if `path` is
  // a directory, or for "-" when stdout is a terminal and `binary`.
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
  std::string path_, tmp_;
  std::FILE* file_ = nullptr;
  std::uint64_t size_ = 0;
  bool committed_ = false;
};

}  // namespace gg
