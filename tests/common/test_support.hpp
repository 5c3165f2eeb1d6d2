#pragma once
// Helpers for the tests of common/: a scratch directory, and running code with one of the
// process's standard streams (fd 0, 1 or 2) redirected to a file, which is what "-" really uses.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

#include <fcntl.h>
#include <stdlib.h>
#include <unistd.h>

namespace gg::test {

// A fresh directory under $TMPDIR (or /tmp), removed with everything in it.
class TempDir {
 public:
  TempDir() {
    std::string pattern = (std::filesystem::temp_directory_path() / "gg-common-test-XXXXXX").string();
    if (!mkdtemp(pattern.data())) throw std::runtime_error("mkdtemp failed");
    path_ = pattern;
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  std::string file(const std::string& name) const { return (path_ / name).string(); }
  const std::filesystem::path& path() const { return path_; }
  // Names of the entries, hidden ones included (to see leftover temporaries).
  std::vector<std::string> entries() const {
    std::vector<std::string> names;
    for (const auto& e : std::filesystem::directory_iterator(path_)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }

 private:
  std::filesystem::path path_;
};

inline std::string read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

inline void write_bytes(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

// Runs `body` with file descriptor `fd` connected to `path` (read for fd 0, truncated for 1
// and 2), then restores it. C stdio buffers are flushed on both sides of the swap.
inline void with_fd_redirected(int fd, const std::string& path, const std::function<void()>& body) {
  std::fflush(nullptr);
  const int saved = dup(fd);
  const int file = fd == 0 ? open(path.c_str(), O_RDONLY) : open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (saved < 0 || file < 0) throw std::runtime_error("cannot redirect fd " + std::to_string(fd) + " to " + path);
  dup2(file, fd);
  close(file);
  struct Restore {
    int fd, saved;
    ~Restore() {
      std::fflush(nullptr);
      dup2(saved, fd);
      close(saved);
    }
  } restore{fd, saved};
  body();
}

// Asserts that `body` throws E and that its message contains every one of `needles`.
template <class E>
void expect_error(const std::function<void()>& body, std::initializer_list<std::string> needles) {
  try {
    body();
    ADD_FAILURE() << "no exception thrown";
  } catch (const E& e) {
    const std::string what = e.what();
    for (const std::string& n : needles) EXPECT_NE(what.find(n), std::string::npos) << "'" << n << "' not in: " << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << "message is not one line: " << what;
  }
}

}  // namespace gg::test
