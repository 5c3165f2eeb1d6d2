#pragma once
// The bad-input table: every tool, run as a user would, on inputs that must be refused;
// its fixtures, and how a case is run (robustness_bad_input_test).
#include <gtest/gtest.h>

#include <hdf5.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "robustness_support.hpp"

namespace gg::robust {

inline constexpr int kEither = -1;  // exit status 1 or 2: where either reading of the contract is fair

// One row of the table. The tool runs in a fresh directory holding only the `inputs` it names
// (built by make_input); afterwards that directory must hold exactly what it held before, every
// file with the same bytes.
struct BadCase {
  std::string name;                 // test name (letters, digits, '_')
  std::string tool;                 // gg-sim, gg-cluster, gg-correlate, gg-domains, gg-velocity, gg-fit
  std::vector<std::string> args;    // after the executable
  std::vector<std::string> inputs;  // fixture names to create in the directory first
  int status;                       // expected exit status: 1 runtime error, 2 usage error, kEither
  // Each needle must occur in the one stderr line (case-insensitive); "a|b" accepts either.
  std::vector<std::string> needles;
  std::string stdin_input;          // fixture fed on stdin ("" = /dev/null)
  int timeout_s = 60;
  // The tool must run out of memory: it runs with 1 GB of address space (else 4 GB, see run_tool).
  // ASan builds cannot cap it; there the case is skipped (the tool would abort in ASan's allocator).
  bool out_of_memory = false;
  int close_fd = -1;  // started with this standard descriptor closed (`>&-`)

  BadCase(std::string name_, std::string tool_, std::vector<std::string> args_, std::vector<std::string> inputs_,
          int status_, std::vector<std::string> needles_, std::string stdin_input_ = "")
      : name(std::move(name_)), tool(std::move(tool_)), args(std::move(args_)), inputs(std::move(inputs_)),
        status(status_), needles(std::move(needles_)), stdin_input(std::move(stdin_input_)) {}
};

inline std::ostream& operator<<(std::ostream& os, const BadCase& c) {
  os << c.tool;
  for (const auto& a : c.args) os << ' ' << a;
  if (!c.stdin_input.empty()) os << " < " << c.stdin_input;
  return os;
}

inline std::string tool_path(const std::string& tool) {
  static const std::map<std::string, std::string> paths{{"gg-sim", GG_SIM_EXE},
                                                        {"gg-cluster", GG_CLUSTER_EXE},
                                                        {"gg-correlate", GG_CORRELATE_EXE},
                                                        {"gg-domains", GG_DOMAINS_EXE},
                                                        {"gg-velocity", GG_VELOCITY_EXE},
                                                        {"gg-fit", GG_FIT_EXE}};
  return paths.at(tool);
}

// ------------------------------------------------------------------------------------------------
// Fixtures: tiny files, each wrong in one way.

constexpr double kL = 10;       // box edge of every particle fixture
constexpr std::size_t kN = 9;   // disks, on a lattice of spacing 2 (no overlap)
constexpr std::size_t kFrames = 2;

inline Snapshots valid_2d() { return lattice_snapshots(2, kN, kL, kFrames, true); }

// Snapshots with one coordinate of the last frame replaced (what gg-sim --init reads, and a frame
// the analysis tools reach only after they have opened their output).
inline Snapshots with_last_frame_value(double x, std::size_t index = 0) {
  Snapshots s = valid_2d();
  s.position[(kFrames - 1) * kN * 2 + index] = x;
  return s;
}

// Replaces the dataset `name` of an existing file with a fixed-length string dataset of `shape`
// (H5Output writes numbers only; a string where numbers belong is what another program may write).
inline void put_string_dataset(const std::string& path, const std::string& name, const std::vector<hsize_t>& shape) {
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  if (file < 0) throw std::runtime_error("cannot reopen " + path);
  if (H5Lexists(file, name.c_str(), H5P_DEFAULT) > 0) H5Ldelete(file, name.c_str(), H5P_DEFAULT);
  const hid_t type = H5Tcopy(H5T_C_S1);
  H5Tset_size(type, 8);
  const hid_t space = H5Screate_simple(static_cast<int>(shape.size()), shape.data(), nullptr);
  const hid_t lcpl = H5Pcreate(H5P_LINK_CREATE);
  H5Pset_create_intermediate_group(lcpl, 1);
  const hid_t ds = H5Dcreate2(file, name.c_str(), type, space, lcpl, H5P_DEFAULT, H5P_DEFAULT);
  hsize_t n = 1;
  for (hsize_t d : shape) n *= d;
  std::string data(static_cast<std::size_t>(n) * 8, '\0');
  for (hsize_t i = 0; i < n; ++i) data.replace(static_cast<std::size_t>(i) * 8, 3, "abc");
  const herr_t written = H5Dwrite(ds, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data());
  H5Dclose(ds);
  H5Pclose(lcpl);
  H5Sclose(space);
  H5Tclose(type);
  H5Fclose(file);
  if (ds < 0 || written < 0) throw std::runtime_error("cannot write string dataset " + name + " in " + path);
}

// m(t) = 2 t^0.6 at 41 times over t = 1 .. 1e4, as gg-cluster would write it; `mutate` edits it
// first, `more` writes more into the file.
inline void write_series(const std::string& path,
                         const std::function<void(std::vector<double>&, std::vector<double>&)>& mutate = {},
                         const std::function<void(H5Output&)>& more = {}) {
  std::vector<double> t, m;
  for (int i = 0; i <= 40; ++i) {
    t.push_back(std::pow(10.0, 0.1 * i));
    m.push_back(2 * std::pow(t.back(), 0.6));
  }
  if (mutate) mutate(t, m);
  H5Output out(path);
  out.write("/cluster/time", t);
  out.write("/cluster/mean_mass", m);
  if (more) more(out);
  out.commit();
}

// A dataset of `dims` doubles that exists only on paper: chunked, no chunk ever written, so the
// file stays a few kB (HDF5 returns the fill value for every element). A valid file, just a huge claim.
inline void sparse_dataset(const std::string& path, const char* name, const std::vector<hsize_t>& dims) {
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  if (H5Lexists(file, name, H5P_DEFAULT) > 0) H5Ldelete(file, name, H5P_DEFAULT);
  const hid_t lcpl = H5Pcreate(H5P_LINK_CREATE);
  H5Pset_create_intermediate_group(lcpl, 1);
  const hid_t dcpl = H5Pcreate(H5P_DATASET_CREATE);
  std::vector<hsize_t> chunk(dims.size(), 1);
  chunk.back() = dims.back();
  H5Pset_chunk(dcpl, static_cast<int>(dims.size()), chunk.data());
  const hid_t space = H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr);
  const hid_t ds = H5Dcreate2(file, name, H5T_IEEE_F64LE, space, lcpl, dcpl, H5P_DEFAULT);
  H5Dclose(ds);
  H5Sclose(space);
  H5Pclose(dcpl);
  H5Pclose(lcpl);
  H5Fclose(file);
  if (ds < 0) throw std::runtime_error(std::string("cannot create sparse dataset ") + name + " in " + path);
}

// The provenance group of `path` gets `extra` more string attributes: with more than 8 in all,
// HDF5 stores them densely (a fractal heap), as a richer provenance would be.
inline void add_provenance_notes(const std::string& path, int extra) {
  {
    H5Output out(path + ".tmp.h5");
    H5Input in(path);
    // Rebuild the file with the notes (H5Output cannot append): copy its top groups, then add.
    for (const auto& top : in.members("/"))
      if (top != "parameters") out.copy_from(in, "/" + top, "/" + top);
    out.attr("/parameters/provenance", "program", std::string("someone-elses-writer"));
    for (int k = 0; k < extra; ++k)
      out.attr("/parameters/provenance", "note" + std::to_string(k), std::string("a note, stored as a string"));
    out.commit();
  }
  fs::rename(path + ".tmp.h5", path);
}

// Flips one byte of the signature of `object`'s header: HDF5 then refuses that object cleanly, a
// damaged file. (Damage further in is caught by the header's checksum, after HDF5 1.10 has begun
// decoding the header, which it then leaks: the Sanitize build would report that as the tool's.)
inline void damage_object_header(const std::string& path, const std::string& object) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  haddr_t addr = HADDR_UNDEF;
#if H5_VERSION_GE(1, 12, 0)
  H5O_info2_t info{};
  if (H5Oget_info_by_name3(f, object.c_str(), &info, H5O_INFO_BASIC, H5P_DEFAULT) >= 0)
    H5VLnative_token_to_addr(f, info.token, &addr);
#else
  H5O_info_t info{};
  if (H5Oget_info_by_name2(f, object.c_str(), &info, H5O_INFO_BASIC, H5P_DEFAULT) >= 0) addr = info.addr;
#endif
  H5Fclose(f);
  if (addr == HADDR_UNDEF) throw std::runtime_error("no object " + object + " in " + path);
  std::string bytes = read_bytes(path);
  bytes.at(static_cast<std::size_t>(addr)) ^= 0x5a;
  write_bytes(path, bytes);
}

// One frame at t = 0 of the particles at `position` ([N][dim]), with `velocity` if not empty.
inline Snapshots one_frame(int dim, std::vector<double> edges, std::vector<double> position, std::vector<double> velocity) {
  Snapshots s;
  s.dim = dim;
  s.n_particles = position.size() / static_cast<std::size_t>(dim);
  s.edges = std::move(edges);
  s.time = {0};
  s.step = {0};
  s.position = std::move(position);
  s.velocity = std::move(velocity);
  return s;
}

// Builds fixture `name` in `dir`.
inline void make_input(const fs::path& dir, const std::string& name) {
  const std::string p = (dir / name).string();
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  if (name == "missing.h5") return;  // named but never created
  if (name == "dir.h5") {
    fs::create_directory(p);
  } else if (name == "empty.h5") {
    write_bytes(p, "");
  } else if (name == "text.h5") {
    write_bytes(p, "time,mean_mass\n1,2\n10,7.9\n");
  } else if (name == "valid.h5") {
    write_particles(p, valid_2d());
  } else if (name == "novelocities.h5") {  // valid snapshots, positions only
    write_particles(p, lattice_snapshots(2, kN, kL, kFrames, false));
  } else if (name == "valid1d.h5") {
    write_particles(p, lattice_snapshots(1, kN, 2 * kL, kFrames, true));
  } else if (name == "nogroups.h5") {  // HDF5, but nothing a gg tool expects
    H5Output out(p);
    out.write("/notes/value", std::vector<double>{1, 2, 3});
    out.commit();
  } else if (name == "nopositions.h5") {  // H5MD with a box and an observable, no snapshots
    H5Output out(p);
    out.attr("/h5md", "version", std::vector<std::int64_t>{1, 1});
    out.attr("/particles/all/box", "dimension", std::int64_t{2});
    out.write("/particles/all/box/edges", std::vector<double>{kL, kL});
    write_observable(out, "kinetic_energy", TimeSeries{{0, 5}, {0, 1}, {1, 0.5}});
    out.commit();
  } else if (name == "rank2.h5") {  // [frames][N*d]
    const Snapshots s = valid_2d();
    write_raw_particles(p, 2, s.edges, Array{{kFrames, kN * 2}, s.position});
  } else if (name == "lastdim1.h5") {  // [frames][N][1] in a 2D box
    write_raw_particles(p, 2, {kL, kL}, Array{{kFrames, kN, 1}, std::vector<double>(kFrames * kN, 1.5)});
  } else if (name == "strings.h5") {  // positions stored as strings
    const Snapshots s = valid_2d();
    write_raw_particles(p, 2, s.edges, Array{{kFrames, kN, 2}, s.position});
    put_string_dataset(p, "/particles/all/position/value", {kFrames, kN, 2});
  } else if (name == "4d.h5") {  // a box of a dimension no tool knows
    write_raw_particles(p, 4, {kL, kL, kL, kL}, Array{{kFrames, kN, 4}, std::vector<double>(kFrames * kN * 4, 1.5)});
  } else if (name == "noframes.h5") {  // positions [0][N][2]
    write_raw_particles(p, 2, {kL, kL}, Array{{0, kN, 2}, {}});
  } else if (name == "nan.h5") {
    write_particles(p, with_last_frame_value(nan, 3));
  } else if (name == "inf.h5") {
    write_particles(p, with_last_frame_value(inf, 3));
  } else if (name == "outside.h5") {  // x = 2.5 L
    write_particles(p, with_last_frame_value(2.5 * kL, 4));
  } else if (name == "negative.h5") {  // x = -0.3 L
    write_particles(p, with_last_frame_value(-0.3 * kL, 4));
  } else if (name == "nanvel.h5") {
    Snapshots s = valid_2d();
    s.velocity[(kFrames - 1) * kN * 2 + 5] = nan;
    write_particles(p, s);
  } else if (name == "badedges.h5") {  // a box edge of -10
    const Snapshots s = valid_2d();
    write_raw_particles(p, 2, {-kL, kL}, Array{{kFrames, kN, 2}, s.position});
  } else if (name == "overlap.h5") {  // disk 1 half a diameter from disk 0 in the last frame
    Snapshots s = valid_2d();
    const std::size_t base = (kFrames - 1) * kN * 2;
    s.position[base + 2] = s.position[base + 0] + 0.5;
    s.position[base + 3] = s.position[base + 1];
    write_particles(p, s);
  } else if (name == "series.h5") {
    write_series(p);
  } else if (name == "series_nonpositive.h5") {
    write_series(p, [](auto&, auto& m) { m[20] = 0; m[21] = -3; });
  } else if (name == "series_nan.h5") {
    write_series(p, [nan](auto&, auto& m) { m[7] = nan; });
  } else if (name == "series_short_time.h5") {
    write_series(p, [](auto& t, auto&) { t.pop_back(); });
  } else if (name == "series_rank2.h5") {
    H5Output out(p);
    out.write("/cluster/time", std::vector<double>{1, 2, 3});
    out.write("/cluster/mean_mass", Array{{3, 3}, {1, 2, 3, 4, 5, 6, 7, 8, 9}});
    out.commit();
  } else if (name == "series_strings.h5") {
    write_series(p);
    put_string_dataset(p, "/cluster/mean_mass", {41});
  } else if (name == "series_notime.h5") {
    H5Output out(p);
    out.write("/cluster/mean_mass", std::vector<double>{1, 2, 3});
    out.commit();
  } else if (name == "zeroN.h5") {  // positions [2][0][2]: no particle
    write_raw_particles(p, 2, {kL, kL}, Array{{2, 0, 2}, {}});
  } else if (name == "bigbox.h5") {  // a box of 10^6 diameters holding two disks: 10^12 cells of edge 1
    write_raw_particles(p, 2, {1e6, 1e6}, Array{{1, 2, 2}, {1, 1, 5, 5}});
  } else if (name == "wrapbox1d.h5") {  // a 1D box of 2^32 + 1 diameters: round(L/grid) fits no int
    write_raw_particles(p, 1, {4294967297.0}, Array{{1, 3, 1}, {1, 4, 7}});
  } else if (name == "huge_positions.h5") {  // snapshots claiming 2^36 particles per frame
    write_raw_particles(p, 2, {kL, kL}, Array{{2, kN, 2}, valid_2d().position});
    sparse_dataset(p, "/particles/all/position/value", {2, hsize_t{1} << 36, 2});
  } else if (name == "huge_series.h5") {  // a time series claiming 2^40 samples
    write_series(p);
    sparse_dataset(p, "/cluster/time", {hsize_t{1} << 40});
    sparse_dataset(p, "/cluster/mean_mass", {hsize_t{1} << 40});
  } else if (name == "damaged_provenance.h5") {
    // A series whose provenance has a child group with a damaged header: the fit works, copying
    // the input's provenance into -o fails.
    write_series(p, {}, [](H5Output& out) {
      out.attr("/parameters/provenance", "program", std::string("gg-cluster"));
      out.attr("/parameters/provenance/inputs/0", "file", std::string("sim.h5"));
    });
    damage_object_header(p, "/parameters/provenance/inputs/0");
  } else if (name == "dense_provenance.h5") {  // valid, with 11 string attributes in its provenance
    write_particles(p, valid_2d());
    add_provenance_notes(p, 10);
  } else if (name == "dense_series.h5") {
    write_series(p);
    add_provenance_notes(p, 10);
  } else if (name == "cycle.h5") {  // a series whose group links back to the root (legal HDF5)
    write_series(p);
    const hid_t file = H5Fopen(p.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    H5Lcreate_hard(file, "/", file, "/cluster/everything", H5P_DEFAULT, H5P_DEFAULT);
    H5Fclose(file);
  } else if (name == "link_to_valid.h5" || name == "link_to_series.h5") {
    // Another name for a fixture (listed before it in `inputs`): a tool must see that both are one file.
    fs::create_symlink(name.substr(std::string("link_to_").size()), p);
  } else if (name == "touching1d.h5") {  // 8 rods filling a ring of 8 diameters: each touches both neighbours
    std::vector<double> x, v;
    for (int i = 0; i < 8; ++i) {
      x.push_back(0.5 + i);
      v.push_back((i % 2 ? -1.0 : 1.0) * (1 + 0.1 * i));
    }
    write_particles(p, one_frame(1, {8}, x, v));
  } else if (name == "float_overlap.h5") {
    // Two disks 1 - 2^-23 apart at float-exact coordinates: what single precision makes of two in contact.
    write_particles(p, one_frame(2, {kL, kL}, {1.0, 1.0, 2.0 - std::ldexp(1.0, -23), 1.0}, {}));
  } else if (name == "aggregates.h5") {  // a gg-sim --aggregate output: its frames hold masses
    H5Output out(p);
    write_snapshots(out, valid_2d(), "gg-sim");
    out.write("/particles/all/mass/value", std::vector<double>(valid_2d().n_particles, 1.0));
    out.commit();
  } else if (name == "interrupted.h5") {  // a gg-sim output of a run stopped by a signal
    H5Output out(p);
    write_snapshots(out, valid_2d(), "gg-sim");
    out.attr("/parameters", "stop_reason", std::string("interrupted"));
    out.commit();
  } else if (name == "checkpoint.h5" || name == "out.h5.checkpoint.h5") {  // the second: -o out.h5's, interrupted
    make_checkpoint(dir, name);
  } else if (name == "ck_damaged.h5" || name == "ck_unsealed.h5") {  // one byte changed; the seal's signature gone
    make_checkpoint(dir, name);
    std::string bytes = read_bytes(p);
    if (name == "ck_damaged.h5") bytes.at(bytes.size() / 2) ^= 0x10;
    else bytes.replace(0, 8, 8, '\0');
    write_bytes(p, bytes);
  } else if (name == "scene_blank.ini") {  // e = (nothing)
    write_bytes(p, "dim = 2\nN = 50\nrho = 0.1\ne =\nt-max = 1\n");
  } else if (name == "scene_bogus.ini") {
    write_bytes(p, "dim = 2\nN = 50\nrho = 0.1\ne = 0.5\nt-max = 1\nbogus = 1\n");
  } else if (name == "scene_section.ini") {  // an INI habit; reported as the key "gg-sim.++" before
    write_bytes(p, "[gg-sim]\ndim = 2\nN = 50\nrho = 0.1\ne = 0.5\nt-max = 1\n");
  } else if (name == "scene_nrho.ini") {
    write_bytes(p, "dim = 2\nN = 50\nrho = 0.1\ne = 0.5\nt-max = 1\n");
  } else {
    throw std::invalid_argument("no fixture named " + name);
  }
}

// ------------------------------------------------------------------------------------------------
// Running one case

inline std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

inline bool contains_any(const std::string& haystack, const std::string& alternatives) {
  std::stringstream alts(alternatives);
  std::string alt;
  while (std::getline(alts, alt, '|'))
    if (lower(haystack).find(lower(alt)) != std::string::npos) return true;
  return false;
}

// The bytes of every regular file in `dir` (through symlinks), by name.
inline std::map<std::string, std::string> file_bytes(const fs::path& dir) {
  std::map<std::string, std::string> bytes;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.is_regular_file()) bytes[e.path().filename().string()] = read_bytes(e.path().string());
  return bytes;
}

// Runs the case and checks: exit status, one line on stderr naming the problem (the needles), no
// output (nor temporary) file left, every input as it was (an output written over an input leaves
// the same names behind), nothing on stdout.
inline void check_bad_case(const BadCase& c) {
  SCOPED_TRACE(::testing::PrintToString(c));
  TempDir root;
  const fs::path work = root.path() / "work", capture = root.path() / "capture";
  fs::create_directory(work);
  fs::create_directory(capture);
  for (const auto& in : c.inputs) make_input(work, in);
  if (!c.stdin_input.empty()) make_input(capture, c.stdin_input);
  const auto before = entries(work);
  const auto bytes_before = file_bytes(work);
  const RunResult r = run_tool(tool_path(c.tool), c.args, work, capture,
                               c.stdin_input.empty() ? "/dev/null" : (capture / c.stdin_input).string(), c.timeout_s,
                               c.out_of_memory ? 1024 : 4096, c.close_fd);
  ASSERT_FALSE(r.timed_out) << r.describe();
  ASSERT_EQ(r.signal, 0) << "crashed: " << r.describe();
  if (c.status == kEither)
    EXPECT_TRUE(r.status == 1 || r.status == 2) << r.describe();
  else
    EXPECT_EQ(r.status, c.status) << r.describe();
  const auto lines = std::count(r.err.begin(), r.err.end(), '\n');
  EXPECT_TRUE(lines == 1 && r.err.back() == '\n' && r.err.size() > 1)
      << "stderr must be exactly one line, got " << lines << ": [" << r.err << "]";
  EXPECT_EQ(r.err.rfind(c.tool, 0), 0u) << "the line should start with the program name: [" << r.err << "]";
  for (const auto& needle : c.needles)
    EXPECT_TRUE(contains_any(r.err, needle)) << "stderr does not name the problem ('" << needle << "'): [" << r.err << "]";
  EXPECT_TRUE(r.out.empty()) << "stdout carries only data, but got " << r.out.size() << " bytes";
  const auto after = entries(work);
  std::vector<std::string> added;
  std::set_difference(after.begin(), after.end(), before.begin(), before.end(), std::back_inserter(added));
  EXPECT_TRUE(added.empty()) << "left behind: " << ::testing::PrintToString(added);
  const auto bytes_after = file_bytes(work);
  for (const auto& [name, bytes] : bytes_before) {
    const auto it = bytes_after.find(name);
    EXPECT_TRUE(it != bytes_after.end() && it->second == bytes) << "input " << name << " was changed or removed";
  }
}

inline std::string case_name(const ::testing::TestParamInfo<BadCase>& info) { return info.param.name; }

}  // namespace gg::robust
