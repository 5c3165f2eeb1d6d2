#include "ggsim/snapshot_store.hpp"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>

#include <fcntl.h>
#include <unistd.h>

#include "gg/errors.hpp"

namespace ggsim {

namespace {

// The directory and name pattern of the frames' file: beside the output (the disk chosen for the
// run's data), or in $TMPDIR for stdout.
std::string file_pattern(const std::string& output) {
  namespace fs = std::filesystem;
  if (output == "-") {
    const char* tmp = std::getenv("TMPDIR");
    return (fs::path(tmp && *tmp ? tmp : "/tmp") / "gg-sim.frames.XXXXXX").string();
  }
  const fs::path target(output);
  const fs::path dir = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  std::string name = ".";  // hidden, like H5Output's temporary (and no "." + string: GCC 12 -Wrestrict)
  name += target.filename().string();
  name += ".frames.XXXXXX";
  return (dir / name).string();
}

std::string in_quotes(const std::string& s) { return "'" + s + "'"; }

}  // namespace

SnapshotStore::SnapshotStore(const std::string& output, std::size_t n, int dim, const std::vector<double>& edges,
                             bool velocities)
    : velocities_(velocities), path_(file_pattern(output)) {
  index_.dim = dim;
  index_.edges = edges;
  index_.n_particles = n;
  fd_ = mkostemp(path_.data(), O_CLOEXEC);
  if (fd_ < 0) {
    const int err = errno;
    const std::string fix = output == "-" ? "set TMPDIR to an existing, writable directory with space"
                                          : "give -o in an existing, writable directory with space";
    const std::string what = "cannot create a temporary file for the snapshots in " +
                             in_quotes(std::filesystem::path(path_).parent_path().string()) + ": " +
                             std::strerror(err) + "; " + fix;
    if (err == ENOENT || err == ENOTDIR || err == EACCES || err == EROFS) throw gg::UsageError(what);
    throw gg::RuntimeError(what);
  }
  // Unlinked at once: the file lives as long as the descriptor, so no end of the process, not even
  // SIGKILL or the OOM killer, leaves it behind (the signal registry of temp_files.hpp cannot catch those).
  unlink(path_.c_str());
}

SnapshotStore::~SnapshotStore() { close(fd_); }

void SnapshotStore::append(double time, std::int64_t step, const double* position, const double* velocity) {
  const std::size_t bytes = field_bytes(), k = index_.frames();
  for (std::size_t field = 0; field < (velocities_ ? 2 : 1); ++field) {
    const char* p = reinterpret_cast<const char*>(field == 0 ? position : velocity);
    for (std::size_t done = 0; done < bytes;) {
      const ssize_t wrote = pwrite(fd_, p + done, bytes - done, offset(k, field) + static_cast<off_t>(done));
      if (wrote < 0 && errno == EINTR) continue;
      if (wrote <= 0)
        throw gg::RuntimeError("cannot write snapshot " + std::to_string(k) + " to the temporary file " +
                               in_quotes(path_) + ": " + std::strerror(wrote < 0 ? errno : ENOSPC) +
                               "; free space there (each snapshot takes " +
                               std::to_string(velocities_ ? 2 * bytes : bytes) + " bytes)");
      done += static_cast<std::size_t>(wrote);
    }
  }
  index_.time.push_back(time);
  index_.step.push_back(step);
}

void SnapshotStore::read(std::size_t k, std::size_t field, double* values) const {
  const std::size_t bytes = field_bytes();
  char* p = reinterpret_cast<char*>(values);
  for (std::size_t done = 0; done < bytes;) {
    const ssize_t got = pread(fd_, p + done, bytes - done, offset(k, field) + static_cast<off_t>(done));
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0)
      throw gg::RuntimeError("cannot read snapshot " + std::to_string(k) + " back from the temporary file " +
                             in_quotes(path_) + ": " + (got < 0 ? std::strerror(errno) : "the file is shorter than written"));
    done += static_cast<std::size_t>(got);
  }
}

std::size_t SnapshotStore::field_bytes() const {
  return index_.n_particles * static_cast<std::size_t>(index_.dim) * sizeof(double);
}

// Frame k is its positions, then its velocities (if any).
off_t SnapshotStore::offset(std::size_t k, std::size_t field) const {
  return static_cast<off_t>((k * (velocities_ ? 2 : 1) + field) * field_bytes());
}

gg::FrameReader SnapshotStore::positions() const {
  return [this](std::size_t k, double* values) { read(k, 0, values); };
}

gg::FrameReader SnapshotStore::velocities() const {
  if (!velocities_) return {};
  return [this](std::size_t k, double* values) { read(k, 1, values); };
}

}  // namespace ggsim
