// gg-velocity --profile on hand-built particles whose slabs are known by hand: a sheared gas
// (u_x = gamma y) with peculiar velocities in +- pairs, so that each slab's density, mean velocity and
// temperature follow from the construction; the mean and standard error over two frames; masses
// weighting u and T; the slabs of --bin-width; the axis of a 3D box.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <vector>

#include "gg/h5file.hpp"
#include "gg/trajectory.hpp"
#include "structure_tools.hpp"
#include "test_support.hpp"
#include "velocity.hpp"

namespace fs = std::filesystem;

namespace gg {
namespace {

// Equal to round-off, NaN equal to NaN.
void expect_values(const std::vector<double>& got, const std::vector<double>& want, const std::string& what) {
  ASSERT_EQ(got.size(), want.size()) << what;
  for (std::size_t j = 0; j < want.size(); ++j) {
    if (std::isnan(want[j]))
      EXPECT_TRUE(std::isnan(got[j])) << what << "[" << j << "] = " << got[j] << ", want NaN";
    else
      EXPECT_NEAR(got[j], want[j], 1e-14 * std::max(1.0, std::abs(want[j]))) << what << "[" << j << "]";
  }
}

// One particle of the sheared gas: its height y and its velocity.
struct Particle {
  double y, vx, vy;
};

// A 6 x 8 box (2D) cut into 4 slabs of height 2 along y (slab volume 12), two frames of 8 particles.
// Flow: u_x = gamma y_c at each slab centre y_c = 1, 3, 5, 7 (gamma = 1/8); u_y = 0 in frame 0 and 1/2 in
// frame 1. Peculiar velocities in +- pairs: A = (1/2, 1/4) (|c|^2 = 5/16), B = (1, -1/2) (|c|^2 = 5/4).
//   frame 0: slab 0 pair A, slab 1 pairs A and B, slab 2 pair B, slab 3 empty;
//   frame 1: slab 0 pairs A and B, slab 1 pair A, slab 2 and slab 3 one particle each (peculiar 0).
// Heights sit on the slab edges too (2.0 is slab 1, 3.999 slab 1, 7.999 slab 3).
constexpr double kGamma = 0.125;

std::vector<Particle> pair_of(double y1, double y2, double ux, double uy, double cx, double cy) {
  return {{y1, ux + cx, uy + cy}, {y2, ux - cx, uy - cy}};
}

Snapshots sheared_frames() {
  const double u0 = kGamma * 1, u1 = kGamma * 3, u2 = kGamma * 5, u3 = kGamma * 7;
  std::vector<std::vector<Particle>> frames(2);
  const auto add = [](std::vector<Particle>& f, const std::vector<Particle>& p) { f.insert(f.end(), p.begin(), p.end()); };
  // Frame 0 (u_y = 0).
  add(frames[0], pair_of(0.0, 1.999, u0, 0, 0.5, 0.25));
  add(frames[0], pair_of(2.0, 2.5, u1, 0, 0.5, 0.25));
  add(frames[0], pair_of(3.0, 3.999, u1, 0, 1.0, -0.5));
  add(frames[0], pair_of(4.0, 5.5, u2, 0, 1.0, -0.5));
  // Frame 1 (u_y = 1/2).
  add(frames[1], pair_of(0.5, 1.0, u0, 0.5, 0.5, 0.25));
  add(frames[1], pair_of(1.5, 1.75, u0, 0.5, 1.0, -0.5));
  add(frames[1], pair_of(2.0, 3.5, u1, 0.5, 0.5, 0.25));
  add(frames[1], {{4.25, u2, 0.5}, {7.999, u3, 0.5}});

  Snapshots s;
  s.dim = 2;
  s.edges = {6.0, 8.0};
  s.n_particles = 8;
  for (std::size_t k = 0; k < frames.size(); ++k) {
    s.time.push_back(static_cast<double>(k));
    s.step.push_back(static_cast<std::int64_t>(10 * k));
    for (std::size_t j = 0; j < frames[k].size(); ++j) {
      const Particle& p = frames[k][j];
      s.position.insert(s.position.end(), {0.5 + 0.7 * static_cast<double>(j), p.y});
      s.velocity.insert(s.velocity.end(), {p.vx, p.vy});
    }
  }
  return s;
}

class VelocityProfile : public ::testing::Test {
 protected:
  void SetUp() override {
    H5Output out(dir_.file("in.h5"));
    write_snapshots(out, sheared_frames(), "test");
    out.commit();
  }

  // gg-velocity --profile y on the sheared frames, into `output` in the scratch directory.
  VelocityConfig config(const std::string& output) const {
    VelocityConfig c;
    c.input = dir_.file("in.h5");
    c.output = dir_.file(output);
    c.profile = "y";
    return c;
  }

  test::TempDir dir_;
};

TEST_F(VelocityProfile, ShearedSlabsGiveTheHandBuiltDensityFlowAndTemperature) {
  VelocityConfig c = config("profile.h5");
  c.bins = 4;
  ASSERT_EQ(run_velocity(c, CommonFlags{false, true}, {"gg-velocity"}), 0);
  H5Input in(c.output);
  const std::string g = "/velocity/profile/";
  expect_values(in.read(g + "position").data, {1, 3, 5, 7}, "position");
  // Particles per slab: (2, 4, 2, 0) and (4, 2, 1, 1), over a slab volume of 12.
  expect_values(in.read(g + "density").data, {0.25, 0.25, 0.125, 1.0 / 24}, "density");
  expect_values(in.read(g + "density_stderr").data, {1.0 / 12, 1.0 / 12, 1.0 / 24, 1.0 / 24}, "density_stderr");
  // u = (gamma y_c, 0) and (gamma y_c, 1/2); slab 3 holds a particle in frame 1 only.
  const Array u = in.read(g + "velocity");
  EXPECT_EQ(u.shape, (std::vector<std::size_t>{4, 2}));
  expect_values(u.data, {0.125, 0.25, 0.375, 0.25, 0.625, 0.25, 0.875, 0.5}, "velocity");
  expect_values(in.read(g + "velocity_stderr").data, {0, 0.25, 0, 0.25, 0, 0.25, kNaN, kNaN}, "velocity_stderr");
  // T = sum |c|^2 / (d (N - 1)): pair A 2 (5/16) / 2, pairs A and B 2 (5/16 + 5/4) / 6, pair B 2 (5/4) / 2;
  // undefined for one particle or none.
  const double TA = 0.3125, TAB = 3.125 / 6, TB = 1.25;
  expect_values(in.read(g + "temperature").data, {(TA + TAB) / 2, (TAB + TA) / 2, TB, kNaN}, "temperature");
  expect_values(in.read(g + "temperature_stderr").data, {(TAB - TA) / 2, (TAB - TA) / 2, kNaN, kNaN},
                "temperature_stderr");
  EXPECT_EQ(in.read_int(g + "velocity_frames"), (std::vector<std::int64_t>{2, 2, 2, 1}));
  EXPECT_EQ(in.read_int(g + "temperature_frames"), (std::vector<std::int64_t>{2, 2, 1, 0}));
  EXPECT_EQ(in.attr_double("/velocity/profile", "bin_width"), 2.0);
  EXPECT_EQ(in.attr_double("/velocity/profile", "bins"), 4.0);
}

TEST_F(VelocityProfile, BinWidthGivesRoundedSlabsOfTheEdge) {
  VelocityConfig c = config("width.h5");
  ASSERT_EQ(run_velocity(c, CommonFlags{false, true}, {"gg-velocity"}), 0);  // default: width 1
  EXPECT_EQ(H5Input(c.output).read("/velocity/profile/position").data.size(), 8u);
  c = config("width3.h5");
  c.bin_width = 3;  // 8 / 3 rounds to 3 slabs of 8/3
  ASSERT_EQ(run_velocity(c, CommonFlags{false, true}, {"gg-velocity"}), 0);
  expect_values(H5Input(c.output).read("/velocity/profile/position").data, {4.0 / 3, 4.0, 20.0 / 3}, "position");
}

TEST_F(VelocityProfile, NoProfileGroupWithoutTheOption) {
  VelocityConfig c = config("none.h5");
  c.profile.clear();
  ASSERT_EQ(run_velocity(c, CommonFlags{false, true}, {"gg-velocity"}), 0);
  EXPECT_TRUE(H5Input(c.output).exists("/velocity/temperature"));
  EXPECT_FALSE(H5Input(c.output).exists("/velocity/profile"));
}

TEST_F(VelocityProfile, AnAxisBeyondTheDimensionIsAUsageErrorAndWritesNothing) {
  VelocityConfig c = config("z.h5");
  c.profile = "z";
  EXPECT_THROW(run_velocity(c, CommonFlags{false, true}, {"gg-velocity"}), UsageError);
  EXPECT_FALSE(fs::exists(c.output));
}

// Two slabs of a 4 x 4 box along x (slab volume 8): masses 1 and 3 with velocities (4, 0) and (0, 0)
// in slab 0, so u = (1, 0) and sum m |v - u|^2 = 1 * 9 + 3 * 1 = 12, T = 12 / (2 * 1); unit masses
// give u = (2, 0) and T = (4 + 4) / 2. Slab 1 holds one particle: u is its velocity, T undefined.
// A fourth row of mass 0 in slab 0 (an aggregate's merged particle) is no particle at all.
TEST(SlabProfile, MassesWeightTheFlowAndTheTemperature) {
  const std::vector<double> position = {0.5, 1.0, 1.5, 3.0, 3.0, 2.0, 1.0, 1.0};
  const std::vector<double> velocity = {4, 0, 0, 0, 1, 1, 50, -50};
  const std::vector<double> mass = {1, 3, 2, 0};
  const SlabProfile m = slab_profile(position.data(), velocity.data(), mass.data(), 4, {4.0, 4.0}, 0, 2);
  expect_values(m.count, {2, 1}, "count");
  expect_values(m.density, {0.25, 0.125}, "density");
  expect_values(m.velocity, {1, 0, 1, 1}, "velocity");
  expect_values(m.temperature, {6, kNaN}, "temperature");
  const SlabProfile unit = slab_profile(position.data(), velocity.data(), nullptr, 3, {4.0, 4.0}, 0, 2);  // rows 0-2
  expect_values(unit.velocity, {2, 0, 1, 1}, "velocity (unit masses)");
  expect_values(unit.temperature, {4, kNaN}, "temperature (unit masses)");
}

// A 2 x 3 x 10 box cut along z into 5 slabs of volume 2 x 3 x 2 = 12: the particle at z = 9.5 is in the
// last slab, whatever its x and y; the one at z = 0 in the first.
TEST(SlabProfile, TheLastAxisOfA3dBox) {
  const std::vector<double> position = {1.9, 2.9, 9.5, 0.1, 0.1, 0.0, 1.0, 1.0, 4.0};
  const std::vector<double> velocity(9, 0.0);
  const SlabProfile p = slab_profile(position.data(), velocity.data(), nullptr, 3, {2.0, 3.0, 10.0}, 2, 5);
  expect_values(p.count, {1, 0, 1, 0, 1}, "count");
  expect_values(p.density, {1.0 / 12, 0, 1.0 / 12, 0, 1.0 / 12}, "density");
}

}  // namespace
}  // namespace gg
