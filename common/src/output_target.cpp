#include "output_target.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "gg/errors.hpp"
#include "gg/standard_streams.hpp"

namespace gg::detail {
namespace {

namespace fs = std::filesystem;

std::string quoted(const std::string& s) { return "'" + s + "'"; }

// The name a chain of symbolic links ends in, when that name does not exist yet (a dangling
// link: the output creates the file it points to).
std::string end_of_links(const std::string& name) {
  std::string p = name;
  for (int hops = 0; hops < 40; ++hops) {
    struct stat st {};
    if (lstat(p.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) return p;
    std::error_code ec;
    const fs::path to = fs::read_symlink(p, ec);
    if (ec) return p;
    p = to.is_absolute() ? to.string() : (fs::path(p).parent_path() / to).string();
  }
  throw UsageError("output " + quoted(name) + " is a chain of more than 40 symbolic links; give the file itself");
}

const char* kind_of(mode_t mode) {
  if (S_ISCHR(mode)) return "character device";
  if (S_ISBLK(mode)) return "block device";
  if (S_ISFIFO(mode)) return "named pipe";
  if (S_ISSOCK(mode)) return "socket";
  return "special file";
}

}  // namespace

OutputTarget resolve_output(const std::string& name, bool binary) {
  OutputTarget t;
  if (name.empty()) throw UsageError("empty output file name; give -o FILE.h5 or -o - for stdout");
  if (name == "-") {
    if (closed_at_start(STDOUT_FILENO))
      throw UsageError("'-o -' writes to stdout, but stdout is closed; redirect it to a file or a pipe, or give -o FILE.h5");
    if (isatty(STDOUT_FILENO))
      throw UsageError("'-o -' writes binary HDF5 to stdout, which is a terminal; pipe it into another tool or give a file");
    t.kind = OutputTarget::kStdout;
    return t;
  }
  struct stat st {};
  if (stat(name.c_str(), &st) == 0) {  // exists (through any links)
    if (S_ISDIR(st.st_mode)) throw UsageError("output " + quoted(name) + " is a directory; give a file name");
    if (!S_ISREG(st.st_mode)) {
      if (S_ISSOCK(st.st_mode))
        throw UsageError("output " + quoted(name) + " is a socket, which cannot be opened as a file; give a file name");
      // A FIFO is not opened now: its reader would see the end of the file at once. It is opened
      // at the end, and that waits for a reader, as a shell redirection does.
      if (S_ISFIFO(st.st_mode)) {
        if (access(name.c_str(), W_OK) != 0)
          throw UsageError("output " + quoted(name) + " is a named pipe that is not writable (" + std::strerror(errno) +
                           "); give a file name");
      } else {
        const int fd = open(name.c_str(), O_WRONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
        if (fd < 0)
          throw UsageError("output " + quoted(name) + " is a " + kind_of(st.st_mode) + " that cannot be opened for writing (" +
                           std::strerror(errno) + "); give a file name");
        const bool terminal = isatty(fd);
        close(fd);
        if (terminal && binary)
          throw UsageError("output " + quoted(name) + " is a terminal; binary data would garble it, give a file name");
      }
      t.kind = OutputTarget::kStream;
      t.path = name;
      return t;
    }
    std::error_code ec;
    t.path = fs::canonical(name, ec).string();
    if (ec) t.path = name;
  } else {
    t.path = end_of_links(name);
  }
  const fs::path target(t.path);
  const fs::path dir = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  std::error_code ec;
  if (!fs::is_directory(dir, ec))
    throw UsageError(fs::exists(dir, ec) ? "output " + quoted(name) + " lies under " + quoted(dir.string()) +
                                               ", which is a file, not a directory; give a path in a directory"
                                         : "output directory " + quoted(dir.string()) + " does not exist; create it first (mkdir -p)");
  if (access(dir.c_str(), W_OK) != 0)
    throw UsageError("output directory " + quoted(dir.string()) + " is not writable; choose another -o");
  t.dir = dir.string();
  return t;
}

}  // namespace gg::detail
