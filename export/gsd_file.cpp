#include "gsd_file.hpp"

#include <algorithm>
#include <bit>
#include <cstring>
#include <stdexcept>

#include "gg/errors.hpp"

namespace gg::gsd {
namespace {

static_assert(std::endian::native == std::endian::little, "GSD files are written in the host's byte order, "
                                                          "and readers expect little-endian");

constexpr std::uint64_t kMagic = 0x65DF65DF65DF65DFull;
constexpr std::size_t kHeaderBytes = 256, kEntryBytes = 32, kNameSegment = 64;

// Versions are packed as 0xaaaabbbb = aaaa.bbbb.
constexpr std::uint32_t version(std::uint32_t major, std::uint32_t minor) { return major << 16 | minor; }

std::size_t type_size(Type t) {
  switch (t) {
    case Type::kUint8: case Type::kInt8: return 1;
    case Type::kUint32: case Type::kInt32: case Type::kFloat: return 4;
    case Type::kUint64: case Type::kDouble: return 8;
  }
  return 0;
}

template <class T>
void put(std::vector<unsigned char>& bytes, std::size_t at, T value) {
  std::memcpy(bytes.data() + at, &value, sizeof value);
}

// A fixed 64-byte, 0-terminated text field of the header.
void put_text(std::vector<unsigned char>& bytes, std::size_t at, const std::string& text) {
  std::memcpy(bytes.data() + at, text.data(), std::min<std::size_t>(text.size(), 63));
}

}  // namespace

Writer::Writer(OutputFile& file, const std::string& application, const std::string& schema, std::uint32_t schema_major,
               std::uint32_t schema_minor)
    : file_(file), application_(application), schema_(schema), schema_version_(version(schema_major, schema_minor)) {
  const std::vector<unsigned char> placeholder(kHeaderBytes, 0);
  file_.write(placeholder.data(), placeholder.size());
}

std::uint16_t Writer::name_id(const std::string& name) {
  const auto it = std::find(names_.begin(), names_.end(), name);
  if (it != names_.end()) return static_cast<std::uint16_t>(it - names_.begin());
  if (names_.size() == 0xffff) throw std::logic_error("gsd::Writer: more than 65535 chunk names");
  names_.push_back(name);
  return static_cast<std::uint16_t>(names_.size() - 1);
}

void Writer::chunk(const std::string& name, Type type, std::uint64_t n, std::uint32_t m, const void* data) {
  this_frame_.push_back({frame_, n, static_cast<std::int64_t>(file_.size()), m, name_id(name), static_cast<std::uint8_t>(type)});
  file_.write(data, n * m * type_size(type));
}

void Writer::end_frame() {
  std::sort(this_frame_.begin(), this_frame_.end(), [](const Entry& a, const Entry& b) { return a.id < b.id; });
  index_.insert(index_.end(), this_frame_.begin(), this_frame_.end());
  this_frame_.clear();
  ++frame_;
}

void Writer::finish() {
  if (!this_frame_.empty()) end_frame();
  // One zero entry more than used: the first entry at location 0 ends the list.
  const std::uint64_t index_location = file_.size(), index_entries = index_.size() + 1;
  std::vector<unsigned char> index(index_entries * kEntryBytes, 0);
  for (std::size_t k = 0; k < index_.size(); ++k) {
    const Entry& e = index_[k];
    const std::size_t at = k * kEntryBytes;
    put(index, at, e.frame);
    put(index, at + 8, e.n);
    put(index, at + 16, e.location);
    put(index, at + 24, e.m);
    put(index, at + 28, e.id);
    put(index, at + 30, e.type);  // flags (at + 31) stay 0
  }
  file_.write(index.data(), index.size());

  // Names, each 0-terminated, then at least one 0 (an empty name ends the list) up to whole segments.
  const std::uint64_t namelist_location = file_.size();
  std::string names;
  for (const std::string& name : names_) names += name + '\0';
  names.resize((names.size() / kNameSegment + 1) * kNameSegment, '\0');
  file_.write(names);

  std::vector<unsigned char> header(kHeaderBytes, 0);
  put(header, 0, kMagic);
  put(header, 8, index_location);
  put(header, 16, index_entries);
  put(header, 24, namelist_location);
  put(header, 32, static_cast<std::uint64_t>(names.size() / kNameSegment));
  put(header, 40, schema_version_);
  put(header, 44, version(2, 0));
  put_text(header, 48, application_);
  put_text(header, 112, schema_);
  file_.write_at(0, header.data(), header.size());
}

}  // namespace gg::gsd
