#include "ggsim/run_pieces.hpp"

#include <cstdint>
#include <string_view>

#include <sys/resource.h>

#include "gg/errors.hpp"
#include "gg/provenance.hpp"
#include "gg/seal.hpp"
#include "gg/version.hpp"

namespace ggsim {

namespace {

double cpu_seconds_so_far() {
  rusage use{};
  getrusage(RUSAGE_SELF, &use);
  const auto seconds = [](const timeval& t) { return static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_usec); };
  return seconds(use.ru_utime) + seconds(use.ru_stime);
}

std::string joined(const std::vector<std::string>& words) {
  std::string s;
  for (const std::string& w : words) s += (s.empty() ? "" : " ") + w;
  return s;
}

std::string describe(const Build& b) {
  return b.git_hash + (b.executable.empty() ? "" : " (executable " + b.executable + ")");
}

}  // namespace

bool Build::clean() const {
  return git_hash != "unknown" && !std::string_view(git_hash).ends_with("-dirty");
}

Build Build::this_program() {
  static const Build self{gg::kGitHash, gg::file_checksum("/proc/self/exe")};
  return self;
}

RunPieces RunPieces::read(const gg::H5Input& in, const std::string& group) {
  RunPieces r;
  if (!in.exists(group)) return r;
  const auto strings = [&](const char* name) { return in.attr_strings(group, name); };
  const auto numbers = [&](const char* name) { return in.read(group + "/" + name).data; };
  const auto program = strings("program"), git = strings("git_hash"), exe = strings("executable");
  const auto utc_start = strings("utc_start"), utc_end = strings("utc_end"), command = strings("command");
  const auto other = in.read_int(group + "/other_build");
  const auto t_start = numbers("t_start"), t_end = numbers("t_end"), cpu = numbers("cpu_seconds");
  const std::size_t n = program.size();
  for (std::size_t size : {git.size(), exe.size(), utc_start.size(), utc_end.size(), command.size(), other.size(),
                           t_start.size(), t_end.size(), cpu.size()})
    if (size != n) throw gg::RuntimeError(in.path() + ": " + group + " lists its fields with different lengths; the file is damaged");
  for (std::size_t k = 0; k < n; ++k)
    r.pieces_.push_back({program[k], {git[k], exe[k]}, other[k] != 0, t_start[k], t_end[k], cpu[k], utc_start[k],
                         utc_end[k], command[k]});
  return r;
}

void RunPieces::start(double t, const std::vector<std::string>& argv, bool other_build) {
  pieces_.push_back({std::string("gg-sim ") + gg::kVersion, Build::this_program(), other_build, t, t, 0,
                     gg::utc_now_iso8601(), "", joined(argv)});
}

void RunPieces::end_at(double t) {
  RunPiece& now = pieces_.back();
  now.t_end = t;
  now.cpu_seconds = cpu_seconds_so_far();
  now.utc_end = gg::utc_now_iso8601();
}

void RunPieces::write(gg::H5Output& out, const std::string& group) const {
  if (pieces_.empty()) return;  // an engine's checkpoint written outside a run (tests)
  // Text as attributes of the group, numbers as its datasets: at most 8 attributes, which HDF5 keeps
  // in the group's header (more go to a fractal heap that h5copy 1.10 cannot copy with strings in it).
  const auto strings = [&](const char* name, auto field) {
    std::vector<std::string> a;
    for (const RunPiece& p : pieces_) a.push_back(field(p));
    out.attr(group, name, a);
  };
  const auto numbers = [&](const char* name, auto field) {
    std::vector<double> a;
    for (const RunPiece& p : pieces_) a.push_back(field(p));
    out.write(group + "/" + name, a);
  };
  const auto flags = [&](const char* name, auto field) {
    std::vector<std::int64_t> a;
    for (const RunPiece& p : pieces_) a.push_back(field(p) ? 1 : 0);
    out.write(group + "/" + name, a);
  };
  strings("program", [](const RunPiece& p) { return p.program; });
  strings("git_hash", [](const RunPiece& p) { return p.build.git_hash; });
  strings("executable", [](const RunPiece& p) { return p.build.executable; });
  strings("utc_start", [](const RunPiece& p) { return p.utc_start; });
  strings("utc_end", [](const RunPiece& p) { return p.utc_end; });
  strings("command", [](const RunPiece& p) { return p.command; });
  flags("clean", [](const RunPiece& p) { return p.build.clean(); });
  flags("other_build", [](const RunPiece& p) { return p.other_build; });
  numbers("t_start", [](const RunPiece& p) { return p.t_start; });
  numbers("t_end", [](const RunPiece& p) { return p.t_end; });
  numbers("cpu_seconds", [](const RunPiece& p) { return p.cpu_seconds; });
}

bool check_resume_build(const std::string& path, const RunPieces& pieces, bool allowed) {
  if (pieces.pieces().empty()) return false;
  const Build& then = pieces.pieces().back().build;
  const Build& now = Build::this_program();
  const bool differs = then.git_hash != now.git_hash || then.executable != now.executable;
  if (differs && !allowed)
    throw gg::UsageError("--resume " + path + " was written by gg-sim build " + describe(then) + ", this is " +
                         describe(now) + "; resume with the build that wrote it (a run's pieces should share one "
                         "build), or add --allow-other-build to go on with this one (recorded in the output)");
  return differs;
}

}  // namespace ggsim
