// H5MD 1.1 snapshots and observables (docs/DESIGN.md "Files"): layout, round trips, validation.
#include "gg/trajectory.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "gg/errors.hpp"
#include "gg/h5file.hpp"
#include "test_support.hpp"

namespace gg {
namespace {

using test::expect_error;
using test::TempDir;

// T frames of N particles in a box of edges L, coordinates spread over [0, L).
Snapshots make_snapshots(int dim, std::size_t frames, std::size_t n, bool velocities) {
  Snapshots s;
  s.dim = dim;
  s.edges = dim == 1 ? std::vector<double>{10.0} : std::vector<double>{10.0, 7.5};
  s.n_particles = n;
  for (std::size_t k = 0; k < frames; ++k) {
    s.time.push_back(0.5 * static_cast<double>(k) + 0.125);
    s.step.push_back(static_cast<std::int64_t>(1000 * k));
    for (std::size_t i = 0; i < n; ++i)
      for (int a = 0; a < dim; ++a) {
        const double L = s.edges[static_cast<std::size_t>(a)];
        s.position.push_back(std::fmod(0.37 * static_cast<double>(i * 7 + k * 3 + static_cast<std::size_t>(a)) + 0.01, L));
        if (velocities) s.velocity.push_back(std::sin(static_cast<double>(i + 10 * k + static_cast<std::size_t>(a))));
      }
  }
  return s;
}

std::string write_file(const TempDir& dir, const std::string& name, const Snapshots& s, bool single = false) {
  H5Output out(dir.file(name));
  write_snapshots(out, s, "gg-test", single);
  out.commit();
  return dir.file(name);
}

void expect_same(const Snapshots& a, const Snapshots& b) {
  EXPECT_EQ(a.dim, b.dim);
  EXPECT_EQ(a.edges, b.edges);
  EXPECT_EQ(a.n_particles, b.n_particles);
  EXPECT_EQ(a.time, b.time);
  EXPECT_EQ(a.step, b.step);
  EXPECT_EQ(a.position, b.position);
  EXPECT_EQ(a.velocity, b.velocity);
}

class CommonTrajectoryRoundTrip : public ::testing::TestWithParam<std::tuple<int, bool>> {};

TEST_P(CommonTrajectoryRoundTrip, ExactInDoublePrecision) {
  const auto [dim, velocities] = GetParam();
  TempDir dir;
  const Snapshots s = make_snapshots(dim, 4, 25, velocities);
  const Snapshots back = read_snapshots(H5Input(write_file(dir, "t.h5", s)));
  expect_same(s, back);
  EXPECT_EQ(back.frames(), 4u);
  EXPECT_EQ(back.frame_position(2)[0], s.position[2 * 25 * static_cast<std::size_t>(dim)]);
}

INSTANTIATE_TEST_SUITE_P(CommonDimAndVelocity, CommonTrajectoryRoundTrip,
                         ::testing::Combine(::testing::Values(1, 2), ::testing::Bool()));

TEST(CommonTrajectory, WritesTheH5mdLayout) {
  TempDir dir;
  H5Input in(write_file(dir, "t.h5", make_snapshots(2, 3, 5, true)));
  EXPECT_EQ(in.attr_doubles("/h5md", "version"), (std::vector<double>{1, 1}));
  EXPECT_TRUE(in.attr_string("/h5md/author", "name").has_value());
  EXPECT_EQ(in.attr_string("/h5md/creator", "name"), "gg-test");
  EXPECT_TRUE(in.attr_string("/h5md/creator", "version").has_value());
  EXPECT_EQ(in.attr_double("/particles/all/box", "dimension"), 2);
  EXPECT_EQ(in.attr_strings("/particles/all/box", "boundary"), (std::vector<std::string>{"periodic", "periodic"}));
  EXPECT_EQ(in.read("/particles/all/box/edges", 1).data, (std::vector<double>{10.0, 7.5}));
  for (const std::string element : {"position", "velocity"}) {
    const std::string g = "/particles/all/" + element;
    EXPECT_EQ(in.shape(g + "/value"), (std::vector<std::size_t>{3, 5, 2}));
    EXPECT_EQ(in.read_int(g + "/step"), (std::vector<std::int64_t>{0, 1000, 2000}));
    EXPECT_EQ(in.read(g + "/time", 1).data, (std::vector<double>{0.125, 0.625, 1.125}));
  }
}

TEST(CommonTrajectory, NoVelocityGroupWhenNoVelocities) {
  TempDir dir;
  H5Input in(write_file(dir, "t.h5", make_snapshots(1, 2, 3, false)));
  EXPECT_FALSE(in.exists("/particles/all/velocity"));
  EXPECT_EQ(in.attr_strings("/particles/all/box", "boundary"), std::vector<std::string>{"periodic"});
}

// The box's boundary per axis (H5MD: "periodic" or "none"): written as Snapshots::periodic says,
// read back into it; a file without it is periodic along every axis; any other value is refused.
TEST(CommonTrajectory, BoundaryRoundTripAndOtherValuesRefused) {
  TempDir dir;
  Snapshots s = make_snapshots(2, 2, 3, false);
  s.periodic = {true, false};
  {
    H5Input in(write_file(dir, "closed.h5", s));
    EXPECT_EQ(in.attr_strings("/particles/all/box", "boundary"), (std::vector<std::string>{"periodic", "none"}));
    EXPECT_EQ(read_snapshots(in).periodic, (std::vector<bool>{true, false}));
    EXPECT_EQ(read_snapshots(H5Input(write_file(dir, "open.h5", make_snapshots(2, 2, 3, false)))).periodic,
              (std::vector<bool>{true, true}));
  }
  s.periodic = {false};
  EXPECT_THROW(write_file(dir, "short.h5", s), std::invalid_argument);
  const auto raw = [&](const std::string& name, const std::vector<std::string>& boundary) {
    H5Output out(dir.file(name));
    out.attr("/h5md", "version", std::vector<std::int64_t>{1, 1});
    out.attr("/particles/all/box", "dimension", 2);
    if (!boundary.empty()) out.attr("/particles/all/box", "boundary", boundary);
    out.write("/particles/all/box/edges", s.edges);
    out.write("/particles/all/position/value", Array{{2, 3, 2}, s.position});
    out.write("/particles/all/position/time", s.time);
    out.write("/particles/all/position/step", s.step);
    out.commit();
    return dir.file(name);
  };
  EXPECT_EQ(read_snapshots(H5Input(raw("none_given.h5", {}))).periodic, (std::vector<bool>{true, true}));
  expect_error<RuntimeError>([&] { read_snapshots(H5Input(raw("fixed.h5", {"periodic", "fixed"}))); },
                             {"fixed.h5", "boundary", "\"periodic\" or \"none\""});
  expect_error<RuntimeError>([&] { read_snapshots(H5Input(raw("one.h5", {"none"}))); }, {"one.h5", "2 values"});
}

// The H5MD image (gg-sim --unwrapped): whole numbers stored as integers, read back as they were,
// sharing position's step and time; an image that is not whole is refused.
TEST(CommonTrajectory, ImageRoundTripAndNonWholeImagesRefused) {
  TempDir dir;
  Snapshots s = make_snapshots(2, 3, 5, false);
  for (std::size_t i = 0; i < s.position.size(); ++i) s.image.push_back(static_cast<double>(i % 7) - 3);
  const std::string path = write_file(dir, "i.h5", s);
  {
    H5Input in(path);
    EXPECT_EQ(in.shape("/particles/all/image/value"), (std::vector<std::size_t>{3, 5, 2}));
    EXPECT_EQ(in.read_int("/particles/all/image/step"), s.step);
    EXPECT_EQ(in.read("/particles/all/image/time").data, s.time);
    EXPECT_EQ(read_snapshots(in).image, s.image);
    EXPECT_EQ(read_snapshots(in, {-1}).image, std::vector<double>(s.image.end() - 10, s.image.end()));
  }
  // Another writer may store the image as floats (H5MD allows it): 0.5 is no image.
  s.image[4] = 0.5;
  H5Output out(dir.file("float.h5"));
  Snapshots plain = s;
  plain.image.clear();
  write_snapshots(out, plain, "gg-test");
  out.write(std::string("/particles/all/image/value"), Array{{3, 5, 2}, s.image});
  out.commit();
  expect_error<RuntimeError>([&] { read_snapshots(H5Input(dir.file("float.h5"))); }, {"not a whole number"});
}

TEST(CommonTrajectory, SinglePrecisionStaysInsideTheBox) {
  TempDir dir;
  Snapshots s = make_snapshots(2, 1, 3, true);
  s.edges = {161.80339887498948, 161.80339887498948};  // not a float, so float(L - tiny) > L
  s.position = {161.8033988, 0.0, 1.0, 161.80339887498945, 80.9, 3.5};
  const Snapshots back = read_snapshots(H5Input(write_file(dir, "f.h5", s, true)));
  for (std::size_t i = 0; i < s.position.size(); ++i) {
    EXPECT_LT(back.position[i], s.edges[i % 2]);
    EXPECT_GE(back.position[i], 0.0);
    EXPECT_NEAR(back.position[i], s.position[i], 2e-5);
    EXPECT_EQ(back.velocity[i], static_cast<double>(static_cast<float>(s.velocity[i])));
  }
}

TEST(CommonTrajectory, FrameSelectionWithNegativeIndices) {
  TempDir dir;
  const Snapshots s = make_snapshots(2, 5, 4, true);
  H5Input in(write_file(dir, "t.h5", s));
  const Snapshots back = read_snapshots(in, {-1, 0, 2});
  ASSERT_EQ(back.frames(), 3u);
  EXPECT_EQ(back.time, (std::vector<double>{s.time[4], s.time[0], s.time[2]}));
  EXPECT_EQ(back.step, (std::vector<std::int64_t>{s.step[4], s.step[0], s.step[2]}));
  const std::size_t per = 4 * 2;
  EXPECT_TRUE(std::equal(back.frame_position(0), back.frame_position(0) + per, s.frame_position(4)));
  EXPECT_TRUE(std::equal(back.velocity.begin() + per, back.velocity.begin() + 2 * per, s.velocity.begin()));
  expect_error<UsageError>([&] { read_snapshots(in, {5}); }, {"frame 5", "t.h5", "5 frames"});
  expect_error<UsageError>([&] { read_snapshots(in, {-6}); }, {"frame -6"});
}

TEST(CommonTrajectory, CoordinatesOffByRoundingAreWrapped) {
  TempDir dir;
  Snapshots s = make_snapshots(1, 1, 3, false);
  s.position = {-1e-12, 10.0 + 1e-12, 10.0};  // L = 10: all within 1e-9 L of the box
  const Snapshots back = read_snapshots(H5Input(write_file(dir, "w.h5", s)));
  EXPECT_NEAR(back.position[0], 10.0 - 1e-12, 1e-15);
  EXPECT_NEAR(back.position[1], 1e-12, 1e-15);
  EXPECT_EQ(back.position[2], 0.0);
  for (double x : back.position) EXPECT_TRUE(x >= 0 && x < 10.0);
}

TEST(CommonTrajectory, RejectsPositionsOutsideTheBox) {
  TempDir dir;
  Snapshots s = make_snapshots(2, 2, 3, false);
  s.position[2 * 3 * 2 - 1] = 7.6;  // last particle of frame 1, y beyond L_y = 7.5
  const std::string path = write_file(dir, "out.h5", s);
  expect_error<RuntimeError>([&] { read_snapshots(H5Input(path)); }, {"out.h5", "particle 2", "frame 1", "outside the box"});
}

TEST(CommonTrajectory, RejectsNonFiniteValues) {
  TempDir dir;
  Snapshots s = make_snapshots(2, 2, 3, true);
  s.position[4] = std::numeric_limits<double>::quiet_NaN();
  expect_error<RuntimeError>([&] { read_snapshots(H5Input(write_file(dir, "nan.h5", s))); },
                             {"nan.h5", "/particles/all/position/value", "non-finite"});
  s = make_snapshots(2, 2, 3, true);
  s.velocity[1] = std::numeric_limits<double>::infinity();
  expect_error<RuntimeError>([&] { read_snapshots(H5Input(write_file(dir, "inf.h5", s))); },
                             {"inf.h5", "/particles/all/velocity/value", "non-finite"});
}

TEST(CommonTrajectory, Reads3DWithAFixedBoxAndWritesItsBoxAsATimeSeries) {
  TempDir dir;
  {  // another writer's file: box/edges a fixed [3] dataset
    H5Output out(dir.file("3d.h5"));
    out.attr("/h5md", "version", std::vector<std::int64_t>{1, 1});
    out.attr("/particles/all/box", "dimension", 3);
    out.write("/particles/all/box/edges", std::vector<double>{5, 6, 7});
    out.write("/particles/all/position/value", Array{{1, 2, 3}, {1, 1, 1, 2, 2, 6.5}});
    out.write("/particles/all/position/time", std::vector<double>{0});
    out.write("/particles/all/position/step", std::vector<std::int64_t>{0});
    out.commit();
  }
  Snapshots s = read_snapshots(H5Input(dir.file("3d.h5")));
  EXPECT_EQ(s.dim, 3);
  EXPECT_EQ(s.edges, (std::vector<double>{5, 6, 7}));
  EXPECT_EQ(s.position, (std::vector<double>{1, 1, 1, 2, 2, 6.5}));
  // Ours: box/edges/value [T][3][3], diagonal box vectors, with position's step and time (what
  // MDAnalysis reads in 3D).
  s.position.insert(s.position.end(), {4, 5, 6, 0, 0, 0});
  s.time.push_back(2.5);
  s.step.push_back(9);
  write_file(dir, "ours.h5", s);
  const H5Input in(dir.file("ours.h5"));
  EXPECT_EQ(in.read("/particles/all/box/edges/value").shape, (std::vector<std::size_t>{2, 3, 3}));
  const std::vector<double> box{5, 0, 0, 0, 6, 0, 0, 0, 7};
  std::vector<double> boxes = box;
  boxes.insert(boxes.end(), box.begin(), box.end());
  EXPECT_EQ(in.read("/particles/all/box/edges/value").data, boxes);
  EXPECT_EQ(in.read("/particles/all/box/edges/time").data, (std::vector<double>{0, 2.5}));
  EXPECT_EQ(in.read_int("/particles/all/box/edges/step"), (std::vector<std::int64_t>{0, 9}));
  const Snapshots back = read_snapshots(in);
  EXPECT_EQ(back.edges, s.edges);
  EXPECT_EQ(back.position, s.position);
  // Box vectors with a tilt (a triclinic box) are refused.
  {
    H5Output out(dir.file("tilted.h5"));
    out.attr("/h5md", "version", std::vector<std::int64_t>{1, 1});
    out.attr("/particles/all/box", "dimension", 3);
    out.write("/particles/all/box/edges/value", Array{{1, 3, 3}, {5, 0, 0, 1, 6, 0, 0, 0, 7}});
    out.write("/particles/all/position/value", Array{{1, 1, 3}, {1, 1, 1}});
    out.write("/particles/all/position/time", std::vector<double>{0});
    out.write("/particles/all/position/step", std::vector<std::int64_t>{0});
    out.commit();
  }
  expect_error<RuntimeError>([&] { read_snapshots(H5Input(dir.file("tilted.h5"))); }, {"tilted.h5", "not a rectangular box"});
  // A box of a dimension no tool knows is refused, naming it.
  {
    H5Output out(dir.file("4d.h5"));
    out.attr("/h5md", "version", std::vector<std::int64_t>{1, 1});
    out.attr("/particles/all/box", "dimension", 4);
    out.write("/particles/all/box/edges", std::vector<double>{5, 5, 5, 5});
    out.write("/particles/all/position/value", Array{{1, 1, 4}, {1, 1, 1, 1}});
    out.write("/particles/all/position/time", std::vector<double>{0});
    out.write("/particles/all/position/step", std::vector<std::int64_t>{0});
    out.commit();
  }
  expect_error<RuntimeError>([&] { read_snapshots(H5Input(dir.file("4d.h5"))); }, {"4d.h5", "box dimension 4 is invalid"});
}

TEST(CommonTrajectory, RejectsFilesThatAreNotH5mdOrMisshapen) {
  TempDir dir;
  {
    H5Output out(dir.file("plain.h5"));
    out.write("/cluster/time", std::vector<double>{1});
    out.commit();
  }
  expect_error<RuntimeError>([&] { read_snapshots(H5Input(dir.file("plain.h5"))); }, {"plain.h5", "not an H5MD file"});

  const Snapshots s = make_snapshots(2, 3, 2, false);
  {  // same content but a box that claims 1D: value's last dimension (2) no longer matches
    H5Output out(dir.file("wrong_dim.h5"));
    out.attr("/h5md", "version", std::vector<std::int64_t>{1, 1});
    out.attr("/particles/all/box", "dimension", 1);
    out.write("/particles/all/box/edges", std::vector<double>{10});
    out.write("/particles/all/position/value", Array{{3, 2, 2}, s.position});
    out.write("/particles/all/position/time", std::vector<double>{0, 1});  // and one time short
    out.write("/particles/all/position/step", std::vector<std::int64_t>{0, 1, 2});
    out.commit();
  }
  expect_error<RuntimeError>([&] { read_snapshots(H5Input(dir.file("wrong_dim.h5"))); },
                             {"wrong_dim.h5", "[frames][particles][1]"});
  {
    H5Output out(dir.file("bad_time.h5"));
    out.attr("/h5md", "version", std::vector<std::int64_t>{1, 1});
    out.attr("/particles/all/box", "dimension", 2);
    out.write("/particles/all/box/edges", s.edges);
    out.write("/particles/all/position/value", Array{{3, 2, 2}, s.position});
    out.write("/particles/all/position/time", std::vector<double>{0, 1});
    out.write("/particles/all/position/step", std::vector<std::int64_t>{0, 1, 2});
    out.commit();
  }
  expect_error<RuntimeError>([&] { read_snapshots(H5Input(dir.file("bad_time.h5"))); },
                             {"bad_time.h5", "time has 2 entries", "3 frames"});
}

TEST(CommonTrajectory, ObservableRoundTrip) {
  TempDir dir;
  const TimeSeries ts{{0, 10, 25}, {0.0, 0.1, 0.3}, {1.0, 0.8, 0.55}};
  {
    H5Output out(dir.file("o.h5"));
    write_observable(out, "kinetic_energy", ts);
    out.commit();
  }
  H5Input in(dir.file("o.h5"));
  EXPECT_TRUE(in.is_dataset("/observables/kinetic_energy/value"));
  const TimeSeries back = read_observable(in, "kinetic_energy");
  EXPECT_EQ(back.step, ts.step);
  EXPECT_EQ(back.time, ts.time);
  EXPECT_EQ(back.value, ts.value);
  expect_error<RuntimeError>([&] { read_observable(in, "pressure"); }, {"o.h5", "pressure"});
}

}  // namespace
}  // namespace gg
