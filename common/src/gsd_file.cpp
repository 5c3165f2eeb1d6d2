#include "gg/gsd_file.hpp"

#include <algorithm>
#include <bit>
#include <cstring>
#include <filesystem>
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

// 0 for an id the specification does not define.
std::size_t type_size(Type t) {
  switch (t) {
    case Type::kUint8: case Type::kInt8: case Type::kCharacter: return 1;
    case Type::kUint16: case Type::kInt16: return 2;
    case Type::kUint32: case Type::kInt32: case Type::kFloat: return 4;
    case Type::kUint64: case Type::kInt64: case Type::kDouble: return 8;
  }
  return 0;
}

template <class T>
T get(const unsigned char* bytes) {
  T value;
  std::memcpy(&value, bytes, sizeof value);
  return value;
}

template <class T>
void convert(const std::vector<unsigned char>& bytes, std::vector<double>& out) {
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = static_cast<double>(get<T>(bytes.data() + i * sizeof(T)));
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

bool is_gsd(const std::string& first_bytes) {
  return first_bytes.size() >= 8 && get<std::uint64_t>(reinterpret_cast<const unsigned char*>(first_bytes.data())) == kMagic;
}

Reader::Reader(const std::string& path) : path_(path), file_(path, std::ios::binary) {
  const std::string name = "'" + path + "'";
  std::error_code error;
  const std::uint64_t size = std::filesystem::file_size(path, error);
  if (!file_ || error) throw RuntimeError(name + ": cannot open the GSD file; check the path and its permissions");
  const std::string damaged = "; the GSD file is truncated or damaged, write it again";
  const auto bytes_at = [&](std::uint64_t at, std::uint64_t count, const char* what) {
    if (at > size || count > size - at)
      throw RuntimeError(name + ": the " + what + " lies past the end of the file" + damaged);
    std::vector<unsigned char> out(count);
    file_.seekg(static_cast<std::streamoff>(at));
    file_.read(reinterpret_cast<char*>(out.data()), static_cast<std::streamsize>(count));
    if (!file_) throw RuntimeError(name + ": cannot read the " + what + damaged);
    return out;
  };
  const std::vector<unsigned char> header = bytes_at(0, kHeaderBytes, "header");
  if (get<std::uint64_t>(header.data()) != kMagic) throw RuntimeError(name + ": not a GSD file (no GSD magic number)");
  const auto index_location = get<std::uint64_t>(header.data() + 8);
  const auto index_entries = get<std::uint64_t>(header.data() + 16);
  const auto namelist_location = get<std::uint64_t>(header.data() + 24);
  const auto namelist_entries = get<std::uint64_t>(header.data() + 32);
  const auto gsd_version = get<std::uint32_t>(header.data() + 44);
  if (gsd_version >> 16 < 1 || gsd_version >> 16 > 2)
    throw RuntimeError(name + ": GSD file layer version " + std::to_string(gsd_version >> 16) + "." +
                       std::to_string(gsd_version & 0xffff) + " is not supported (1.x and 2.x are)");
  schema_.assign(reinterpret_cast<const char*>(header.data() + 112), 63);
  schema_.resize(std::strlen(schema_.c_str()));
  if (index_entries > size / kEntryBytes || namelist_entries > size / kNameSegment)
    throw RuntimeError(name + ": the index or the name list is larger than the file" + damaged);

  // Names: GSD 1.x gives each a 64-byte slot, 2.x packs 0-terminated strings; an empty name ends both.
  const std::vector<unsigned char> list = bytes_at(namelist_location, namelist_entries * kNameSegment, "name list");
  std::vector<std::string> names;
  for (std::size_t at = 0; at < list.size();) {
    const auto* begin = reinterpret_cast<const char*>(list.data() + at);
    const std::size_t length = strnlen(begin, list.size() - at);
    if (length == 0) break;
    names.emplace_back(begin, length);
    at = gsd_version >> 16 == 1 ? at + kNameSegment : at + length + 1;
  }

  // The index: valid entries up to the first at location 0.
  const std::vector<unsigned char> index = bytes_at(index_location, index_entries * kEntryBytes, "index");
  for (std::uint64_t k = 0; k < index_entries; ++k) {
    const unsigned char* e = index.data() + k * kEntryBytes;
    const Chunk chunk{static_cast<Type>(e[30]), get<std::uint64_t>(e + 8), get<std::uint32_t>(e + 24),
                      get<std::uint64_t>(e + 16)};
    if (chunk.location == 0) break;
    const auto frame = get<std::uint64_t>(e);
    if (frame >= index_entries)  // every frame holds a chunk: no frame number can pass the entries
      throw RuntimeError(name + ": an index entry names frame " + std::to_string(frame) + " of at most " +
                         std::to_string(index_entries) + damaged);    const auto id = get<std::uint16_t>(e + 28);
    if (id >= names.size()) throw RuntimeError(name + ": an index entry names chunk " + std::to_string(id) +
                                               ", which the name list lacks" + damaged);
    const std::size_t element = type_size(chunk.type);
    if (element == 0)
      throw RuntimeError(name + ": chunk '" + names[id] + "' has type " + std::to_string(e[30]) +
                         ", which the GSD specification does not define" + damaged);
    if (chunk.m != 0 && chunk.n > (size / element) / chunk.m)
      throw RuntimeError(name + ": chunk '" + names[id] + "' is larger than the file" + damaged);
    if (chunk.location > size || chunk.n * chunk.m * element > size - chunk.location)
      throw RuntimeError(name + ": chunk '" + names[id] + "' of frame " + std::to_string(frame) +
                         " lies past the end of the file" + damaged);
    index_[{frame, names[id]}] = chunk;
    frames_ = std::max(frames_, frame + 1);
  }
}

std::optional<Reader::Chunk> Reader::find(std::uint64_t frame, const std::string& name) const {
  const auto it = index_.find({frame, name});
  if (it == index_.end()) return std::nullopt;
  return it->second;
}

std::vector<double> Reader::read(const Chunk& chunk) const {
  const std::size_t count = chunk.n * chunk.m;
  std::vector<unsigned char> bytes(count * type_size(chunk.type));
  file_.clear();
  file_.seekg(static_cast<std::streamoff>(chunk.location));
  file_.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  if (!file_) throw RuntimeError("'" + path_ + "': cannot read a chunk; the GSD file is truncated or damaged, write it again");
  std::vector<double> out(count);
  switch (chunk.type) {
    case Type::kUint8: convert<std::uint8_t>(bytes, out); break;
    case Type::kUint16: convert<std::uint16_t>(bytes, out); break;
    case Type::kUint32: convert<std::uint32_t>(bytes, out); break;
    case Type::kUint64: convert<std::uint64_t>(bytes, out); break;
    case Type::kInt8: case Type::kCharacter: convert<std::int8_t>(bytes, out); break;
    case Type::kInt16: convert<std::int16_t>(bytes, out); break;
    case Type::kInt32: convert<std::int32_t>(bytes, out); break;
    case Type::kInt64: convert<std::int64_t>(bytes, out); break;
    case Type::kFloat: convert<float>(bytes, out); break;
    case Type::kDouble: convert<double>(bytes, out); break;
  }
  return out;
}

}  // namespace gg::gsd
