// The engine renumbers its particles in space now and then (engine.hpp, renumber()); that must
// change nothing but where records lie in memory: observers see the numbers of the start, and
// the trajectory is the one of an engine that never renumbers.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <tuple>
#include <vector>

#include "engine_harness.hpp"
#include "ggsim/permutation.hpp"

namespace {

using ggsim::Effects;
using ggsim::EngineParameters;
using ggsim::Vec;

TEST(Renumber, PermuteInPlaceFollowsTheOrder) {
  // order[k] = where element k comes from: two cycles (0 2 4) (1 3) and a fixed point 5.
  std::vector<char> a = {'a', 'b', 'c', 'd', 'e', 'f'};
  ggsim::permute_in_place(a, {2, 3, 4, 1, 0, 5});
  EXPECT_EQ(std::string(a.begin(), a.end()), "cdebaf");
}

// Runs `start` to t_end with renumbering every `every` events per particle; returns positions,
// velocities (by the numbers of the start) and the collision count.
template <class Fx>
std::tuple<std::vector<Vec<2>>, std::vector<Vec<2>>, std::uint64_t> run(const ggtest::Start<2>& s, double e, double tc,
                                                                       double every, double t_end) {
  EngineParameters par;
  par.rule = {e, 0.0, tc};
  par.renumber_every = every;
  ggsim::Engine<2, Fx> eng(s.box, s.r, s.v, par);
  ggtest::Silent none;
  eng.run(t_end, UINT64_MAX, none);
  std::vector<Vec<2>> r, v;
  for (std::size_t i = 0; i < eng.size(); ++i) r.push_back(eng.position_at(i, t_end)), v.push_back(eng.particle(i).v);
  return {r, v, eng.collisions()};
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

TEST(Renumber, SameTrajectoryAsWithoutRenumbering) { expect_same_trajectory<Effects<false, false, false>>(0.9, 0); }

TEST(Renumber, SameTrajectoryWithTheTcModel) { expect_same_trajectory<Effects<false, true, false>>(0.5, 1e-3); }

}  // namespace
