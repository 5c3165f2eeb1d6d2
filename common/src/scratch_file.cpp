#include "gg/scratch_file.hpp"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>

#include <fcntl.h>
#include <unistd.h>

#include "gg/errors.hpp"
#include "temp_files.hpp"

namespace gg {

ScratchFile::ScratchFile(const std::string& dir, const std::string& stem, const std::string& fix)
    : path_((std::filesystem::path(dir) / (stem + ".XXXXXX")).string()) {
  fd_ = mkostemp(path_.data(), O_CLOEXEC);
  if (fd_ < 0) {
    const int err = errno;
    const std::string what = "cannot create a temporary file in '" + dir + "': " + std::strerror(err) + "; " + fix;
    if (err == ENOENT || err == ENOTDIR || err == EACCES || err == EROFS) throw UsageError(what);
    throw RuntimeError(what);
  }
  detail::track_temp_file(path_);
}

ScratchFile::~ScratchFile() {
  drop_name();
  close(fd_);
}

void ScratchFile::drop_name() {
  if (!named_) return;
  unlink(path_.c_str());
  detail::untrack_temp_file(path_);
  named_ = false;
}

std::string ScratchFile::temp_dir() {
  const char* tmp = std::getenv("TMPDIR");
  return tmp && *tmp ? tmp : "/tmp";
}

ScratchFile ScratchFile::in_temp_dir(const std::string& stem) {
  return ScratchFile(temp_dir(), stem, "set TMPDIR to an existing, writable directory with space");
}

int ScratchFile::write_at(const void* data, std::size_t bytes, off_t offset) const {
  const char* p = static_cast<const char*>(data);
  for (std::size_t done = 0; done < bytes;) {
    const ssize_t wrote = pwrite(fd_, p + done, bytes - done, offset + static_cast<off_t>(done));
    if (wrote < 0 && errno == EINTR) continue;
    if (wrote <= 0) return wrote < 0 ? errno : ENOSPC;
    done += static_cast<std::size_t>(wrote);
  }
  return 0;
}

int ScratchFile::read_at(void* data, std::size_t bytes, off_t offset) const {
  char* p = static_cast<char*>(data);
  for (std::size_t done = 0; done < bytes;) {
    const ssize_t got = pread(fd_, p + done, bytes - done, offset + static_cast<off_t>(done));
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) return errno;
    if (got == 0) return -1;
    done += static_cast<std::size_t>(got);
  }
  return 0;
}

}  // namespace gg
