// gg-sim --dim 3: the starts (random, face-centred cubic lattice), every output (snapshots with
// velocities, the 3D H5MD box as a time series, the pressure's unit), checkpoints that resume bit
// for bit, and the refusals.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "gg/errors.hpp"
#include "ggsim/effects/effect_set.hpp"
#include "ggsim/recorder.hpp"
#include "sim_3d_harness.hpp"

namespace {

double min_pair_distance(const gg::Snapshots& s, std::size_t frame) {
  const double* x = s.frame_position(frame);
  double best = INFINITY;
  for (std::size_t i = 0; i < s.n_particles; ++i)
    for (std::size_t j = 0; j < i; ++j) {
      double d2 = 0;
      for (int k = 0; k < 3; ++k) {
        double d = x[i * 3 + k] - x[j * 3 + k];
        d -= s.edges[k] * std::nearbyint(d / s.edges[k]);
        d2 += d * d;
      }
      best = std::min(best, d2);
    }
  return std::sqrt(best);
}

TEST(GgSim3D, LatticeStartIsFaceCentredCubic) {
  // 4 m^3 = 500 sites (m = 5) at eta = 0.5: cell a = L/5, nearest neighbours a/sqrt(2) apart.
  gg::test::TempDir dir;
  ggsim::SimConfig c = ggtest::scene_3d(500, 0.5, 1, dir.file("fcc.h5"));
  c.init = "lattice";
  c.t_max = 1;
  c.snapshots = {0};
  ASSERT_EQ(ggtest::simulate(c), 0);
  const gg::Snapshots s = gg::read_snapshots(gg::H5Input(dir.file("fcc.h5")));
  ASSERT_EQ(s.dim, 3);
  ASSERT_EQ(s.n_particles, 500u);
  const double L = std::cbrt(500 / ggtest::sphere_density(0.5));
  EXPECT_NEAR(min_pair_distance(s, 0), L / 5 / std::sqrt(2.0), 1e-9);
  // Densest packing pi/(3 sqrt 2) = 0.7405: beyond it no lattice fits.
  ggsim::SimConfig dense = ggtest::scene_3d(500, 0.75, 1, dir.file("dense.h5"));
  dense.init = "lattice";
  dense.t_max = 1;
  EXPECT_THROW(ggtest::simulate(dense), gg::UsageError);
  EXPECT_FALSE(std::filesystem::exists(dir.file("dense.h5")));
}

TEST(GgSim3D, SnapshotsBoxAndUnitsAreThreeDimensional) {
  gg::test::TempDir dir;
  ggsim::SimConfig c = ggtest::scene_3d(800, 0.3, 0.8, dir.file("run.h5"));
  c.t_max = 5;
  c.snapshots = {0, 2, 5};
  c.velocities = true;
  c.effects.set<ggsim::PressureParameters>().on = true;
  ASSERT_EQ(ggtest::simulate(c), 0);
  gg::H5Input in(dir.file("run.h5"));
  const gg::Snapshots s = gg::read_snapshots(in);
  ASSERT_EQ(s.dim, 3);
  ASSERT_EQ(s.frames(), 3u);
  ASSERT_EQ(s.velocity.size(), 3u * 800 * 3);
  const double L = std::cbrt(800 / ggtest::sphere_density(0.3));
  for (double edge : s.edges) EXPECT_NEAR(edge, L, 1e-12 * L);
  for (std::size_t f = 0; f < s.frames(); ++f) EXPECT_GE(min_pair_distance(s, f), 1 - 1e-9);
  // The box as MDAnalysis reads it: an element with one diagonal [3][3] matrix of box vectors per
  // frame and position's step and time.
  const gg::Array edges = in.read("/particles/all/box/edges/value");
  EXPECT_EQ(edges.shape, (std::vector<std::size_t>{3, 3, 3}));
  for (std::size_t i = 0; i < edges.data.size(); ++i) EXPECT_EQ(edges.data[i], i % 9 % 4 == 0 ? s.edges[0] : 0.0) << i;
  EXPECT_EQ(in.read("/particles/all/box/edges/time").data, s.time);
  EXPECT_EQ(in.read_int("/particles/all/box/edges/step"), s.step);
  EXPECT_EQ(in.attr_double("/particles/all/box", "dimension"), 3.0);
  EXPECT_EQ(in.attr_strings("/particles/all/box", "boundary"), std::vector<std::string>(3, "periodic"));
  EXPECT_EQ(in.attr_string("/observables/pressure/value", "unit"), "m sigma-1 tau-2");
  EXPECT_EQ(in.attr_double("/parameters", "dim"), 3.0);
  // Temperature from the first snapshot's velocities: T0 = 1 = <v_x^2>.
  double sum2 = 0;
  for (std::size_t i = 0; i < 800 * 3; ++i) sum2 += s.velocity[i] * s.velocity[i];
  EXPECT_NEAR(sum2 / (800 * 3), 1, 1e-12);
}

// Every dataset of the particles and the observables, for bit-for-bit comparisons.
std::vector<std::vector<double>> datasets(const std::string& path) {
  gg::H5Input in(path);
  std::vector<std::vector<double>> all;
  for (const char* d : {"/particles/all/position/value", "/particles/all/velocity/value", "/particles/all/position/time",
                        "/observables/kinetic_energy/value", "/observables/pressure/value",
                        "/observables/collisions_per_particle/value"})
    all.push_back(in.read(d).data);
  return all;
}

TEST(GgSim3D, InterruptedRunResumesBitForBit) {
  gg::test::TempDir dir;
  ggsim::SimConfig c = ggtest::scene_3d(2000, 0.3, 0.9, dir.file("full.h5"));
  c.effects.set<ggsim::TcParameters>().tc = 1e-5;
  c.effects.set<ggsim::PressureParameters>().on = true;
  c.velocities = true;
  c.t_max = 30;
  c.snapshots_per_decade = 4;
  ASSERT_EQ(ggtest::simulate(c), 0);
  // A stop request standing from the start ends the run at its first poll (65536 events in), with
  // a checkpoint: the same place every time.
  c.output = dir.file("part.h5");
  ggsim::g_stop_requested = 1;
  const int status = ggtest::simulate(c);
  ggsim::g_stop_requested = 0;
  ASSERT_EQ(status, 1);
  ASSERT_TRUE(std::filesystem::exists(dir.file("part.h5.checkpoint.h5")));
  c.resume = dir.file("part.h5.checkpoint.h5");
  ASSERT_EQ(ggtest::simulate(c), 0);
  EXPECT_EQ(datasets(dir.file("part.h5")), datasets(dir.file("full.h5")));
  EXPECT_FALSE(std::filesystem::exists(dir.file("part.h5.checkpoint.h5")));
}

TEST(GgSim3D, AFourthDimensionIsRefusedNamingTheFlag) {
  ggsim::SimConfig c = ggtest::scene_3d(100, 0.1, 1, "x.h5");
  c.dim = 4;
  c.t_max = 1;
  try {
    c.resolve(true, false, true);
    ADD_FAILURE() << "--dim 4 accepted";
  } catch (const gg::UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("--dim must be 1, 2 or 3"), std::string::npos) << e.what();
  }
}

}  // namespace
