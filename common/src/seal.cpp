#include "gg/seal.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <vector>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "gg/errors.hpp"

namespace gg {
namespace {

constexpr char kSignature[8] = {'G', 'G', '-', 'S', 'E', 'A', 'L', '1'};

// FNV-1a over 64-bit words (then the bytes of a short tail): each step is a bijection of the
// state, so a file that differs in one word always gets another checksum.
struct Checksum {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  void add(const unsigned char* p, std::size_t n) {
    std::size_t i = 0;
    for (; i + 8 <= n; i += 8) {
      std::uint64_t w;
      std::memcpy(&w, p + i, 8);
      h = (h ^ w) * 0x100000001b3ULL;
    }
    for (; i < n; ++i) h = (h ^ p[i]) * 0x100000001b3ULL;
  }
};

void put_u64(unsigned char* at, std::uint64_t v) {
  for (int k = 0; k < 8; ++k) at[k] = static_cast<unsigned char>(v >> (8 * k));
}

std::uint64_t get_u64(const unsigned char* at) {
  std::uint64_t v = 0;
  for (int k = 0; k < 8; ++k) v |= static_cast<std::uint64_t>(at[k]) << (8 * k);
  return v;
}

bool read_fully(int fd, unsigned char* p, std::size_t n, off_t at) {
  for (std::size_t done = 0; done < n;) {
    const ssize_t got = pread(fd, p + done, n - done, at + static_cast<off_t>(done));
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) return false;
    done += static_cast<std::size_t>(got);
  }
  return true;
}

constexpr std::uint64_t kHeadBytes = 24;  // signature, length, checksum

// The checksum of the bytes of `fd` from `from` to `size`, or false if they cannot all be read.
bool checksum_from(int fd, std::uint64_t from, std::uint64_t size, std::uint64_t& sum) {
  Checksum c;
  std::vector<unsigned char> chunk(std::size_t{1} << 20);
  for (std::uint64_t at = from; at < size;) {
    const auto n = static_cast<std::size_t>(std::min<std::uint64_t>(chunk.size(), size - at));
    if (!read_fully(fd, chunk.data(), n, static_cast<off_t>(at))) return false;
    c.add(chunk.data(), n);
    at += n;
  }
  sum = c.h;
  return true;
}

// The checksum of every byte after the seal's own head, the rest of the user block included (so
// that no byte of the file can change unnoticed).
bool checksum_after_block(int fd, std::uint64_t size, std::uint64_t& sum) {
  return checksum_from(fd, kHeadBytes, size, sum);
}

}  // namespace

void write_seal(int fd, const std::string& name) {
  struct stat st {};
  std::uint64_t sum = 0;
  if (fstat(fd, &st) != 0 || static_cast<std::uint64_t>(st.st_size) < kSealBytes ||
      !checksum_after_block(fd, static_cast<std::uint64_t>(st.st_size), sum))
    throw RuntimeError("cannot read back " + name + " to seal it: " + std::strerror(errno));
  unsigned char head[kHeadBytes];
  std::memcpy(head, kSignature, 8);
  put_u64(head + 8, static_cast<std::uint64_t>(st.st_size));
  put_u64(head + 16, sum);
  if (pwrite(fd, head, sizeof head, 0) != static_cast<ssize_t>(sizeof head) || fsync(fd) != 0)
    throw RuntimeError("cannot seal " + name + ": " + std::strerror(errno) + "; check disk space");
}

SealState read_seal(const std::string& path) {
  const int fd = open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return SealState::kNone;  // the reader that follows says why
  unsigned char head[kHeadBytes];
  SealState state = SealState::kNone;
  struct stat st {};
  if (fstat(fd, &st) == 0 && read_fully(fd, head, sizeof head, 0) && std::memcmp(head, kSignature, 8) == 0) {
    std::uint64_t sum = 0;
    const bool same = get_u64(head + 8) == static_cast<std::uint64_t>(st.st_size) &&
                      checksum_after_block(fd, static_cast<std::uint64_t>(st.st_size), sum) && sum == get_u64(head + 16);
    state = same ? SealState::kIntact : SealState::kBroken;
  }
  close(fd);
  return state;
}

std::string file_checksum(const std::string& path) {
  const int fd = open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return {};
  struct stat st {};
  std::uint64_t sum = 0;
  const bool read = fstat(fd, &st) == 0 && checksum_from(fd, 0, static_cast<std::uint64_t>(st.st_size), sum);
  close(fd);
  if (!read) return {};
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(sum));
  return hex;
}

}  // namespace gg
