#include "file_image.hpp"

#include <cstddef>
#include <cstdint>

namespace gg::detail {
namespace {

constexpr std::uint32_t rot(std::uint32_t x, int k) { return (x << k) | (x >> (32 - k)); }

// Bob Jenkins' lookup3 hashlittle (public domain), read byte by byte as HDF5's
// H5_checksum_lookup3 does, with initial value 0: the checksum of HDF5 metadata.
std::uint32_t lookup3(const unsigned char* k, std::size_t length) {
  std::uint32_t a, b, c;
  a = b = c = 0xdeadbeef + static_cast<std::uint32_t>(length);
  auto word = [](const unsigned char* p) {
    return std::uint32_t{p[0]} | std::uint32_t{p[1]} << 8 | std::uint32_t{p[2]} << 16 | std::uint32_t{p[3]} << 24;
  };
  while (length > 12) {
    a += word(k);
    b += word(k + 4);
    c += word(k + 8);
    a -= c; a ^= rot(c, 4);  c += b;
    b -= a; b ^= rot(a, 6);  a += c;
    c -= b; c ^= rot(b, 8);  b += a;
    a -= c; a ^= rot(c, 16); c += b;
    b -= a; b ^= rot(a, 19); a += c;
    c -= b; c ^= rot(b, 4);  b += a;
    length -= 12;
    k += 12;
  }
  if (length == 0) return c;
  unsigned char tail[12] = {};
  for (std::size_t i = 0; i < length; ++i) tail[i] = k[i];
  a += word(tail);
  b += word(tail + 4);
  c += word(tail + 8);
  c ^= b; c -= rot(b, 14);
  a ^= c; a -= rot(c, 11);
  b ^= a; b -= rot(a, 25);
  c ^= b; c -= rot(b, 16);
  a ^= c; a -= rot(c, 4);
  b ^= a; b -= rot(a, 14);
  c ^= b; c -= rot(b, 24);
  return c;
}

}  // namespace

void fix_superblock_checksum(std::vector<char>& image) {
  // Superblock v2/v3 (HDF5 file format spec): signature[8], version, size of offsets, size of
  // lengths, status flags, then 4 addresses (base, extension, end of file, root group), checksum.
  constexpr unsigned char kSignature[8] = {0x89, 'H', 'D', 'F', '\r', '\n', 0x1a, '\n'};
  if (image.size() < 12) return;
  auto* bytes = reinterpret_cast<unsigned char*>(image.data());
  for (int i = 0; i < 8; ++i)
    if (bytes[i] != kSignature[i]) return;
  const unsigned version = bytes[8], offset_size = bytes[9];
  if (version != 2 && version != 3) return;
  const std::size_t covered = 12 + 4 * std::size_t{offset_size};
  if (image.size() < covered + 4) return;
  const std::uint32_t sum = lookup3(bytes, covered);
  for (int i = 0; i < 4; ++i) bytes[covered + i] = static_cast<unsigned char>(sum >> (8 * i));
}

}  // namespace gg::detail
