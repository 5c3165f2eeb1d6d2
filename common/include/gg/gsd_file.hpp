#pragma once
// The GSD file layer, version 2.0, written from its published specification (the "File layer"
// page of the GSD documentation, glotzerlab/gsd doc/file-layer.rst): a 256-byte header, the data
// chunks, then the index (32-byte entries sorted by frame, then name id, ended by an entry at
// location 0) and the name list (0-terminated names, padded with zeros to whole 64-byte segments).
// The writer writes whole files: chunks go out as they come, the index and the name list at the
// end, and the header, which points at both, last. The reader reads any file of the 1.x or 2.x
// file layer (GSD 1.x names are 64-byte slots, 2.x names 0-terminated strings), whatever wrote it.
#include <cstdint>
#include <fstream>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "gg/output_file.hpp"

namespace gg::gsd {

// Element types (the specification's type ids; 11, character, is GSD 3's).
enum class Type : std::uint8_t {
  kUint8 = 1, kUint16 = 2, kUint32 = 3, kUint64 = 4, kInt8 = 5, kInt16 = 6, kInt32 = 7, kInt64 = 8,
  kFloat = 9, kDouble = 10, kCharacter = 11
};

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

// One GSD file opened for reading: the header, the index and the name list are read and checked
// on opening (RuntimeError naming the file: not GSD, truncated, a chunk past the end); the chunks
// are read when asked for.
class Reader {
 public:
  struct Chunk {
    Type type;
    std::uint64_t n;  // rows
    std::uint32_t m;  // columns
    std::uint64_t location;
  };
  explicit Reader(const std::string& path);
  const std::string& path() const { return path_; }
  const std::string& schema() const { return schema_; }
  // 1 + the last frame that holds a chunk (0 for a file without chunks).
  std::uint64_t frames() const { return frames_; }
  // The chunk `name` of `frame`, if that frame has one.
  std::optional<Chunk> find(std::uint64_t frame, const std::string& name) const;
  // Its N x M values, row-major, converted to double.
  std::vector<double> read(const Chunk& chunk) const;

 private:
  std::string path_, schema_;
  mutable std::ifstream file_;
  std::uint64_t frames_ = 0;
  std::map<std::pair<std::uint64_t, std::string>, Chunk> index_;
};

// Whether the file begins with the GSD magic number.
bool is_gsd(const std::string& first_bytes);

}  // namespace gg::gsd
