// A checkpoint holds the engine's state in a layout that changes with the engine: one written by
// another version of gg-sim, or damaged, is refused with an error that says so, never misread.
#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "gg/errors.hpp"
#include "gg/h5file.hpp"
#include "ggsim/checkpoint.hpp"

namespace {

// Writes a checkpoint with `fill` (the scene and dimension are written for it) and expects
// reading it to throw an Error whose message contains `message`.
template <class Error>
void expect_refused(const std::string& what, const std::function<void(gg::H5Output&)>& fill,
                    const std::string& message) {
  // One file per test: ctest runs the tests of this file in parallel.
  const std::string name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
  const auto path = (std::filesystem::temp_directory_path() / ("gg_checkpoint_" + name + ".h5")).string();
  ggsim::SimConfig cfg;
  cfg.resume = path;
  {
    gg::H5Output out(path, true);  // sealed, as gg-sim writes them
    out.attr("/checkpoint", "scene", cfg.fingerprint());
    out.attr("/checkpoint", "dim", std::int64_t{2});
    fill(out);
    out.commit();
  }
  gg::Box<2> box;
  try {
    ggsim::SavedRun(path).engine_state<2>(&box);
    ADD_FAILURE() << what << " was read";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
  }
  std::filesystem::remove(path);
}

TEST(Checkpoint, AnotherFormatIsRefusedNotMisread) {
  // a checkpoint without a format number (as a first version of gg-sim wrote): the scene only
  expect_refused<gg::UsageError>("a checkpoint without a format", [](gg::H5Output&) {}, "checkpoint format 1");
  // the layout before each effect kept its own arrays
  expect_refused<gg::UsageError>(
      "a checkpoint of format 4", [](gg::H5Output& out) { out.attr("/checkpoint", "format", std::int64_t{4}); },
      "checkpoint format 4");
}

// A checkpoint names the effects of the engine that wrote it, by their words; a resume holds them.
TEST(Checkpoint, ItNamesTheEffectsOfItsEngine) {
  const unsigned key = ggsim::kBit<ggsim::MixtureEffect> | ggsim::kBit<ggsim::VirialEffect>;
  EXPECT_EQ(ggsim::effect_words(key), "virial+mixture");  // in the registry's order
  EXPECT_EQ(ggsim::effect_words(0), "plain");
  std::string_view unknown;
  EXPECT_EQ(ggsim::effects_named("virial+mixture", unknown), key);
  EXPECT_TRUE(unknown.empty());
  EXPECT_EQ(ggsim::effects_named("virial+glue", unknown), unsigned{ggsim::kBit<ggsim::VirialEffect>});
  EXPECT_EQ(unknown, "glue");
  // one of an effect this gg-sim does not have, and one that does not name its effects
  expect_refused<gg::UsageError>(
      "a checkpoint of an effect gg-sim lacks",
      [](gg::H5Output& out) {
        out.attr("/checkpoint", "format", std::int64_t{11});
        out.attr("/checkpoint", "effects", std::string("mixture+glue"));
      },
      "with the effect 'glue'");
  expect_refused<gg::RuntimeError>(
      "a checkpoint without its effects", [](gg::H5Output& out) { out.attr("/checkpoint", "format", std::int64_t{11}); },
      "no list of its effects");
}

// One of format 10 does not name its effects: it resumes with its scene's, and state that none of
// them takes (a run started from a mixture's output) is refused rather than lost.
TEST(Checkpoint, StateOfAFormat10CheckpointThatNoEffectTakesIsRefused) {
  const auto path = (std::filesystem::temp_directory_path() / "gg_checkpoint_format10.h5").string();
  {
    gg::H5Output out(path, true);
    out.attr("/checkpoint", "scene", ggsim::SimConfig{}.fingerprint());
    out.attr("/checkpoint", "dim", std::int64_t{2});
    out.attr("/checkpoint", "format", std::int64_t{10});
    out.write("/checkpoint/t", std::vector<double>{0, 0});
    out.commit();
  }
  const ggsim::SavedRun saved(path);
  std::filesystem::remove(path);
  EXPECT_EQ(saved.effects(), 0u);
  EXPECT_NO_THROW(saved.require_taken({}));
  ggsim::EffectRecords left;
  left.real["radius"] = {0.5, 0.7};
  try {
    saved.require_taken(left);
    ADD_FAILURE() << "state no effect takes was accepted";
  } catch (const gg::RuntimeError& e) {
    EXPECT_NE(std::string(e.what()).find("(radius) of effects its scene does not name"), std::string::npos) << e.what();
  }
}

TEST(Checkpoint, AnEffectsArrayOfTheWrongSizeIsRefused) {
  // two particles, and the TC model's last collision times for three
  ggsim::EffectRecords saved;
  saved.real["last_collision"] = {0.0, 1.0, 2.0};
  ggsim::EngineParameters par;
  EXPECT_THROW((ggsim::Effects<ggsim::TcEffect>::Set<2>(par, ggsim::EffectStart{.n = 2, .records = &saved})),
               gg::RuntimeError);
}

TEST(Checkpoint, ADatasetOfTheWrongSizeIsRefusedNotReadPastItsEnd) {
  // two particles, but positions for one and a half
  expect_refused<gg::RuntimeError>(
      "a checkpoint with 3 coordinates for 2 disks",
      [](gg::H5Output& out) {
        out.attr("/checkpoint", "format", std::int64_t{10});
        out.write("/checkpoint/edges", std::vector<double>{10, 10});
        out.write("/checkpoint/t", std::vector<double>{0, 0});
        out.write("/checkpoint/r", std::vector<double>{1, 1, 3});
      },
      "/checkpoint/r has the wrong size");
}

}  // namespace
