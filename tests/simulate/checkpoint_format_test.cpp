// A checkpoint holds the engine's state in a layout that changes with the engine: one written by
// another version of gg-sim is refused with a usage error that says so, never misread.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "gg/errors.hpp"
#include "gg/h5file.hpp"
#include "ggsim/checkpoint.hpp"

namespace {

TEST(Checkpoint, AnotherFormatIsRefusedNotMisread) {
  const auto path = (std::filesystem::temp_directory_path() / "gg_checkpoint_format_test.h5").string();
  ggsim::SimConfig cfg;
  cfg.resume = path;
  {  // what the founding session's gg-sim wrote: the scene, no format
    gg::H5Output out(path);
    out.attr("/checkpoint", "scene", cfg.fingerprint());
    out.attr("/checkpoint", "dim", std::int64_t{2});
    out.commit();
  }
  gg::Box<2> box;
  try {
    ggsim::read_checkpoint<2>(cfg, &box);
    ADD_FAILURE() << "a checkpoint without a format was read";
  } catch (const gg::UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("checkpoint format 1"), std::string::npos) << e.what();
  }
  std::filesystem::remove(path);
}

TEST(Checkpoint, ADatasetOfTheWrongSizeIsRefusedNotReadPastItsEnd) {
  const auto path = (std::filesystem::temp_directory_path() / "gg_checkpoint_size_test.h5").string();
  ggsim::SimConfig cfg;
  cfg.resume = path;
  {  // two particles, but positions for one and a half
    gg::H5Output out(path);
    out.attr("/checkpoint", "scene", cfg.fingerprint());
    out.attr("/checkpoint", "format", std::int64_t{2});
    out.attr("/checkpoint", "dim", std::int64_t{2});
    out.write("/checkpoint/edges", std::vector<double>{10, 10});
    out.write("/checkpoint/t", std::vector<double>{0, 0});
    out.write("/checkpoint/r", std::vector<double>{1, 1, 3});
    out.commit();
  }
  gg::Box<2> box;
  try {
    ggsim::read_checkpoint<2>(cfg, &box);
    ADD_FAILURE() << "a checkpoint with 3 coordinates for 2 disks was read";
  } catch (const gg::RuntimeError& e) {
    EXPECT_NE(std::string(e.what()).find("/checkpoint/r has the wrong size"), std::string::npos) << e.what();
  }
  std::filesystem::remove(path);
}

}  // namespace
