// Progress line on stderr: format, throttling, final newline.
#include "gg/progress.hpp"

#include <gtest/gtest.h>

#include "test_support.hpp"

namespace gg {
namespace {

TEST(CommonProgress, PrintsPercentThrottlesAndEndsTheLine) {
  test::TempDir dir;
  test::with_fd_redirected(2, dir.file("err"), [] {
    Progress p(true, "gg-sim");
    p.update(0.452, "t = 12.5");
    p.update(0.5, "dropped: less than a quarter second later");
    p.update(1.0, "done");  // the end is always shown; spaces blank the longer line before
  });
  EXPECT_EQ(test::read_bytes(dir.file("err")), "\rgg-sim 45.2% t = 12.5\rgg-sim 100.0% done   \n");
}

TEST(CommonProgress, DisabledPrintsNothing) {
  test::TempDir dir;
  test::with_fd_redirected(2, dir.file("err"), [] {
    Progress p(false, "gg-sim");
    p.update(0.3);
    p.update(1.0);
  });
  EXPECT_EQ(test::read_bytes(dir.file("err")), "");
}

}  // namespace
}  // namespace gg
