// The store that keeps gg-sim's snapshots on disk: frames come back bit for bit, and its
// temporary file never outlives it (nor shows up beside the output while the run goes on).
#include "ggsim/snapshot_store.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include <unistd.h>

#include "gg/errors.hpp"

namespace {

namespace fs = std::filesystem;

// A fresh empty directory for one test.
fs::path empty_directory(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / (name + "." + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directory(dir);
  return dir;
}

std::size_t open_descriptors() {
  return static_cast<std::size_t>(std::distance(fs::directory_iterator("/proc/self/fd"), fs::directory_iterator()));
}

// Values whose bits would betray any rounding: subnormals, -0, the largest double, pi's neighbours.
std::vector<double> frame_values(std::size_t count, int frame) {
  std::vector<double> v(count);
  for (std::size_t i = 0; i < count; ++i) v[i] = std::nextafter(M_PI * (frame + 1), 0.0) * static_cast<double>(i) / 7;
  v[0] = -0.0;
  v[1] = std::numeric_limits<double>::denorm_min() * (frame + 1);
  v[2] = std::numeric_limits<double>::max();
  return v;
}

bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

TEST(SnapshotStore, FramesComeBackBitForBit) {
  const fs::path dir = empty_directory("gg_snapshot_store_test");
  const std::size_t n = 1001, values = 2 * n;
  ggsim::SnapshotStore store((dir / "run.h5").string(), n, 2, {40, 50}, {.velocities = true});
  for (int k = 0; k < 3; ++k)
    store.append(0.5 * k, 10 * k, {.position = frame_values(values, k).data(), .velocity = frame_values(values, k + 10).data()});
  ASSERT_EQ(store.index().frames(), 3u);
  EXPECT_EQ(store.index().time, (std::vector<double>{0, 0.5, 1}));
  EXPECT_EQ(store.index().step, (std::vector<std::int64_t>{0, 10, 20}));
  EXPECT_TRUE(store.index().position.empty());
  std::vector<double> got(values);
  for (int k : {2, 0, 1}) {  // any order
    store.positions()(static_cast<std::size_t>(k), got.data());
    EXPECT_TRUE(same_bits(got, frame_values(values, k))) << "positions of frame " << k;
    store.velocities()(static_cast<std::size_t>(k), got.data());
    EXPECT_TRUE(same_bits(got, frame_values(values, k + 10))) << "velocities of frame " << k;
  }
  fs::remove_all(dir);
}

TEST(SnapshotStore, WithoutVelocitiesThereIsNoVelocityReader) {
  const fs::path dir = empty_directory("gg_snapshot_store_test_1d");
  ggsim::SnapshotStore store((dir / "run.h5").string(), 5, 1, {10}, {});
  const std::vector<double> x{0, 1, 2, 3, 9.5};
  store.append(1, 4, {.position = x.data()});
  std::vector<double> got(5);
  store.positions()(0, got.data());
  EXPECT_TRUE(same_bits(got, x));
  EXPECT_FALSE(store.velocities());
  fs::remove_all(dir);
}

TEST(SnapshotStore, TheTemporaryIsNeverLeftBehind) {
  const fs::path dir = empty_directory("gg_snapshot_store_test_gone");
  const std::size_t before = open_descriptors();
  {
    ggsim::SnapshotStore store((dir / "run.h5").string(), 100, 2, {20, 20}, {});
    store.append(0, 0, {.position = frame_values(200, 0).data()});
    // Unlinked from the start, so even SIGKILL leaves nothing in the output's directory.
    EXPECT_TRUE(fs::is_empty(dir));
    EXPECT_EQ(open_descriptors(), before + 1);
  }
  EXPECT_EQ(open_descriptors(), before) << "the file's space is freed only when its descriptor closes";
  EXPECT_TRUE(fs::is_empty(dir));
  fs::remove_all(dir);
}

TEST(SnapshotStore, AMissingDirectoryIsAUsageErrorNamingIt) {
  const fs::path dir = fs::temp_directory_path() / "gg_snapshot_store_test_no_such_dir";
  fs::remove_all(dir);
  try {
    ggsim::SnapshotStore store((dir / "run.h5").string(), 10, 2, {10, 10}, {});
    ADD_FAILURE() << "created in a missing directory";
  } catch (const gg::UsageError& e) {
    EXPECT_NE(std::string(e.what()).find(dir.string()), std::string::npos) << e.what();
  }
}

}  // namespace
