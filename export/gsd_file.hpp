#pragma once
// The GSD file layer, version 2.0, written from its published specification (the "File layer"
// page of the GSD documentation, glotzerlab/gsd doc/file-layer.rst): a 256-byte header, the data
// chunks, then the index (32-byte entries sorted by frame, then name id, ended by an entry at
// location 0) and the name list (0-terminated names, padded with zeros to whole 64-byte segments).
// Only writing, only whole files: chunks go out as they come, the index and the name list at the
// end, and the header, which points at both, last.
#include <cstdint>
#include <string>
#include <vector>

#include "gg/output_file.hpp"

namespace gg::gsd {

// Element types (the specification's type ids).
enum class Type : std::uint8_t { kUint8 = 1, kUint32 = 3, kUint64 = 4, kInt8 = 5, kInt32 = 7, kFloat = 9, kDouble = 10 };

class Writer {
 public:
  Writer(OutputFile& file, const std::string& application, const std::string& schema, std::uint32_t schema_major,
         std::uint32_t schema_minor);
  // A chunk of the current frame: an N x M matrix, row-major, of `type` values.
  void chunk(const std::string& name, Type type, std::uint64_t n, std::uint32_t m, const void* data);
  void end_frame();
  // Writes the index, the name list and the header; the file can then be committed.
  void finish();

 private:
  struct Entry {
    std::uint64_t frame, n;
    std::int64_t location;
    std::uint32_t m;
    std::uint16_t id;
    std::uint8_t type;
  };
  std::uint16_t name_id(const std::string& name);

  OutputFile& file_;
  std::string application_, schema_;
  std::uint32_t schema_version_;
  std::uint64_t frame_ = 0;
  std::vector<std::string> names_;
  std::vector<Entry> index_, this_frame_;
};

}  // namespace gg::gsd
