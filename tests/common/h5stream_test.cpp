// "-" as a file name: HDF5 files through stdout and stdin (docs/DESIGN.md: pipelines). Both sides go
// through scratch files in $TMPDIR (HDF5 must seek; a pipe cannot), never through memory.
#include <gtest/gtest.h>

#include <cstdlib>

#include <sys/wait.h>
#include <unistd.h>

#include "gg/errors.hpp"
#include "gg/h5file.hpp"
#include "test_support.hpp"

namespace gg {
namespace {

using test::TempDir;

// Sets TMPDIR for the life of the object.
class TmpdirSet {
 public:
  explicit TmpdirSet(const std::string& dir) {
    if (const char* old = std::getenv("TMPDIR")) saved_ = old, had_ = true;
    setenv("TMPDIR", dir.c_str(), 1);
  }
  ~TmpdirSet() {
    if (had_) setenv("TMPDIR", saved_.c_str(), 1);
    else unsetenv("TMPDIR");
  }

 private:
  std::string saved_;
  bool had_ = false;
};

void write_sample(H5Output& out) {
  out.write("/cluster/time", std::vector<double>{1, 2, 4});
  out.write("/cluster/count", std::vector<std::int64_t>{9, 5, 2});
  out.attr("/cluster", "tool", std::string("gg-cluster"));
}

void expect_sample(const H5Input& in) {
  EXPECT_EQ(in.read("/cluster/time", 1).data, (std::vector<double>{1, 2, 4}));
  EXPECT_EQ(in.read_int("/cluster/count"), (std::vector<std::int64_t>{9, 5, 2}));
  EXPECT_EQ(in.attr_string("/cluster", "tool"), "gg-cluster");
}

TEST(CommonH5Stream, PipeFromWriterProcessToReader) {
  int fds[2];
  ASSERT_EQ(pipe(fds), 0);
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {  // the upstream tool: "... -o -"
    close(fds[0]);
    dup2(fds[1], STDOUT_FILENO);
    close(fds[1]);
    H5Output out("-");
    write_sample(out);
    out.commit();
    _exit(0);
  }
  close(fds[1]);
  // The downstream tool: "gg-x - ..."
  const int saved = dup(STDIN_FILENO);
  dup2(fds[0], STDIN_FILENO);
  close(fds[0]);
  {
    H5Input in("-");
    EXPECT_EQ(in.path(), "<stdin>");
    expect_sample(in);
  }
  dup2(saved, STDIN_FILENO);
  close(saved);
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
}

// A writer and a reader joined by a pipe, their scratch files in `scratch`: while the writer writes,
// while the reader reads, and when both are done, their files have no names (nothing is left even
// after SIGKILL). The reader's file has one while the pipe is copied into it.
TEST(CommonH5Stream, ScratchFilesOfAPipeHaveNoNames) {
  TempDir scratch;
  TmpdirSet tmpdir(scratch.path().string());
  int fds[2];
  ASSERT_EQ(pipe(fds), 0);
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    close(fds[0]);
    dup2(fds[1], STDOUT_FILENO);
    close(fds[1]);
    H5Output out("-");
    write_sample(out);
    bool named = false;
    for (const std::string& name : scratch.entries()) named = named || name.rfind("gg.stdout", 0) == 0;
    out.commit();
    _exit(named ? 3 : 0);
  }
  close(fds[1]);
  const int saved = dup(STDIN_FILENO);
  dup2(fds[0], STDIN_FILENO);
  close(fds[0]);
  {
    H5Input in("-");
    EXPECT_TRUE(scratch.entries().empty());
    expect_sample(in);
  }
  dup2(saved, STDIN_FILENO);
  close(saved);
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "the writer's scratch file had a name while it wrote";
  EXPECT_TRUE(scratch.entries().empty());
}

TEST(CommonH5Stream, MissingTmpdirIsUsageErrorNamingIt) {
  TempDir dir;
  TmpdirSet tmpdir("/nonexistent-gg-tmpdir");
  test::with_fd_redirected(STDOUT_FILENO, dir.file("out"), [] {
    test::expect_error<UsageError>([] { H5Output out("-"); }, {"/nonexistent-gg-tmpdir", "TMPDIR"});
  });
  EXPECT_EQ(test::read_bytes(dir.file("out")), "");
}

TEST(CommonH5Stream, StdoutImageIsTheSameFileAsWrittenToDisk) {
  TempDir dir;
  test::with_fd_redirected(STDOUT_FILENO, dir.file("image.h5"), [] {
    H5Output out("-");
    write_sample(out);
    out.commit();
  });
  {
    H5Output out(dir.file("disk.h5"));
    write_sample(out);
    out.commit();
  }
  const std::string image = test::read_bytes(dir.file("image.h5"));
  EXPECT_EQ(image.substr(0, 8), std::string("\x89HDF\r\n\x1a\n", 8));
  EXPECT_TRUE(image == test::read_bytes(dir.file("disk.h5")));  // no dump of binary on failure
  expect_sample(H5Input(dir.file("image.h5")));
}

TEST(CommonH5Stream, UncommittedStdoutOutputWritesNothing) {
  TempDir dir;
  test::with_fd_redirected(STDOUT_FILENO, dir.file("out"), [] {
    H5Output out("-");
    write_sample(out);
  });
  EXPECT_EQ(test::read_bytes(dir.file("out")), "");
}

TEST(CommonH5Stream, StdinRedirectedFromFile) {
  TempDir dir;
  {
    H5Output out(dir.file("in.h5"));
    write_sample(out);
    out.commit();
  }
  test::with_fd_redirected(STDIN_FILENO, dir.file("in.h5"), [] { expect_sample(H5Input("-")); });
}

TEST(CommonH5Stream, EmptyStdinIsRuntimeError) {
  TempDir dir;
  test::write_bytes(dir.file("empty"), "");
  test::with_fd_redirected(STDIN_FILENO, dir.file("empty"), [] {
    test::expect_error<RuntimeError>([] { H5Input in("-"); }, {"<stdin>", "no data"});
  });
}

TEST(CommonH5Stream, TextOnStdinIsRuntimeError) {
  TempDir dir;
  test::write_bytes(dir.file("text"), "this is not HDF5\n");
  test::with_fd_redirected(STDIN_FILENO, dir.file("text"), [] {
    test::expect_error<RuntimeError>([] { H5Input in("-"); }, {"<stdin>", "not an HDF5 file"});
  });
}

TEST(CommonH5Stream, CopyFromStdinImage) {
  TempDir dir;
  {
    H5Output out(dir.file("in.h5"));
    write_sample(out);
    out.commit();
  }
  test::with_fd_redirected(STDIN_FILENO, dir.file("in.h5"), [&] {
    H5Input in("-");
    H5Output out(dir.file("copy.h5"));
    out.copy_from(in, "/cluster", "/deep/copy/cluster");
    out.commit();
  });
  H5Input copy(dir.file("copy.h5"));
  EXPECT_EQ(copy.read("/deep/copy/cluster/time").data, (std::vector<double>{1, 2, 4}));
  EXPECT_EQ(copy.attr_string("/deep/copy/cluster", "tool"), "gg-cluster");
}

}  // namespace
}  // namespace gg
