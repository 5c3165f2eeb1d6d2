// The engine renumbers its particles in space now and then (engine.hpp, renumber()); that must
// change nothing but where records lie in memory: observers see the numbers of the start, and
// the trajectory is the one of an engine that never renumbers.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "engine_harness.hpp"
#include "ggsim/permutation.hpp"

namespace {

using ggsim::Effects;
using ggsim::EngineParameters;
using ggsim::Vec;

TEST(Renumber, PermuteByRankFollowsTheRanks) {
  // Each element carries its rank (where it goes), as the cell grid's entries do: two cycles
  // 0 -> 4 -> 2 -> 0 and 1 -> 3 -> 1, and a fixed point 5.
  std::vector<std::pair<char, std::uint32_t>> a = {{'a', 4}, {'b', 3}, {'c', 0}, {'d', 1}, {'e', 2}, {'f', 5}};
  ggsim::permute_by_rank(a, [&](std::size_t k) { return a[k].second; });
  std::string letters;
  for (std::size_t k = 0; k < a.size(); ++k) {
    letters += a[k].first;
    EXPECT_EQ(a[k].second, k);
  }
  EXPECT_EQ(letters, "cdebaf");
}

// Runs `start` to t_end with renumbering every `every` events per particle; returns positions,
// velocities (by the numbers of the start) and the collision count.
template <class Fx>
std::tuple<std::vector<Vec<2>>, std::vector<Vec<2>>, std::uint64_t> run(const ggtest::Start<2>& s, double e, double tc,
                                                                       double every, double t_end) {
  EngineParameters par;
  par.rule.e = e;
  par.rule.effects.set<ggsim::TcParameters>().tc = tc;
  par.renumber_every = every;
  ggsim::Engine<2, Fx> eng(s.box, s.r, s.v, par);
  ggtest::Silent none;
  eng.run(t_end, UINT64_MAX, none);
  auto o = ggtest::observed(eng, t_end);
  return {std::move(o.r), std::move(o.v), eng.collisions()};
}

template <class Fx>
void expect_same_trajectory(double e, double tc) {
  const auto s = ggtest::random_start<2>(60, 0.37, 11);  // N = 1332
  // Renumbered every quarter event per particle (about 40 times by t = 4), and never.
  const auto [r1, v1, c1] = run<Fx>(s, e, tc, 0.25, 4.0);
  const auto [r0, v0, c0] = run<Fx>(s, e, tc, 1e30, 4.0);
  ASSERT_GT(2 * c0, 5 * s.r.size());  // more than 5 collisions per particle
  EXPECT_EQ(c1, c0);
  std::size_t differ = 0;
  for (std::size_t i = 0; i < r0.size(); ++i) differ += r1[i] != r0[i] || v1[i] != v0[i];
  EXPECT_EQ(differ, 0u) << "particles whose position or velocity differ at t = 4";
}

TEST(Renumber, SameTrajectoryAsWithoutRenumbering) { expect_same_trajectory<Effects<>>(0.9, 0); }

TEST(Renumber, SameTrajectoryWithTheTcModel) { expect_same_trajectory<Effects<ggsim::TcEffect>>(0.5, 1e-3); }

}  // namespace
