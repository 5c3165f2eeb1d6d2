// Reading HDF5 written by others: a seeded random mutator over small valid files (a gg-sim
// output, the same file as another H5MD program would write it, a gg-cluster output, a gg-fit
// average and a gg-fit power-law fit) feeds every reader in-process: gg::H5Input, read_snapshots,
// read_observable, the analysis tools' run_* and gg-fit's main. Each must succeed or throw
// gg::RuntimeError / gg::UsageError: never crash, hang, or throw anything else (gg-fit's main turns
// exceptions into one line, so its line must not be a raw C++ library message). Mutated gg-sim
// checkpoints go to `gg-sim --resume`, which must refuse every one (CheckpointResume).
//
// Deterministic: iteration i of a seed file is mutated by an RNG seeded from (file, i) alone, so
// GG_FUZZ_REPRO=<test name>:<i> reruns exactly that input (and keeps it as ./fuzz-repro.h5).
// GG_FUZZ_SCALE=<factor> multiplies the iteration counts for a longer local campaign.
#include <gtest/gtest.h>

#include <hdf5.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <functional>
#include <iostream>
#include <map>
#include <memory>
#include <new>
#include <string>
#include <typeinfo>
#include <vector>

#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <unistd.h>

#include "fit/tool.hpp"
#include "gg/dataset_ref.hpp"
#include "gg/errors.hpp"
#include "gg/h5file.hpp"
#include "gg/trajectory.hpp"
#include "robustness_support.hpp"
#include "structure_tools.hpp"

#if defined(__SANITIZE_ADDRESS__)
#define GG_FUZZ_ASAN 1
#include <sanitizer/common_interface_defs.h>
// A damaged header may claim 2^60 elements: HDF5's own malloc() of such a size then returns NULL,
// which HDF5 handles. (Our operator new cannot fail softly under ASan, it reports and aborts: the
// readers refuse such claims before allocating, which this test checks too.)
extern "C" const char* __asan_default_options() { return "allocator_may_return_null=1:max_allocation_size_mb=3072"; }
// HDF5 1.10 leaks the half-decoded metadata of a damaged object header (allocated under H5C_protect,
// never freed on the error path), and after that its free lists are not released at exit either.
// Those leaks are inside libhdf5; leaks of ours (HDF5 identifiers we fail to close) are checked
// directly after every input instead (close_leftover_identifiers).
extern "C" const char* __lsan_default_suppressions() { return "leak:libhdf5\n"; }
#else
#define GG_FUZZ_ASAN 0
#endif

namespace gg::robust {
namespace {

// ------------------------------------------------------------------------------------------------
// What is running now, for the last words of a crash or a hang.

char g_current[1024] = "setting up";

void say_current(const char* why) {
  const char* parts[] = {"\nfuzz_readers_test: ", why, " while reading ", g_current,
                         "\n(rerun just this input with GG_FUZZ_REPRO=<test>:<iteration>)\n"};
  for (const char* p : parts) {
    ssize_t ignored = write(STDERR_FILENO, p, std::strlen(p));
    (void)ignored;
  }
}

void on_alarm(int) {
  say_current("HANG (no progress for 20 s)");
  _exit(3);
}

#if GG_FUZZ_ASAN
void on_sanitizer_death() { say_current("sanitizer report"); }
#else
void on_fatal(int sig) {
  say_current(sig == SIGSEGV ? "SIGSEGV" : sig == SIGABRT ? "SIGABRT" : sig == SIGBUS ? "SIGBUS" : "fatal signal");
  signal(sig, SIG_DFL);
  raise(sig);
}
#endif

void install_last_words() {
  static bool done = false;
  if (done) return;
  done = true;
  signal(SIGALRM, on_alarm);
#if GG_FUZZ_ASAN
  __sanitizer_set_death_callback(on_sanitizer_death);
#else
  for (int sig : {SIGSEGV, SIGABRT, SIGBUS, SIGFPE, SIGILL}) signal(sig, on_fatal);
  // A corrupted header may claim terabytes: let such an allocation fail instead of taking the machine.
  rlimit lim{3ull << 30, 3ull << 30};
  setrlimit(RLIMIT_AS, &lim);
#endif
}

// ------------------------------------------------------------------------------------------------
// Seed files

// The sim output rewritten the way other H5MD writers store it: HDF5's default (oldest) format,
// no checksums in object headers, and the time-dependent datasets chunked, extendable and
// compressed (H5MD 1.1 section "time-dependent data").
void rewrite_as_other_writer(const std::string& src, const std::string& dst) {
  const hid_t in = H5Fopen(src.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  // No object timestamps, so the seed is the same file on every run (HDF5's default records them).
  const hid_t fcpl = H5Pcreate(H5P_FILE_CREATE), gcpl = H5Pcreate(H5P_GROUP_CREATE);
  H5Pset_obj_track_times(fcpl, false);
  H5Pset_obj_track_times(gcpl, false);
  const hid_t out = H5Fcreate(dst.c_str(), H5F_ACC_TRUNC, fcpl, H5P_DEFAULT);
  H5Pclose(fcpl);
  ASSERT_GE(in, 0);
  ASSERT_GE(out, 0);
  // Not /parameters itself: its 22 attributes are stored densely, and HDF5 before 1.14.4 crashes
  // copying dense variable-length string attributes (HDFGroup/hdf5#2414).
  H5Gclose(H5Gcreate2(out, "/parameters", H5P_DEFAULT, gcpl, H5P_DEFAULT));
  H5Pclose(gcpl);
  for (const char* top : {"/h5md", "/particles", "/observables", "/parameters/provenance"})
    ASSERT_GE(H5Ocopy(in, top, out, top, H5P_DEFAULT, H5P_DEFAULT), 0) << top;
  H5Fclose(in);
  const bool gzip = H5Zfilter_avail(H5Z_FILTER_DEFLATE) > 0;
  for (const char* name : {"/particles/all/position/value", "/particles/all/velocity/value",
                           "/observables/kinetic_energy/value", "/observables/kinetic_energy/time"}) {
    const hid_t ds = H5Dopen2(out, name, H5P_DEFAULT);
    ASSERT_GE(ds, 0) << name;
    const hid_t space = H5Dget_space(ds);
    const int rank = H5Sget_simple_extent_ndims(space);
    std::vector<hsize_t> dims(static_cast<std::size_t>(rank)), maxdims(dims.size()), chunk(dims.size());
    H5Sget_simple_extent_dims(space, dims.data(), nullptr);
    hsize_t n = 1;
    for (int k = 0; k < rank; ++k) {
      n *= dims[static_cast<std::size_t>(k)];
      maxdims[static_cast<std::size_t>(k)] = k == 0 ? H5S_UNLIMITED : dims[static_cast<std::size_t>(k)];
      chunk[static_cast<std::size_t>(k)] = k == 0 ? 4 : dims[static_cast<std::size_t>(k)];
    }
    std::vector<double> data(n);
    H5Dread(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data());
    H5Sclose(space);
    H5Dclose(ds);
    H5Ldelete(out, name, H5P_DEFAULT);
    const hid_t dcpl = H5Pcreate(H5P_DATASET_CREATE);
    H5Pset_obj_track_times(dcpl, false);
    H5Pset_chunk(dcpl, rank, chunk.data());
    if (gzip) {
      H5Pset_shuffle(dcpl);
      H5Pset_deflate(dcpl, 4);
    }
    const hid_t fspace = H5Screate_simple(rank, dims.data(), maxdims.data());
    // Single precision, as many writers store positions.
    const hid_t nds = H5Dcreate2(out, name, H5T_IEEE_F32LE, fspace, H5P_DEFAULT, dcpl, H5P_DEFAULT);
    ASSERT_GE(nds, 0) << name;
    ASSERT_GE(H5Dwrite(nds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()), 0);
    H5Dclose(nds);
    H5Sclose(fspace);
    H5Pclose(dcpl);
  }
  H5Fclose(out);
}

// Provenance holds the UTC time of the run ("2026-11-22T10:57:03Z", a variable-length string in
// the global heap, which has no checksum): overwrite it in place so the seed bytes, and with them
// every mutated input, are the same on every run.
std::string without_timestamps(std::string b) {
  auto digit = [&](std::size_t i) { return b[i] >= '0' && b[i] <= '9'; };
  const std::string shape = "dddd-dd-ddTdd:dd:ddZ";
  for (std::size_t i = 0; i + shape.size() <= b.size(); ++i) {
    bool match = true;
    for (std::size_t k = 0; k < shape.size() && match; ++k) match = shape[k] == 'd' ? digit(i + k) : b[i + k] == shape[k];
    if (match) b.replace(i, shape.size(), "2000-01-01T00:00:00Z");
  }
  return b;
}

struct Seeds {
  TempDir dir;
  std::map<std::string, std::string> bytes;  // name -> file contents
};

// Built once per process by the tools themselves (their directory is removed at exit).
Seeds& seeds() {
  static Seeds s;
  static const bool built = [] {
    Seeds* seeds = &s;
    const fs::path d = seeds->dir.path();
    fs::create_directory(d / "capture");
    auto tool = [&](const std::string& exe, const std::vector<std::string>& args) {
      const RunResult r = run_tool(exe, args, d, d / "capture");
      if (r.status != 0) throw std::runtime_error("making a seed file failed: " + exe + ": " + r.describe());
    };
    tool(GG_SIM_EXE, {"--dim", "2", "--N", "16", "--L", "8", "--e", "0.7", "--seed", "3", "--t-max", "2", "--samples-per-decade",
                      "5", "--snapshots", "0,1,2", "--velocities", "--pressure", "--quiet", "-o", "sim.h5"});
    tool(GG_SIM_EXE, {"--dim", "2", "--N", "16", "--L", "8", "--e", "0.7", "--seed", "4", "--t-max", "2", "--samples-per-decade",
                      "5", "--snapshots", "0,1,2", "--quiet", "-o", "sim2.h5"});
    tool(GG_CLUSTER_EXE, {"sim.h5", "--histogram", "--grid", "2", "-o", "cluster.h5"});
    tool(GG_FIT_EXE, {"average", "sim.h5:/observables/kinetic_energy/value", "sim2.h5:/observables/kinetic_energy/value",
                      "-o", "average.h5"});
    tool(GG_FIT_EXE, {"power-law", "average.h5:/average/mean", "--window", "0.1", "2", "-o", "fit.h5"});
    rewrite_as_other_writer((d / "sim.h5").string(), (d / "other.h5").string());
    for (const char* name : {"sim.h5", "other.h5", "cluster.h5", "average.h5", "fit.h5"})
      seeds->bytes[name] = without_timestamps(read_bytes((d / name).string()));
    return true;
  }();
  (void)built;
  return s;
}

// ------------------------------------------------------------------------------------------------
// The mutator

// splitmix64: a tiny RNG whose output is the same everywhere (std distributions are not).
struct Rng {
  std::uint64_t s;
  std::uint64_t next() {
    std::uint64_t z = (s += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  std::size_t below(std::size_t n) { return n == 0 ? 0 : static_cast<std::size_t>(next() % n); }
};

std::uint64_t seed_for(const std::string& name, std::uint64_t iteration) {
  std::uint64_t h = 1469598103934665603ULL;  // FNV-1a of the name, then the iteration
  for (char c : name) h = (h ^ static_cast<unsigned char>(c)) * 1099511628211ULL;
  return h ^ (iteration * 0x9e3779b97f4a7c15ULL);
}

// Values that sizes, offsets, counts and dimensions like to get wrong.
constexpr std::array<std::uint64_t, 14> kInteresting{0,          1,          2,          0x7f,       0x80,
                                                      0xff,       0x100,      0x7fff,     0xffff,     0x7fffffff,
                                                      0xffffffff, 0x100000000, 0x7fffffffffffffff, ~0ULL};

// One to four of: bit flips, interesting bytes/words, zeroed runs, truncation, splices from a
// second file, duplicated runs. `other` is the file spliced in.
std::string mutate(std::string b, const std::string& other, Rng& rng, std::string* log = nullptr) {
  const std::size_t ops = 1 + rng.below(4);
  for (std::size_t op = 0; op < ops && !b.empty(); ++op) {
    const std::size_t at = rng.below(b.size());
    const std::size_t kind = rng.below(8);
    if (log) *log += (log->empty() ? "" : "; ") + std::string("op ") + std::to_string(kind) + " at " + std::to_string(at);
    switch (kind) {
      case 0:
      case 1:  // flip a few bits
        for (std::size_t k = 0, n = 1 + rng.below(8); k < n; ++k) b[rng.below(b.size())] ^= static_cast<char>(1u << rng.below(8));
        break;
      case 2:  // an interesting byte
        b[at] = static_cast<char>(kInteresting[rng.below(6)] & 0xff);
        break;
      case 3: {  // an interesting little-endian word of 2, 4 or 8 bytes
        const std::size_t width = std::size_t{2} << rng.below(3);
        std::uint64_t v = kInteresting[rng.below(kInteresting.size())];
        if (rng.below(4) == 0) v = b.size() + rng.below(64) - 32;  // an offset near the end of the file
        for (std::size_t k = 0; k < width && at + k < b.size(); ++k) b[at + k] = static_cast<char>((v >> (8 * k)) & 0xff);
        break;
      }
      case 4:  // zero a run
        std::fill(b.begin() + static_cast<long>(at), b.begin() + static_cast<long>(std::min(b.size(), at + 1 + rng.below(256))), '\0');
        break;
      case 5:  // truncate
        b.resize(rng.below(b.size()));
        break;
      case 6: {  // splice a run of the other file over this one
        if (other.empty()) break;
        const std::size_t from = rng.below(other.size());
        const std::size_t len = std::min({1 + rng.below(512), other.size() - from, b.size() - at});
        b.replace(at, len, other, from, len);
        break;
      }
      default: {  // duplicate a run (shifts everything after it)
        const std::size_t len = std::min(1 + rng.below(128), b.size() - at);
        b.insert(at, b.substr(at, len));
        break;
      }
    }
  }
  return b;
}

// HDF5 1.10 trusts the object headers inside a global heap collection ("GCOL", where variable-length
// strings live), so a damaged one makes the library itself hang or crash:
//  - a free-space object (index 0) of size 0: H5HG__cache_heap_deserialize advances by that size,
//    forever (a hang);
//  - an object whose size runs past the end of its collection: H5HG_read memcpy()s that many
//    bytes (a segfault).
// Both are HDF5's bugs, not ours (see the robustness report), so inputs with such a collection are
// skipped; everything else in the heap (the strings themselves) is still mutated. The walk mirrors
// HDF5's: a 16-byte collection header (signature, version 1, reserved, size), then objects of a
// 16-byte header (index, references, reserved, size) followed by their data padded to 8 bytes.
// `collections` are the offsets of the collections in the unmutated file: HDF5 looks for them there
// only (a "GCOL" spliced in elsewhere is never read).
std::vector<std::size_t> global_heap_collections(const std::string& b) {
  std::vector<std::size_t> at;
  for (std::size_t p = b.find("GCOL"); p != std::string::npos; p = b.find("GCOL", p + 1)) at.push_back(p);
  return at;
}

bool hdf5_global_heap_damaged(const std::string& b, const std::vector<std::size_t>& collections) {
  auto u64 = [&](std::size_t at) {
    std::uint64_t v = 0;
    for (std::size_t k = 0; k < 8; ++k) v |= static_cast<std::uint64_t>(static_cast<unsigned char>(b[at + k])) << (8 * k);
    return v;
  };
  for (std::size_t at : collections) {
    if (at + 16 > b.size() || b.compare(at, 4, "GCOL") != 0) continue;  // HDF5 refuses a missing signature
    const std::uint64_t size = u64(at + 8);
    // A collection HDF5 cannot take for one (or that runs past the end of the file) is refused cleanly.
    if (b[at + 4] != 1 || size < 16 || size > b.size() - at) continue;
    const std::size_t end = at + static_cast<std::size_t>(size);
    std::size_t p = at + 16;
    while (p + 16 <= end) {
      const unsigned idx = static_cast<unsigned char>(b[p]) | static_cast<unsigned>(static_cast<unsigned char>(b[p + 1])) << 8;
      const std::uint64_t obj = u64(p + 8);
      const std::uint64_t need = idx > 0 ? 16 + ((obj + 7) / 8) * 8 : obj;
      if (need == 0 || need > end - p || obj > end - p) return true;
      p += static_cast<std::size_t>(need);
    }
  }
  return false;
}

// HDF5 1.10 divides by the chunk dimensions of a dataset's layout message without checking them or
// their count (SIGFPE in H5D__chunk_set_info_real on opening the dataset; HDFGroup/hdf5#578). Only
// the seed written like other programs do has chunked datasets, and its object headers (version 1)
// carry no checksum, so a flipped byte reaches that division. A version 3 chunked layout message in a
// version 1 object header: type 0x0008 (2 bytes), size (2), flags (1), reserved (3), then version 3,
// class 2, dimensionality n, the B-tree address (8 bytes) and n chunk dimensions of 4 bytes.
bool hdf5_chunk_dimension_zero(const std::string& b) {
  for (std::size_t p = 0; p + 19 <= b.size(); ++p) {
    if (b[p] != 8 || b[p + 1] != 0 || b[p + 8] != 3 || b[p + 9] != 2) continue;
    const std::size_t n = static_cast<unsigned char>(b[p + 10]);
    if (n == 0) return true;  // no dimensions at all: HDF5 divides by a chunk size it never read
    if (p + 19 + 4 * n > b.size()) continue;
    for (std::size_t k = 0; k < n; ++k)
      if (b.compare(p + 19 + 4 * k, 4, std::string(4, '\0')) == 0) return true;
  }
  return false;
}

// ------------------------------------------------------------------------------------------------
// Readers

struct Outcome {
  std::vector<std::string> failures;  // readers that threw something other than gg errors, or misbehaved
};

// Runs `f`; gg::RuntimeError and gg::UsageError are the accepted ways to refuse a file.
void guarded(Outcome& o, const std::string& what, const std::function<void()>& f) {
  try {
    f();
  } catch (const RuntimeError&) {
  } catch (const UsageError&) {
  } catch (const std::exception& e) {
    o.failures.push_back(what + " threw " + typeid(e).name() + ": " + e.what());
  } catch (...) {
    o.failures.push_back(what + " threw a non-std exception");
  }
}

// Every group and dataset (depth-limited: a damaged file may link a group into itself), read every
// way H5Input offers, with the attributes the tools look for.
void walk(const H5Input& in, const std::string& group, int depth, Outcome& o, int& budget) {
  static const char* const kAttrs[] = {"version", "name", "dimension", "boundary", "program", "argv", "seed",
                                       "input", "frames", "grid", "rho", "e", "dim", "method", "inputs", "box_edges"};
  for (const char* a : kAttrs) {
    guarded(o, "attr_strings(" + group + ", " + a + ")", [&] { in.attr_strings(group, a); });
    guarded(o, "attr_doubles(" + group + ", " + a + ")", [&] { in.attr_doubles(group, a); });
    guarded(o, "attr_string(" + group + ", " + a + ")", [&] { in.attr_string(group, a); });
    guarded(o, "attr_double(" + group + ", " + a + ")", [&] { in.attr_double(group, a); });
  }
  if (depth > 6) return;
  std::vector<std::string> names;
  guarded(o, "members(" + group + ")", [&] { names = in.members(group); });
  for (const auto& n : names) {
    if (--budget < 0) return;
    const std::string p = (group == "/" ? "/" : group + "/") + n;
    bool dataset = false;
    guarded(o, "is_dataset(" + p + ")", [&] { dataset = in.is_dataset(p); });
    if (!dataset) {
      walk(in, p, depth + 1, o, budget);
      continue;
    }
    guarded(o, "shape(" + p + ")", [&] { in.shape(p); });
    guarded(o, "read(" + p + ")", [&] { in.read(p); });
    guarded(o, "read_int(" + p + ")", [&] { in.read_int(p); });
    guarded(o, "read_rows(" + p + ")", [&] { in.read_rows(p, {0}); });
    guarded(o, "paired_time(" + p + ")", [&] { paired_time(in, p); });
    for (const char* a : {"name", "unit"}) guarded(o, "attr(" + p + ")", [&] { in.attr_strings(p, a); });
  }
}

// gg-fit's main with stdout discarded and stderr kept: its one line must be ours, not a raw
// message of the C++ library (which would mean an exception escaped our checks).
int fit_main(const std::vector<std::string>& args, const std::string& err_file, std::string& err) {
  std::vector<std::string> a{"gg-fit"};
  a.insert(a.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& s : a) argv.push_back(s.data());
  argv.push_back(nullptr);
  std::fflush(nullptr);
  const int saved_out = dup(1), saved_err = dup(2);
  const int null = open("/dev/null", O_WRONLY), errf = open(err_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  dup2(null, 1);
  dup2(errf, 2);
  close(null);
  close(errf);
  int status = -1;
  try {
    status = fit::gg_fit_main(static_cast<int>(a.size()), argv.data());
  } catch (...) {
    status = -2;
  }
  std::fflush(nullptr);
  std::cout.flush();
  std::cerr.flush();
  dup2(saved_out, 1);
  dup2(saved_err, 2);
  close(saved_out);
  close(saved_err);
  err = read_bytes(err_file);
  return status;
}

bool looks_like_raw_library_message(const std::string& line) {
  for (const char* raw : {"std::", "vector::", "basic_string", "stod", "stoi", "stol", "bad_alloc", "out_of_range",
                          "_M_", "bad_optional", "bad_variant", "map::at"})
    if (line.find(raw) != std::string::npos) return true;
  return false;
}

void close_leftover_identifiers(Outcome& o) {
  const ssize_t open_ids = H5Fget_obj_count(H5F_OBJ_ALL, H5F_OBJ_ALL);
  if (open_ids <= 0) return;
  std::vector<hid_t> ids(static_cast<std::size_t>(open_ids));
  H5Fget_obj_ids(H5F_OBJ_ALL, H5F_OBJ_ALL, ids.size(), ids.data());
  std::string what = std::to_string(open_ids) + " HDF5 identifiers left open:";
  for (hid_t id : ids) {
    char name[256] = "";
    H5Iget_name(id, name, sizeof name);
    const H5I_type_t type = H5Iget_type(id);
    what += " [type " + std::to_string(static_cast<int>(type)) + " " + name + "]";
    if (type == H5I_FILE) H5Fclose(id);
    else if (type == H5I_ATTR) H5Aclose(id);
    else if (type == H5I_DATATYPE) H5Tclose(id);
    else H5Oclose(id);
  }
  o.failures.push_back(what);
}

void exercise(const std::string& path, const fs::path& work, Outcome& o) {
  // The low-level reader and the H5MD readers.
  {
    std::unique_ptr<H5Input> in;
    guarded(o, "H5Input", [&] { in = std::make_unique<H5Input>(path); });
    if (in) {
      int budget = 200;
      walk(*in, "/", 0, o, budget);
      guarded(o, "read_snapshots(all)", [&] { read_snapshots(*in); });
      guarded(o, "read_snapshots(-1)", [&] { read_snapshots(*in, {-1}); });
      guarded(o, "read_snapshots(0,1)", [&] { read_snapshots(*in, {0, 1}); });
      for (const char* obs : {"kinetic_energy", "collisions_per_particle", "pressure"})
        guarded(o, std::string("read_observable(") + obs + ")", [&] { read_observable(*in, obs); });
    }
  }
  // The structural tools, end to end through their library entry points.
  const std::string out = (work / "out.h5").string();
  CommonFlags quiet;
  quiet.quiet = true;
  const std::vector<std::string> argv{"fuzz"};
  auto after_tool = [&](const std::string& tool) {
    // Written or not, nothing half-done may stay behind.
    std::error_code ec;
    fs::remove(out, ec);
    for (const auto& name : entries(work))
      if (name != "in.h5" && name != "err.txt") {
        o.failures.push_back(tool + " left " + name + " behind");
        fs::remove(work / name, ec);
      }
  };
  ClusterConfig cc;
  cc.input = path;
  cc.output = out;
  cc.histogram = true;
  guarded(o, "run_cluster", [&] { run_cluster(cc, quiet, argv); });
  after_tool("run_cluster");
  CorrelateConfig rc;
  rc.input = path;
  rc.output = out;
  guarded(o, "run_correlate", [&] { run_correlate(rc, quiet, argv); });
  after_tool("run_correlate");
  DomainsConfig dc;
  dc.input = path;
  dc.output = out;
  guarded(o, "run_domains", [&] { run_domains(dc, quiet, argv); });
  after_tool("run_domains");
  // gg-fit on whatever the file holds.
  const std::string err_file = (work / "err.txt").string();
  const std::vector<std::vector<std::string>> fits{
      {"table", path},
      {"power-law", path + ":/observables/kinetic_energy/value", "--window", "0.1", "2", "-o", out},
      {"power-law", path + ":/average/mean", "--window", "0.1", "2", "--errors", "jackknife", "-o", out},
      {"average", path + ":/average/mean", path + ":/average/mean", "-o", out},
      {"local-exponent", path + ":/cluster/mean_mass", "--window", "0.3"},
      {"haff", path + ":/observables/kinetic_energy/value", "-o", out},
      {"table", path + ":/cluster/mass_histogram"},
  };
  for (const auto& args : fits) {
    std::string err;
    const int status = fit_main(args, err_file, err);
    const std::string what = "gg-fit " + args[0] + " " + args[1];
    if (status < 0 || status > 2) o.failures.push_back(what + ": exit status " + std::to_string(status));
    const auto lines = std::count(err.begin(), err.end(), '\n');
    if (status != 0 && looks_like_raw_library_message(err)) {
      o.failures.push_back(what + ": stderr [" + err + "]");
    } else if (status != 0 && lines != 1) {
      o.failures.push_back(what + ": " + std::to_string(lines) + " lines on stderr [" + err + "]");
    }
    after_tool(what);
  }
}

// ------------------------------------------------------------------------------------------------

// Iterations per seed file: about 3 s of CPU each in Release; a quarter of them under the sanitizers,
// which run the readers about four times slower. GG_FUZZ_SCALE multiplies both.
std::size_t scaled(std::size_t n) {
  const char* s = std::getenv("GG_FUZZ_SCALE");
  const double f = s ? std::atof(s) : 1.0;
  if (kAddressSanitizer) n /= 4;
  return static_cast<std::size_t>(static_cast<double>(n) * (f > 0 ? f : 1.0));
}

// Mutates `seed` `iterations` times (deterministically) and runs every reader on each result.
void fuzz(const std::string& test, const std::string& seed, const std::string& splice_from, std::size_t iterations) {
  install_last_words();
  const std::string& original = seeds().bytes.at(seed);
  const std::string& other = seeds().bytes.at(splice_from);
  const std::vector<std::size_t> collections = global_heap_collections(original);
  TempDir dir;
  const fs::path work = dir.path();
  const std::string path = (work / "in.h5").string();

  std::size_t first = 0, last = scaled(iterations);
  bool repro = false;
  if (const char* r = std::getenv("GG_FUZZ_REPRO")) {
    const std::string spec = r;
    const auto colon = spec.find(':');
    if (spec.substr(0, colon) != test) GTEST_SKIP() << "GG_FUZZ_REPRO names another test";
    first = std::stoul(spec.substr(colon + 1));
    last = first + 1;
    repro = true;
  }
  // Unmutated, every reader must simply work on the seed (or refuse it cleanly).
  std::size_t failures_shown = 0, failed = 0;
  std::map<std::string, std::size_t> skipped;  // inputs that would hit an HDF5 bug, by kind
  for (std::size_t i = first; i < last; ++i) {
    Rng rng{seed_for(test, i)};
    std::string ops;
    const std::string bytes = mutate(original, other, rng, &ops);
    write_bytes(path, bytes);
    if (repro) {
      write_bytes("fuzz-repro.h5", bytes);
      write_bytes("fuzz-repro-seed.h5", original);
      std::cerr << test << " iteration " << i << ": " << ops << " (ops: 0-1 bit flips, 2 byte, 3 word, 4 zero run, "
                << "5 truncate, 6 splice, 7 duplicate)\n";
    }
    if (hdf5_global_heap_damaged(bytes, collections)) {
      ++skipped["damaged global heap (HDF5 hangs or crashes)"];
      continue;
    }
    if (hdf5_chunk_dimension_zero(bytes)) {
      ++skipped["chunk dimension 0 (HDF5 divides by it)"];
      continue;
    }
    std::snprintf(g_current, sizeof g_current, "%s iteration %zu (%zu bytes, kept at %s)", test.c_str(), i,
                  bytes.size(), path.c_str());
    alarm(20);
    Outcome o;
    exercise(path, work, o);
    alarm(0);
    // Every identifier the readers opened must be closed again, whatever the file held (what HDF5
    // itself leaks on a damaged file is its business: see __lsan_default_suppressions).
    close_leftover_identifiers(o);
    if (!o.failures.empty()) {
      ++failed;
      for (const auto& f : o.failures)
        if (failures_shown++ < 20) ADD_FAILURE() << test << " iteration " << i << ": " << f;
    }
  }
  std::snprintf(g_current, sizeof g_current, "%s: done", test.c_str());
  std::cout << test << ": " << (last - first) << " mutated inputs, " << failed << " failed\n";
  for (const auto& [why, n] : skipped) std::cout << "  skipped " << n << " (HDF5 bug: " << why << ")\n";
  EXPECT_EQ(failed, 0u) << "of " << (last - first) << " mutated inputs";
}

TEST(FuzzReaders, SeedsReadCleanly) {
  install_last_words();
  for (const auto& [name, bytes] : seeds().bytes) {
    TempDir dir;
    const std::string path = dir.file("in.h5");
    write_bytes(path, bytes);
    EXPECT_FALSE(hdf5_global_heap_damaged(bytes, global_heap_collections(bytes))) << name;
    EXPECT_FALSE(hdf5_chunk_dimension_zero(bytes)) << name;
    Outcome o;
    exercise(path, dir.path(), o);
    for (const auto& f : o.failures) ADD_FAILURE() << name << " (unmutated): " << f;
  }
}

// gg-sim --resume of a mutated checkpoint (a real one, of a run stopped by SIGTERM): an error, one
// line, exit 1 or 2, the checkpoint untouched and nothing written; never a crash, a hang, or a run
// that continues from other bytes than the ones gg-sim wrote (their seal covers every byte).
TEST(FuzzReaders, CheckpointResume) {
  TempDir dir;
  const fs::path work = dir.path() / "work", capture = dir.path() / "capture";
  fs::create_directory(work);
  fs::create_directory(capture);
  make_checkpoint(dir.path(), "seed.h5");
  const std::string original = read_bytes(dir.file("seed.h5"));
  const std::string ck = (work / "ck.h5").string();
  std::size_t tried = 0, failed = 0;
  for (std::size_t i = 0; i < scaled(100); ++i) {
    Rng rng{seed_for("CheckpointResume", i)};
    const std::string bytes = mutate(original, original, rng);
    if (bytes == original) continue;  // nothing changed (a run of zeros zeroed, say)
    ++tried;
    write_bytes(ck, bytes);
    const RunResult r = run_tool(GG_SIM_EXE, {"--resume", "ck.h5", "-o", "out.h5", "--quiet"}, work, capture, "/dev/null", 20);
    std::vector<std::string> wrong;
    if (r.timed_out || r.signal != 0) wrong.push_back(r.describe());
    if (r.status != 1 && r.status != 2) wrong.push_back("resumed, or failed otherwise: " + r.describe());
    if (std::count(r.err.begin(), r.err.end(), '\n') != 1) wrong.push_back("not one line on stderr: [" + r.err + "]");
    if (read_bytes(ck) != bytes) wrong.push_back("the checkpoint was changed");
    if (entries(work) != std::set<std::string>{"ck.h5"}) wrong.push_back("left behind: " + ::testing::PrintToString(entries(work)));
    if (!wrong.empty()) {
      ++failed;
      for (const auto& w : wrong) ADD_FAILURE() << "CheckpointResume iteration " << i << ": " << w;
    }
    for (const auto& name : entries(work)) fs::remove_all(work / name);
  }
  std::cout << "CheckpointResume: " << tried << " mutated checkpoints, " << failed << " failed\n";
  EXPECT_GT(tried, 0u);
}

TEST(FuzzReaders, SimOutput) { fuzz("SimOutput", "sim.h5", "cluster.h5", 200); }
TEST(FuzzReaders, OtherWriterH5md) { fuzz("OtherWriterH5md", "other.h5", "sim.h5", 200); }
TEST(FuzzReaders, ClusterOutput) { fuzz("ClusterOutput", "cluster.h5", "sim.h5", 200); }
TEST(FuzzReaders, AverageOutput) { fuzz("AverageOutput", "average.h5", "fit.h5", 200); }
TEST(FuzzReaders, FitOutput) { fuzz("FitOutput", "fit.h5", "average.h5", 200); }

}  // namespace
}  // namespace gg::robust
