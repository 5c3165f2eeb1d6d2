// The time-left estimate of progress lines (gg/remaining_time.hpp), on made-up clocks.
#include "gg/remaining_time.hpp"

#include <gtest/gtest.h>

namespace gg {
namespace {

TEST(CommonRemainingTime, SteadyRateExtrapolatesToTheEnd) {
  RemainingTime r;
  for (int s = 0; s <= 10; ++s) r.add(s, 0.01 * s);  // 1% per second
  ASSERT_TRUE(r.seconds_left());
  EXPECT_DOUBLE_EQ(*r.seconds_left(), 90);
}

TEST(CommonRemainingTime, UsesTheLastMinuteOnly) {
  RemainingTime r;
  for (int s = 0; s <= 100; ++s) r.add(s, 0.001 * s);        // slow start: 0.1% per second
  for (int s = 101; s <= 300; ++s) r.add(s, 0.1 + 0.002 * (s - 100));  // then 0.2% per second
  // f(300) = 0.5; the window holds only the faster rate: 0.5 / 0.002 = 250 s.
  EXPECT_NEAR(*r.seconds_left(), 250, 1e-9);
}

TEST(CommonRemainingTime, NoEstimateWithoutProgressOrTime) {
  RemainingTime r;
  EXPECT_FALSE(r.seconds_left());
  r.add(0, 0.2);
  r.add(0.5, 0.3);  // less than a second
  EXPECT_FALSE(r.seconds_left());
  r.add(2, 0.3);
  RemainingTime stalled;
  stalled.add(0, 0.4);
  stalled.add(5, 0.4);
  EXPECT_FALSE(stalled.seconds_left());
}

TEST(CommonRemainingTime, Wording) {
  EXPECT_EQ(describe_time_left(44.6), "about 45 s left");
  EXPECT_EQ(describe_time_left(200), "about 3 min 20 s left");
  EXPECT_EQ(describe_time_left(7500), "about 2 h 5 min left");
  EXPECT_EQ(describe_time_left(-3), "about 0 s left");
}

}  // namespace
}  // namespace gg
