// Provenance of every output, and the lineage copied from its inputs (docs/DESIGN.md).
#include "gg/provenance.hpp"

#include <gtest/gtest.h>

#include <cctype>

#include "gg/h5file.hpp"
#include "gg/version.hpp"
#include "test_support.hpp"

namespace gg {
namespace {

using test::TempDir;

const std::string kProv = "/parameters/provenance";

// "2024-05-01T12:34:56Z"
bool is_iso8601_utc(const std::string& t) {
  const std::string pattern = "dddd-dd-ddTdd:dd:ddZ";
  if (t.size() != pattern.size()) return false;
  for (std::size_t i = 0; i < t.size(); ++i)
    if (pattern[i] == 'd' ? !std::isdigit(static_cast<unsigned char>(t[i])) : t[i] != pattern[i]) return false;
  return true;
}

TEST(CommonProvenance, RecordsProgramVersionArgvTimeSeedAndLibraries) {
  TempDir dir;
  {
    H5Output out(dir.file("p.h5"));
    write_provenance(out, {"gg-sim", {"gg-sim", "--seed", "7", "-o", "p.h5"}, 18446744073709551615ull});
    out.commit();
  }
  H5Input in(dir.file("p.h5"));
  EXPECT_EQ(in.attr_string(kProv, "program"), "gg-sim");
  EXPECT_EQ(in.attr_string(kProv, "version"), std::string(kVersion));
  EXPECT_EQ(in.attr_string(kProv, "git_hash"), std::string(kGitHash));
  EXPECT_EQ(in.attr_strings(kProv, "argv"), (std::vector<std::string>{"gg-sim", "--seed", "7", "-o", "p.h5"}));
  EXPECT_TRUE(is_iso8601_utc(*in.attr_string(kProv, "utc_time"))) << *in.attr_string(kProv, "utc_time");
  EXPECT_EQ(in.attr_double(kProv, "seed"), 18446744073709551615.0);
  EXPECT_EQ(in.attr_string(kProv, "libraries"), library_versions());
  EXPECT_FALSE(in.exists(kProv + "/inputs"));
}

TEST(CommonProvenance, LibraryVersionsNameTheLinkedLibraries) {
  const std::string v = library_versions();
  EXPECT_EQ(v.rfind("HDF5 " + hdf5_version() + ", FFTW 3.", 0), 0u) << v;
  EXPECT_NE(v.find(", GSL 2."), std::string::npos) << v;
  EXPECT_EQ(hdf5_version().rfind("1.", 0), 0u) << hdf5_version();
}

TEST(CommonProvenance, NoSeedAttributeWithoutSeed) {
  TempDir dir;
  {
    H5Output out(dir.file("p.h5"));
    write_provenance(out, {"gg-cluster", {"gg-cluster"}, std::nullopt});
    out.commit();
  }
  EXPECT_FALSE(H5Input(dir.file("p.h5")).attr_double(kProv, "seed").has_value());
}

TEST(CommonProvenance, InputsProvenanceIsCopiedInOrderWithLineage) {
  TempDir dir;
  {  // a simulation output
    H5Output out(dir.file("sim.h5"));
    write_provenance(out, {"gg-sim", {"gg-sim", "--seed", "3"}, 3});
    out.commit();
  }
  {  // a file without provenance
    H5Output out(dir.file("bare.h5"));
    out.write("/x", std::vector<double>{1});
    out.commit();
  }
  {  // an analysis of both
    H5Input sim(dir.file("sim.h5")), bare(dir.file("bare.h5"));
    H5Output out(dir.file("cluster.h5"));
    write_provenance(out, {"gg-cluster", {"gg-cluster", "sim.h5", "bare.h5"}, std::nullopt}, {&sim, &bare});
    out.commit();
  }
  {  // and a fit of the analysis
    H5Input cluster(dir.file("cluster.h5"));
    H5Output out(dir.file("fit.h5"));
    write_provenance(out, {"gg-fit", {"gg-fit"}, std::nullopt}, {&cluster});
    out.commit();
  }
  H5Input cluster(dir.file("cluster.h5"));
  EXPECT_EQ(cluster.members(kProv + "/inputs"), (std::vector<std::string>{"0", "1"}));
  EXPECT_EQ(cluster.attr_string(kProv + "/inputs/0", "program"), "gg-sim");
  EXPECT_EQ(cluster.attr_double(kProv + "/inputs/0", "seed"), 3);
  EXPECT_EQ(cluster.attr_string(kProv + "/inputs/0", "file"), dir.file("sim.h5"));
  EXPECT_FALSE(cluster.attr_string(kProv + "/inputs/1", "program").has_value());
  EXPECT_EQ(cluster.attr_string(kProv + "/inputs/1", "file"), dir.file("bare.h5"));

  H5Input fit(dir.file("fit.h5"));
  EXPECT_EQ(fit.attr_string(kProv + "/inputs/0", "program"), "gg-cluster");
  EXPECT_EQ(fit.attr_string(kProv + "/inputs/0/inputs/0", "program"), "gg-sim");  // the whole lineage
}

// More than 8 attributes are stored densely, where HDF5 before 1.14.4 crashes copying
// variable-length strings with H5Ocopy (HDFGroup/hdf5#2414): a richer provenance from another writer.
TEST(CommonProvenance, DenseProvenanceOfAnInputIsCopied) {
  TempDir dir;
  {
    H5Output out(dir.file("rich.h5"));
    for (int k = 0; k < 12; ++k) out.attr(kProv, "note" + std::to_string(k), "note " + std::to_string(k));
    out.attr(kProv, "seeds", std::vector<std::int64_t>{1, 2, 3});
    out.attr(kProv, "empty", std::vector<std::string>{});
    for (int k = 0; k < 10; ++k) out.attr(kProv + "/inputs/0", "tag" + std::to_string(k), static_cast<double>(k));
    out.write(kProv + "/table", std::vector<double>{1, 2});
    out.attr(kProv + "/table", "unit", std::string("sigma"));
    out.commit();
  }
  {
    H5Input rich(dir.file("rich.h5"));
    H5Output out(dir.file("a.h5"));
    write_provenance(out, {"gg-cluster", {"gg-cluster"}, std::nullopt}, {&rich});
    out.commit();
  }
  H5Input a(dir.file("a.h5"));
  const std::string in = kProv + "/inputs/0";
  EXPECT_EQ(a.attr_string(in, "note11"), "note 11");
  EXPECT_EQ(a.attr_doubles(in, "seeds"), (std::vector<double>{1, 2, 3}));
  EXPECT_TRUE(a.attr_strings(in, "empty").empty());
  EXPECT_EQ(a.attr_double(in + "/inputs/0", "tag9"), 9);
  EXPECT_EQ(a.read(in + "/table").data, (std::vector<double>{1, 2}));
  EXPECT_EQ(a.attr_string(in + "/table", "unit"), "sigma");
}

TEST(CommonProvenance, InputFromStdinIsCopied) {
  TempDir dir;
  {
    H5Output out(dir.file("sim.h5"));
    write_provenance(out, {"gg-sim", {"gg-sim"}, 11});
    out.commit();
  }
  test::with_fd_redirected(0, dir.file("sim.h5"), [&] {
    H5Input in("-");
    H5Output out(dir.file("a.h5"));
    write_provenance(out, {"gg-cluster", {"gg-cluster", "-"}, std::nullopt}, {&in});
    out.commit();
  });
  H5Input a(dir.file("a.h5"));
  EXPECT_EQ(a.attr_string(kProv + "/inputs/0", "program"), "gg-sim");
  EXPECT_EQ(a.attr_string(kProv + "/inputs/0", "file"), "<stdin>");
}

}  // namespace
}  // namespace gg
