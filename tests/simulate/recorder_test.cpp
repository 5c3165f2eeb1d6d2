// The recorder's logarithmic time grid (recorder.hpp, LogTimes; docs/DESIGN.md "Units and
// definitions"): t = 0, then 10^(k/K) for every integer k with from <= 10^(k/K) < t_max, then
// t_max itself; with t_max infinite the grid goes on.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "ggsim/recorder.hpp"

namespace {

// The grid's times up to (and including) the first infinite one, at most `most`.
std::vector<double> times(ggsim::LogTimes g, std::size_t most = 1000) {
  std::vector<double> t;
  while (t.size() < most) {
    t.push_back(g.next());
    if (std::isinf(g.next())) break;
    g.pop();
  }
  return t;
}

constexpr double kInf = std::numeric_limits<double>::infinity();

}  // namespace

TEST(LogTimes, ZeroThenKPerDecadeFromFromUpToTMaxThenTMaxThenNothing) {
  const auto t = times(ggsim::LogTimes(10, 0.01, 1000, true));
  // 0; k = -20 ... 29 (0.01 <= 10^(k/10) < 1000): 50 times; 1000; then no more (infinity).
  ASSERT_EQ(t.size(), 53u);
  EXPECT_EQ(t[0], 0.0);
  EXPECT_EQ(t[51], 1000.0);
  EXPECT_TRUE(std::isinf(t[52]));
  // Whole decades land on the decade exactly.
  EXPECT_DOUBLE_EQ(t[1], 0.01);
  EXPECT_DOUBLE_EQ(t[11], 0.1);
  EXPECT_DOUBLE_EQ(t[21], 1.0);
  EXPECT_DOUBLE_EQ(t[31], 10.0);
  EXPECT_DOUBLE_EQ(t[41], 100.0);
  // Successive times a constant factor 10^(1/10) apart.
  const double ratio = std::pow(10.0, 0.1);
  for (std::size_t i = 2; i <= 50; ++i) EXPECT_NEAR(t[i] / t[i - 1], ratio, 1e-12) << i;
  EXPECT_LT(t[50], 1000.0);
}

TEST(LogTimes, FirstTimeIsTheFirstGridPointAtOrAfterFrom) {
  // 0.015 lies between 10^(-19/10) = 0.01259 and 10^(-18/10) = 0.01585.
  EXPECT_NEAR(ggsim::LogTimes(10, 0.015, 1, false).next(), std::pow(10.0, -1.8), 1e-15);
  // A from that is a grid point, as computed in floating point, starts there (not one later):
  // 10^(1/20) = 1.1220..., whose log10 times 20 may round just above 1.
  for (int k = -40; k <= 40; ++k) {
    const double from = std::pow(10.0, k / 20.0);
    EXPECT_DOUBLE_EQ(ggsim::LogTimes(20, from, kInf, false).next(), from) << k;
  }
}

TEST(LogTimes, WithoutZeroAndWithAFromBeyondTMaxOnlyTMaxIsLeft) {
  const auto t = times(ggsim::LogTimes(5, 10, 3, false));
  ASSERT_EQ(t.size(), 2u);
  EXPECT_EQ(t[0], 3.0);
  EXPECT_TRUE(std::isinf(t[1]));
  // With zero: 0, then t_max.
  const auto z = times(ggsim::LogTimes(5, 10, 3, true));
  ASSERT_EQ(z.size(), 3u);
  EXPECT_EQ(z[0], 0.0);
  EXPECT_EQ(z[1], 3.0);
}

TEST(LogTimes, InfiniteTMaxGoesOnForever) {
  const auto t = times(ggsim::LogTimes(2, 1, kInf, true), 200);
  ASSERT_EQ(t.size(), 200u);  // never ran out
  EXPECT_EQ(t[0], 0.0);
  EXPECT_DOUBLE_EQ(t[1], 1.0);
  EXPECT_DOUBLE_EQ(t[3], 10.0);
  EXPECT_NEAR(t[199] / 1e99, 1.0, 1e-12);  // k = 198: 10^99
}

TEST(LogTimes, StateRestoresThePlaceOnTheGrid) {
  ggsim::LogTimes a(20, 0.01, 1e4, true);
  for (int i = 0; i < 37; ++i) a.pop();
  ggsim::LogTimes b(20, 0.01, 1e4, true);
  b.restore(a.state());
  EXPECT_EQ(times(b), times(a));
}
