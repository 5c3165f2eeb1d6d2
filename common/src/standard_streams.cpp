#include "gg/standard_streams.hpp"

#include <cerrno>

#include <fcntl.h>
#include <unistd.h>

namespace gg {
namespace {

bool g_closed[3] = {false, false, false};

}  // namespace

void guard_standard_streams() {
  static const bool done = [] {
    for (int fd = 0; fd < 3; ++fd) {
      if (fcntl(fd, F_GETFD) != -1 || errno != EBADF) continue;
      g_closed[fd] = true;
      // open() returns the lowest free number: this one, as the lower ones are open by now.
      const int null = open("/dev/null", fd == 0 ? O_RDONLY : O_WRONLY);
      if (null >= 0 && null != fd) {
        dup2(null, fd);
        close(null);
      }
    }
    return true;
  }();
  (void)done;
}

bool closed_at_start(int fd) { return fd >= 0 && fd < 3 && g_closed[fd]; }

}  // namespace gg
