// ScratchFile: a temporary file that outlives its name (gg/scratch_file.hpp).
#include <gtest/gtest.h>

#include <cerrno>
#include <cstdlib>
#include <string>

#include "gg/errors.hpp"
#include "gg/scratch_file.hpp"
#include "test_support.hpp"

namespace gg {
namespace {

using test::TempDir;

TEST(CommonScratchFile, KeepsItsDataAfterItsNameIsDropped) {
  TempDir dir;
  ScratchFile f(dir.path().string(), "stem", "fix");
  ASSERT_EQ(dir.entries().size(), 1u);
  EXPECT_EQ(dir.entries()[0].substr(0, 5), "stem.");
  f.drop_name();
  EXPECT_TRUE(dir.entries().empty());
  const std::string text = "frames of a run";
  EXPECT_EQ(f.write_at(text.data(), text.size(), 100), 0);
  std::string back(text.size(), '\0');
  EXPECT_EQ(f.read_at(back.data(), back.size(), 100), 0);
  EXPECT_EQ(back, text);
  char gap[4] = {1, 1, 1, 1};
  EXPECT_EQ(f.read_at(gap, 4, 0), 0);  // bytes never written read as zeros
  EXPECT_EQ(std::string(gap, 4), std::string(4, '\0'));
  EXPECT_EQ(f.read_at(back.data(), back.size(), 110), -1);  // the file ends first
}

TEST(CommonScratchFile, NameIsRemovedWhenTheObjectEnds) {
  TempDir dir;
  { ScratchFile f(dir.path().string(), "kept", "fix"); }
  EXPECT_TRUE(dir.entries().empty());
}

TEST(CommonScratchFile, MissingDirectoryIsUsageErrorWithTheFix) {
  test::expect_error<UsageError>([] { ScratchFile f("/nonexistent-gg-dir", "stem", "set TMPDIR"); },
                                 {"/nonexistent-gg-dir", "set TMPDIR"});
}

TEST(CommonScratchFile, TempDirFollowsTmpdir) {
  const char* old = std::getenv("TMPDIR");
  const std::string saved = old ? old : "";
  setenv("TMPDIR", "/some/where", 1);
  EXPECT_EQ(ScratchFile::temp_dir(), "/some/where");
  unsetenv("TMPDIR");
  EXPECT_EQ(ScratchFile::temp_dir(), "/tmp");
  if (old) setenv("TMPDIR", saved.c_str(), 1);
}

}  // namespace
}  // namespace gg
