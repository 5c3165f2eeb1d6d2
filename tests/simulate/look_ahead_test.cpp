// The engine's look-ahead only asks memory for what events will read (look_ahead.hpp);
// its extra steps, taken for mid-sized N, must leave the trajectory as it is. They read the
// records of collision partners and the cell lists around them, so a run with them also checks,
// under the sanitizers, that no read goes astray.
#include <gtest/gtest.h>

#include <cstdint>
#include <tuple>
#include <utility>
#include <vector>

#include "engine_harness.hpp"

namespace {

using ggsim::Effects;
using ggsim::EngineParameters;
using ggsim::Vec;

// Runs `start` for `collisions` with the look-ahead's extra steps on or off; returns positions,
// velocities (by the numbers of the start) and the clock.
std::tuple<std::vector<Vec<2>>, std::vector<Vec<2>>, double> run(const ggtest::Start<2>& s, bool deeper,
                                                                std::uint64_t collisions) {
  EngineParameters par;
  par.rule.e = 0.5;
  par.rule.effects.set<ggsim::TcParameters>().tc = 1e-3;
  par.fetch_deeper = deeper;
  ggsim::Engine<2, Effects<ggsim::TcEffect>> eng(s.box, s.r, s.v, par);
  ggtest::Silent none;
  EXPECT_EQ(eng.run(ggsim::kNever, collisions, none), ggsim::StopReason::kCollisionBudget);
  auto o = ggtest::observed(eng, eng.now());
  return {std::move(o.r), std::move(o.v), eng.now()};
}

TEST(LookAhead, ExtraStepsLeaveTheTrajectoryAsItIs) {
  const auto s = ggtest::random_start<2>(60, 0.37, 13);  // N = 1332, far below where they are on by default
  const std::uint64_t collisions = 20 * s.r.size();  // 40 per particle: clusters forming
  const auto [r1, v1, t1] = run(s, true, collisions);
  const auto [r0, v0, t0] = run(s, false, collisions);
  EXPECT_EQ(t1, t0);
  std::size_t differ = 0;
  for (std::size_t i = 0; i < r0.size(); ++i) differ += r1[i] != r0[i] || v1[i] != v0[i];
  EXPECT_EQ(differ, 0u) << "particles whose position or velocity differ after " << collisions << " collisions";
}

}  // namespace
