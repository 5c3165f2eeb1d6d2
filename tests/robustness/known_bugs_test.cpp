// Tool bugs found by the robustness tests (issue 7), each shown by a failing test. Built as
// robustness_known_bugs but NOT registered with ctest: run it by hand
//   build/tests/robustness/robustness_known_bugs
// and once a bug is fixed, move its test into the registered suites (a bad-input row goes to
// bad_input_test.cpp; the fuzz test then also stops counting it as "known").
#include <gtest/gtest.h>

#include <hdf5.h>

#include <cmath>
#include <string>
#include <vector>

#include "bad_input_cases.hpp"
#include "gg/h5file.hpp"
#include "gg/provenance.hpp"
#include "h5_contents.hpp"

namespace gg::robust {
namespace {

// ------------------------------------------------------------------------------------------------
// Fixtures of these tests

void raw_file(const std::string& p, std::int64_t dim, const std::vector<double>& edges, const Array& value) {
  write_raw_particles(p, dim, edges, value);
}

// A dataset of `n` doubles that exists only on paper: chunked, no chunk ever written, so the file
// stays a few KB (HDF5 returns the fill value for every element). A valid file, just a huge claim.
void sparse_dataset(hid_t file, const char* name, const std::vector<hsize_t>& dims) {
  const hid_t lcpl = H5Pcreate(H5P_LINK_CREATE);
  H5Pset_create_intermediate_group(lcpl, 1);
  const hid_t dcpl = H5Pcreate(H5P_DATASET_CREATE);
  std::vector<hsize_t> chunk(dims.size(), 1);
  chunk.back() = dims.back();
  H5Pset_chunk(dcpl, static_cast<int>(dims.size()), chunk.data());
  const hid_t space = H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr);
  const hid_t ds = H5Dcreate2(file, name, H5T_IEEE_F64LE, space, lcpl, dcpl, H5P_DEFAULT);
  if (ds < 0) throw std::runtime_error(std::string("cannot create sparse dataset ") + name);
  H5Dclose(ds);
  H5Sclose(space);
  H5Pclose(dcpl);
  H5Pclose(lcpl);
}

// The provenance group of `p` gets `extra` more string attributes: with more than 8 in all, HDF5
// stores them densely (a fractal heap), as a richer provenance would be.
void add_provenance_notes(const std::string& p, int extra) {
  H5Output out(p + ".tmp.h5");
  H5Input in(p);
  // Rebuild the file with the notes (H5Output cannot append): copy its top groups, then add.
  for (const auto& top : in.members("/"))
    if (top != "parameters") out.copy_from(in, "/" + top, "/" + top);
  out.attr("/parameters/provenance", "program", std::string("someone-elses-writer"));
  for (int k = 0; k < extra; ++k)
    out.attr("/parameters/provenance", "note" + std::to_string(k), std::string("a note, stored as a string"));
  out.commit();
  fs::rename(p + ".tmp.h5", p);
}

// Flips one byte inside the object header of `object` (H5Output's format checksums headers, so
// HDF5 then refuses that object cleanly: a damaged file, no crash).
void damage_object_header(const std::string& p, const std::string& object) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  const hid_t f = H5Fopen(p.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  H5O_info_t info{};
#if H5_VERSION_GE(1, 12, 0)
  haddr_t addr = HADDR_UNDEF;
  H5O_info2_t info2{};
  if (H5Oget_info_by_name3(f, object.c_str(), &info2, H5O_INFO_BASIC, H5P_DEFAULT) >= 0)
    H5VLnative_token_to_addr(f, info2.token, &addr);
  (void)info;
#else
  const herr_t got = H5Oget_info_by_name2(f, object.c_str(), &info, H5O_INFO_BASIC, H5P_DEFAULT);
  const haddr_t addr = got >= 0 ? info.addr : HADDR_UNDEF;
#endif
  H5Fclose(f);
  if (addr == HADDR_UNDEF) throw std::runtime_error("no object " + object + " in " + p);
  std::string bytes = read_bytes(p);
  bytes.at(static_cast<std::size_t>(addr) + 12) ^= 0x5a;
  write_bytes(p, bytes);
}

void register_fixtures() {
  auto& f = extra_fixtures();
  if (!f.empty()) return;
  // gg-sim --init: a file of 0 particles.
  f["zeroN.h5"] = [](const std::string& p) { raw_file(p, 2, {kL, kL}, Array{{2, 0, 2}, {}}); };
  // A box of 10^6 diameters holding two disks: 10^12 cells of edge 1.
  f["bigbox.h5"] = [](const std::string& p) { raw_file(p, 2, {1e6, 1e6}, Array{{1, 2, 2}, {1, 1, 5, 5}}); };
  // A 1D box of 2^32 + 1 diameters: round(L/grid) does not fit in an int.
  f["wrapbox1d.h5"] = [](const std::string& p) { raw_file(p, 1, {4294967297.0}, Array{{1, 3, 1}, {1, 4, 7}}); };
  // A series whose group links back to the root (legal in HDF5; h5ls -r prints "same as /").
  f["cycle.h5"] = [](const std::string& p) {
    write_series(p);
    const hid_t file = H5Fopen(p.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    H5Lcreate_hard(file, "/", file, "/cluster/everything", H5P_DEFAULT, H5P_DEFAULT);
    H5Fclose(file);
  };
  // A time series claiming 2^40 samples (a few KB on disk).
  f["huge_series.h5"] = [](const std::string& p) {
    const hid_t file = H5Fcreate(p.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    sparse_dataset(file, "/cluster/time", {hsize_t{1} << 40});
    sparse_dataset(file, "/cluster/mean_mass", {hsize_t{1} << 40});
    H5Fclose(file);
  };
  // Snapshots claiming 2^36 particles per frame.
  f["huge_positions.h5"] = [](const std::string& p) {
    raw_file(p, 2, {kL, kL}, Array{{2, kN, 2}, valid_2d().position});
    const hid_t file = H5Fopen(p.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    H5Ldelete(file, "/particles/all/position/value", H5P_DEFAULT);
    sparse_dataset(file, "/particles/all/position/value", {2, hsize_t{1} << 36, 2});
    H5Fclose(file);
  };
  // Valid files whose provenance holds 11 string attributes (dense attribute storage).
  f["dense_provenance.h5"] = [](const std::string& p) {
    write_particles(p, valid_2d());
    add_provenance_notes(p, 10);
  };
  f["dense_series.h5"] = [](const std::string& p) {
    write_series(p);
    add_provenance_notes(p, 10);
  };
  // A series whose provenance has a child group with a damaged header: the fit works, copying the
  // input's provenance into -o fails.
  f["damaged_provenance.h5"] = [](const std::string& p) {
    {
      std::vector<double> t, m;
      for (int i = 0; i <= 40; ++i) {
        t.push_back(std::pow(10.0, 0.1 * i));
        m.push_back(2 * std::pow(t.back(), 0.6));
      }
      H5Output out(p);
      out.write("/cluster/time", t);
      out.write("/cluster/mean_mass", m);
      out.attr("/parameters/provenance", "program", std::string("gg-cluster"));
      out.attr("/parameters/provenance/inputs/0", "file", std::string("sim.h5"));
      out.commit();
    }
    damage_object_header(p, "/parameters/provenance/inputs/0");
  };
}

// ------------------------------------------------------------------------------------------------
// Bad-input rows that fail today

bool needs_memory_cap(const BadCase& c) {
  return c.name.find("huge") != std::string::npos || c.name.find("box") != std::string::npos;
}

std::vector<BadCase> known_bad_cases() {
  register_fixtures();
  const std::vector<std::string> end{"--e", "0.5", "--t-max", "1", "-o", "out.h5"};
  auto with = [](std::vector<std::string> a, const std::vector<std::string>& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
  };
  std::vector<BadCase> c{
      // --init FILE with 0 particles runs and writes an output.
      {"gg_sim_init_zero_particles", "gg-sim", with({"--init", "zeroN.h5"}, end), {"zeroN.h5"}, kEither,
       {"zeroN.h5", "particle"}},
      // Asking for 2e9 samples: "std::bad_alloc", which names neither the flag nor the cause.
      {"gg_sim_samples_per_decade_huge", "gg-sim",
       {"--N", "50", "--rho", "0.1", "--e", "0.5", "--t-max", "1", "--samples-per-decade", "1e9", "-o", "out.h5"}, {},
       kEither, {"--samples-per-decade|memory"}},
      // gg-fit table FILE recurses through a group cycle until the stack overflows (hours first:
      // the path grows at every level), so this row times out after 10 s.
      {"gg_fit_table_group_cycle", "gg-fit", {"table", "cycle.h5"}, {"cycle.h5"}, kEither, {"cycle.h5"}},
      // A time series claiming 2^40 samples: H5Input::read allocates first -> "std::bad_alloc".
      {"gg_fit_huge_dataset", "gg-fit",
       {"power-law", "huge_series.h5:/cluster/mean_mass", "--window", "1", "100", "-o", "out.h5"}, {"huge_series.h5"}, 1,
       {"huge_series.h5", "/cluster/mean_mass"}},
      // gg-fit prints the fit's result line, then fails copying the input's provenance into -o:
      // two lines on stderr (say() comes before Output::finish()).
      {"gg_fit_result_line_before_failed_output", "gg-fit",
       {"power-law", "damaged_provenance.h5:/cluster/mean_mass", "--window", "1", "100", "-o", "out.h5"},
       {"damaged_provenance.h5"}, 1, {"damaged_provenance.h5"}},
  };
  for (const char* tool : {"gg-cluster", "gg-correlate", "gg-domains"}) {
    const std::string t = tool;
    const std::string id = t == "gg-cluster" ? "cluster" : t == "gg-correlate" ? "correlate" : "domains";
    // L = 10^6: 10^12 cells of the default --grid 1 -> "std::bad_alloc"; should name --grid.
    c.push_back({"gg_" + id + "_box_1e6_cells", t, {"bigbox.h5", "-o", "out.h5"}, {"bigbox.h5"}, 2, {"--grid"}});
    // L = 2^32 + 1: the cell count wraps to 1 and the tool "succeeds" with one cell; should refuse.
    c.push_back({"gg_" + id + "_cell_count_overflow", t, {"wrapbox1d.h5", "-o", "out.h5"}, {"wrapbox1d.h5"}, 2, {"--grid"}});
    // Positions claiming 2^36 particles: "std::bad_alloc".
    c.push_back({"gg_" + id + "_huge_positions", t, {"huge_positions.h5", "-o", "out.h5"}, {"huge_positions.h5"}, 1,
                 {"huge_positions.h5", "position"}});
  }
  c.push_back({"gg_sim_init_huge_positions", "gg-sim", with({"--init", "huge_positions.h5"}, end), {"huge_positions.h5"},
               1, {"huge_positions.h5", "position"}});
  for (auto& row : c) {
    if (row.name == "gg_fit_table_group_cycle") row.timeout_s = 10;
    // Where a tool believes a huge size, 1 GB of address space is enough to see it fail.
    if (needs_memory_cap(row)) row.memory_mb = 1024;
  }
  return c;
}

class KnownBadInput : public ::testing::TestWithParam<BadCase> {};

TEST_P(KnownBadInput, RefusedWithOneLineAndNoOutput) {
  const BadCase& c = GetParam();
  if (kAddressSanitizer && needs_memory_cap(c))
    GTEST_SKIP() << "needs the memory cap that ASan builds cannot set (the tool would abort in ASan's allocator)";
  check_bad_case(c);
}

INSTANTIATE_TEST_SUITE_P(Table, KnownBadInput, ::testing::ValuesIn(known_bad_cases()), case_name);

// ------------------------------------------------------------------------------------------------
// Valid input, wrong result

struct Dir {
  TempDir root;
  fs::path work = root.path() / "work", capture = root.path() / "capture";
  Dir() {
    fs::create_directory(work);
    fs::create_directory(capture);
  }
};

// Every analysis tool copies its input's /parameters/provenance with H5Ocopy, which in HDF5 < 1.14.4
// segfaults on densely stored variable-length string attributes (HDFGroup/hdf5#2414): an input whose
// provenance has more than 8 string attributes (e.g. from another writer, or a future gg version)
// crashes gg-cluster/-correlate/-domains (exit 139, the temporary output left behind) and gg-fit -o.
// Copy the attributes one by one instead (H5Ocopy with H5O_COPY_WITHOUT_ATTR_FLAG, then read and
// write each attribute), as h5repack does since hdf5#3419.
TEST(ProvenanceKnownBugs, DenseProvenanceOfTheInputIsCopied) {
  register_fixtures();
  struct Run {
    std::string tool;
    std::vector<std::string> args;
    std::string input;
  };
  const std::vector<Run> runs{
      {"gg-cluster", {"dense_provenance.h5", "-o", "out.h5"}, "dense_provenance.h5"},
      {"gg-correlate", {"dense_provenance.h5", "-o", "out.h5"}, "dense_provenance.h5"},
      {"gg-domains", {"dense_provenance.h5", "-o", "out.h5"}, "dense_provenance.h5"},
      {"gg-fit", {"power-law", "dense_series.h5:/cluster/mean_mass", "--window", "1", "100", "-o", "out.h5"}, "dense_series.h5"},
  };
  for (const auto& r : runs) {
    SCOPED_TRACE(r.tool);
    Dir d;
    make_input(d.work, r.input);
    const RunResult res = run_tool(tool_path(r.tool), r.args, d.work, d.capture);
    EXPECT_EQ(res.signal, 0) << res.describe();
    EXPECT_EQ(res.status, 0) << res.describe();
    EXPECT_EQ(entries(d.work), (std::set<std::string>{r.input, "out.h5"}));
    if (res.status == 0) {
      const Contents out = h5_contents((d.work / "out.h5").string());
      EXPECT_TRUE(out.count("/parameters/provenance/inputs/0@note9")) << "the input's provenance is not in the output";
    }
  }
}

// gg-sim --init FILE writes /parameters/rho = 0 (the value of the unset flag), not N/L^d of the
// file; gg-fit haff then refuses the output ("rho = 0 gives packing fraction 0").
TEST(SimKnownBugs, InitFromFileRecordsTheDensityOfTheFile) {
  register_fixtures();
  Dir d;
  make_input(d.work, "valid.h5");
  const RunResult r = run_tool(GG_SIM_EXE, {"--init", "valid.h5", "--e", "0.5", "--t-max", "1", "-o", "out.h5"}, d.work,
                               d.capture);
  ASSERT_EQ(r.status, 0) << r.describe();
  H5Input in((d.work / "out.h5").string());
  EXPECT_EQ(in.attr_double("/parameters", "N"), static_cast<double>(kN));
  EXPECT_EQ(in.attr_double("/parameters", "L"), kL);
  EXPECT_DOUBLE_EQ(in.attr_double("/parameters", "rho").value_or(-1), static_cast<double>(kN) / (kL * kL));
}

}  // namespace
}  // namespace gg::robust
