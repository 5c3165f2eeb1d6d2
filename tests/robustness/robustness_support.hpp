#pragma once
// Helpers for the robustness tests: a scratch directory, running a built tool in it with
// its stdout and stderr captured outside it, and the small particle files the cases start from.
// The executables come from compile definitions (tests/robustness/CMakeLists.txt).
#include <gtest/gtest.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include "gg/h5file.hpp"
#include "gg/trajectory.hpp"

namespace gg::robust {

namespace fs = std::filesystem;

// A fresh directory under $TMPDIR (or /tmp), removed with everything in it.
class TempDir {
 public:
  TempDir() {
    std::string pattern = (fs::temp_directory_path() / "gg-robust-XXXXXX").string();
    if (!mkdtemp(pattern.data())) throw std::runtime_error("mkdtemp failed");
    path_ = pattern;
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  std::string file(const std::string& name) const { return (path_ / name).string(); }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

// Names of the entries of `dir`, hidden ones included (a leftover temporary is hidden).
inline std::set<std::string> entries(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.insert(e.path().filename().string());
  return names;
}

inline std::string read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

inline void write_bytes(const std::string& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << bytes;
  if (!out) throw std::runtime_error("cannot write " + path);
}

struct RunResult {
  int status = -1;       // exit status, or -1 if the process did not exit normally
  int signal = 0;        // the signal that ended it, if any
  bool timed_out = false;
  std::string out, err;
  std::string describe() const {
    std::string d = timed_out ? "timed out" : signal ? "killed by signal " + std::to_string(signal)
                                                      : "exit status " + std::to_string(status);
    return d + "; stderr: [" + err + "]";
  }
};

// Runs `exe args...` with `cwd` as working directory, stdin from `stdin_path` (default /dev/null),
// stdout and stderr captured in `capture_dir` (which must not be `cwd`, so that the tool's
// directory holds only what the tool itself left there). Killed after `timeout_s` seconds.
// Outside sanitizer builds the tool's address space is capped (`memory_mb`, default 4 GB), so a
// tool that believes a huge size fails fast instead of taking the machine (ASan needs terabytes of
// address space for its shadow memory, so there the cap is left off).
#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kAddressSanitizer = true;
#else
inline constexpr bool kAddressSanitizer = false;
#endif

// `close_fd` (0, 1 or 2): started with that descriptor closed, as `tool >&-` does.
inline RunResult run_tool(const std::string& exe, const std::vector<std::string>& args, const fs::path& cwd,
                          const fs::path& capture_dir, const std::string& stdin_path = "/dev/null",
                          int timeout_s = 60, std::size_t memory_mb = 4096, int close_fd = -1) {
  const std::string out_path = (capture_dir / "captured.stdout").string();
  const std::string err_path = (capture_dir / "captured.stderr").string();
  std::vector<std::string> argv_s{exe};
  argv_s.insert(argv_s.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& a : argv_s) argv.push_back(a.data());
  argv.push_back(nullptr);
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error("fork failed");
  if (pid == 0) {
    if (chdir(cwd.c_str()) != 0) _exit(126);
    if (!kAddressSanitizer && memory_mb > 0) {
      const rlimit cap{memory_mb << 20, memory_mb << 20};
      setrlimit(RLIMIT_AS, &cap);
    }
    const int in = open(stdin_path.c_str(), O_RDONLY);
    const int out = open(out_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int err = open(err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (in < 0 || out < 0 || err < 0) _exit(126);
    dup2(in, 0);
    dup2(out, 1);
    dup2(err, 2);
    if (close_fd >= 0) close(close_fd);
    execv(exe.c_str(), argv.data());
    _exit(127);
  }
  RunResult r;
  int raw = 0;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(timeout_s);
  for (;;) {
    const pid_t done = waitpid(pid, &raw, WNOHANG);
    if (done == pid) break;
    if (done < 0 && errno != EINTR) throw std::runtime_error("waitpid failed");
    if (std::chrono::steady_clock::now() > deadline) {
      kill(pid, SIGKILL);
      waitpid(pid, &raw, 0);
      r.timed_out = true;
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  if (WIFEXITED(raw)) r.status = WEXITSTATUS(raw);
  if (WIFSIGNALED(raw)) r.signal = WTERMSIG(raw);
  r.out = read_bytes(out_path);
  r.err = read_bytes(err_path);
  return r;
}

// A checkpoint of gg-sim, as a run stopped by SIGTERM leaves it: 20 elastic disks (they never
// stop), --t-max 1e9, stopped after 0.2 s. Its scene: dim 2, N 20, rho 0.1, e 1, seed 1. A run that
// had not yet set up its signal handler dies of the signal without a checkpoint (a slow start: a
// sanitizer build, a loaded machine): then it is run again and stopped later.
inline void make_checkpoint(const fs::path& dir, const std::string& name) {
  for (const int ms : {200, 500, 1000, 2000, 4000}) {
    const pid_t pid = fork();
    if (pid < 0) throw std::runtime_error("fork failed");
    if (pid == 0) {
      if (chdir(dir.c_str()) != 0) _exit(126);
      const int null = open("/dev/null", O_RDWR);
      dup2(null, 0);
      dup2(null, 1);
      dup2(null, 2);
      execl(GG_SIM_EXE, GG_SIM_EXE, "--N", "20", "--rho", "0.1", "--e", "1", "--t-max", "1e9", "--quiet",
            "--checkpoint", name.c_str(), "-o", ".checkpoint-run.h5", static_cast<char*>(nullptr));
      _exit(127);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(ms));
    kill(pid, SIGTERM);
    int status = 0;
    waitpid(pid, &status, 0);
    fs::remove(dir / ".checkpoint-run.h5");
    if (fs::exists(dir / name)) return;
  }
  throw std::runtime_error("gg-sim left no checkpoint " + name);
}

// ------------------------------------------------------------------------------------------------
// Particle files

// A 2D H5MD file from the project's writer: `frames` frames of N disks on a square lattice of
// spacing 2 in a box of edge L (no two disks overlap), shifted by 0.1 per frame.
inline Snapshots lattice_snapshots(int dim, std::size_t n, double L, std::size_t frames, bool velocities) {
  Snapshots s;
  s.dim = dim;
  s.edges.assign(static_cast<std::size_t>(dim), L);
  s.n_particles = n;
  const auto per_row = static_cast<std::size_t>(L / 2);
  for (std::size_t f = 0; f < frames; ++f) {
    s.time.push_back(static_cast<double>(f));
    s.step.push_back(static_cast<std::int64_t>(10 * f));
    for (std::size_t i = 0; i < n; ++i) {
      if (dim == 1) {
        s.position.push_back(2.0 * static_cast<double>(i) + 0.5 + 0.1 * static_cast<double>(f));
      } else {
        s.position.push_back(2.0 * static_cast<double>(i % per_row) + 0.5 + 0.1 * static_cast<double>(f));
        s.position.push_back(2.0 * static_cast<double>(i / per_row) + 0.5);
      }
      for (int k = 0; k < dim && velocities; ++k)
        s.velocity.push_back(0.5 - 0.25 * static_cast<double>((i + static_cast<std::size_t>(k)) % 5));
    }
  }
  return s;
}

inline void write_particles(const std::string& path, const Snapshots& s) {
  H5Output out(path);
  write_snapshots(out, s, "gg-robustness-test");
  out.commit();
}

// An H5MD-looking file whose /particles/all/position/value is whatever `value` is (any rank), with a
// box of `dim_attr` dimensions: for shapes and dimensions that write_snapshots refuses to write.
inline void write_raw_particles(const std::string& path, std::int64_t dim_attr, const std::vector<double>& edges,
                                const Array& value) {
  H5Output out(path);
  out.attr("/h5md", "version", std::vector<std::int64_t>{1, 1});
  out.attr("/h5md/creator", "name", std::string("someone-else"));
  out.attr("/particles/all/box", "dimension", dim_attr);
  out.attr("/particles/all/box", "boundary",
           std::vector<std::string>(static_cast<std::size_t>(std::max<std::int64_t>(dim_attr, 0)), "periodic"));
  out.write("/particles/all/box/edges", edges);
  const std::size_t frames = value.shape.empty() ? 0 : value.shape[0];
  std::vector<double> time;
  std::vector<std::int64_t> step;
  for (std::size_t f = 0; f < frames; ++f) {
    time.push_back(static_cast<double>(f));
    step.push_back(static_cast<std::int64_t>(f));
  }
  out.write("/particles/all/position/time", time);
  out.write("/particles/all/position/step", step);
  out.write("/particles/all/position/value", value);
  out.commit();
}

}  // namespace gg::robust
