// gg-cluster, gg-correlate, gg-domains end to end: H5MD in, groups of docs/DESIGN.md "Files" out; files vs
// pipes bit-identical; bad input gives one line, the right exit status and no output file.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "gg/h5file.hpp"
#include "gg/trajectory.hpp"
#include "density_grid_fixtures.hpp"
#include "structure_tools.hpp"

namespace fs = std::filesystem;

namespace gg {
namespace {

// Frames of a 2D box L = 64: (0) stripes a = 4, b = 12 normal to x (1 particle per rich cell),
// (1) a 6x6 patch of 2 particles per cell across the periodic corner, (2) uniform random at rho = 0.37.
Snapshots three_frames() {
  Snapshots s;
  s.dim = 2;
  s.edges = {64.0, 64.0};
  const std::vector<int> n = {64, 64};
  const std::vector<double> h = {1.0, 1.0};
  std::vector<std::vector<double>> frames = {
      test::fill_cells(n, h, [](const test::Cell& c) { return c[0] % 16 < 4 ? 1 : 0; }),
      test::fill_cells(n, h, [](const test::Cell& c) { return (c[0] + 3) % 64 < 6 && (c[1] + 3) % 64 < 6 ? 2 : 0; })};
  // Same particle count in every frame: the rest are piled into cell (40, 40), in the middle of a poor
  // stripe and far from the patch: one more cluster (its 3x3 block) holding all of them.
  frames.push_back(test::random_positions(2, 64.0, 1516, 5));
  std::size_t N = 0;
  for (const auto& f : frames) N = std::max(N, f.size() / 2);
  for (auto& f : frames)
    while (f.size() / 2 < N) {
      f.push_back(40.5);
      f.push_back(40.5);
    }
  s.n_particles = N;
  for (std::size_t k = 0; k < frames.size(); ++k) {
    s.time.push_back(1.5 * static_cast<double>(k));
    s.step.push_back(static_cast<std::int64_t>(1000 * k));
    s.position.insert(s.position.end(), frames[k].begin(), frames[k].end());
  }
  return s;
}

class StructureTools : public ::testing::Test {
 protected:
  void SetUp() override {
    char tmpl[] = "/tmp/gg-structure-test-XXXXXX";
    ASSERT_NE(mkdtemp(tmpl), nullptr);
    dir_ = tmpl;
    H5Output out(path("in.h5"));
    write_snapshots(out, three_frames(), "test");
    out.commit();
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  // Runs a shell command; returns the exit status; stderr captured into err_.
  int sh(const std::string& cmd) {
    const int status = std::system((cmd + " 2>" + path("err.txt")).c_str());
    std::ifstream e(path("err.txt"));
    std::stringstream ss;
    ss << e.rdbuf();
    err_ = ss.str();
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }

  fs::path dir_;
  std::string err_;
};

// Every value, bit for bit (NaN included).
void expect_same_bits(const Array& a, const Array& b, const std::string& what) {
  ASSERT_EQ(a.shape, b.shape) << what;
  ASSERT_EQ(a.data.size(), b.data.size()) << what;
  EXPECT_EQ(std::memcmp(a.data.data(), b.data.data(), a.data.size() * sizeof(double)), 0) << what;
}

TEST_F(StructureTools, ClusterGroupHoldsTheHandKnownNumbers) {
  ClusterConfig c;
  c.input = path("in.h5");
  c.output = path("cluster.h5");
  c.histogram = true;
  c.particle_clusters = true;
  ASSERT_EQ(run_cluster(c, CommonFlags{false, true}, {"gg-cluster"}), 0);
  H5Input in(c.output);
  EXPECT_EQ(in.read("/cluster/time").data, (std::vector<double>{0.0, 1.5, 3.0}));
  const auto count = in.read_int("/cluster/count");
  const auto largest = in.read_int("/cluster/largest");
  const auto mean = in.read("/cluster/mean_mass").data;
  const std::int64_t N = static_cast<std::int64_t>(three_frames().n_particles);
  // Frame 0: 4 stripes of 4 x 64 = 256 particles, plus the pile cell holding the rest.
  const std::int64_t pile0 = N - 4 * 256;
  EXPECT_EQ(count[0], 5);
  EXPECT_EQ(largest[0], std::max<std::int64_t>(256, pile0));
  EXPECT_DOUBLE_EQ(mean[0], static_cast<double>(N) / 5);
  // Frame 1: the patch across the corner (72) and the pile.
  EXPECT_EQ(count[1], 2);
  EXPECT_DOUBLE_EQ(mean[1], static_cast<double>(N) / 2);
  // The giant-cluster numbers: frame 0's largest is the pile (no wrapping), the rest its 4 stripes,
  // and every particle is in a cluster.
  ASSERT_GT(pile0, 256);
  EXPECT_EQ(in.read("/cluster/largest_share").data[0], static_cast<double>(pile0) / static_cast<double>(N));
  EXPECT_EQ(in.read("/cluster/largest_share_of_clustered").data[0], static_cast<double>(pile0) / static_cast<double>(N));
  EXPECT_EQ(in.read("/cluster/rest_mean_mass").data[0], 256.0);
  EXPECT_EQ(in.read("/cluster/rest_mean_mass").data[1], 72.0);
  const Array wraps = in.read("/cluster/wraps");
  EXPECT_EQ(wraps.shape, (std::vector<std::size_t>{3, 2}));
  EXPECT_EQ(wraps.data[0] + wraps.data[1], 0.0);
  const Array particle = in.read("/cluster/particle_cluster");
  ASSERT_EQ(particle.shape, (std::vector<std::size_t>{3, static_cast<std::size_t>(N)}));
  EXPECT_EQ(particle.data[static_cast<std::size_t>(N) - 1], 0.0);  // the pile is frame 0's largest
  EXPECT_EQ(particle.data[0], 1.0);                                  // cell (0, 0): the first stripe
  EXPECT_EQ(in.attr_double("/cluster", "connectivity"), 4.0);
  EXPECT_EQ(in.attr_double("/cluster", "rho_c"), 0.5);
  EXPECT_EQ(in.read("/cluster/mass_histogram").shape, (std::vector<std::size_t>{3, in.read("/cluster/mass_bin_edges").data.size() - 1}));
  EXPECT_TRUE(in.exists("/parameters/provenance"));
  EXPECT_TRUE(in.exists("/parameters/provenance/inputs/0"));
}

TEST_F(StructureTools, CorrelationAndDomainGroupsHaveTheDesignShapes) {
  CorrelateConfig c;
  c.input = path("in.h5");
  c.output = path("corr.h5");
  c.frames = {0};
  ASSERT_EQ(run_correlate(c, CommonFlags{false, true}, {"gg-correlate"}), 0);
  H5Input corr(c.output);
  EXPECT_EQ(corr.read("/correlation/r").data.size(), 33u);  // shells 0..32
  EXPECT_EQ(corr.read("/correlation/C").shape, (std::vector<std::size_t>{1, 33}));
  EXPECT_EQ(corr.read("/correlation/length").data.size(), 1u);
  EXPECT_EQ(corr.read("/correlation/S").shape[0], 1u);
  EXPECT_EQ(corr.read("/correlation/k1").data.size(), 1u);
  // g(r) and S_rho cost a pair search and a second FFT per frame: written only when asked for.
  EXPECT_FALSE(corr.exists("/correlation/g"));
  EXPECT_FALSE(corr.exists("/correlation/g_contact"));
  EXPECT_FALSE(corr.exists("/correlation/S_rho"));
  c.output = path("corr-pairs.h5");
  c.pairs = c.density = true;
  ASSERT_EQ(run_correlate(c, CommonFlags{false, true}, {"gg-correlate", "--pairs", "--density"}), 0);
  H5Input pairs(c.output);
  const std::size_t bins = pairs.read("/correlation/g_r").data.size();
  EXPECT_EQ(bins, 250u);  // g_max 5 / g_bin 0.02
  EXPECT_EQ(pairs.read("/correlation/g").shape, (std::vector<std::size_t>{1, bins}));
  EXPECT_EQ(pairs.read("/correlation/g_contact").data.size(), 1u);
  EXPECT_EQ(pairs.read("/correlation/S_rho").shape, pairs.read("/correlation/S").shape);
  EXPECT_EQ(pairs.read("/correlation/C").data, corr.read("/correlation/C").data);

  DomainsConfig d;
  d.input = path("in.h5");
  d.output = path("dom.h5");
  d.frames = {0};
  d.phase = "rich";
  ASSERT_EQ(run_domains(d, CommonFlags{false, true}, {"gg-domains"}), 0);
  H5Input dom(d.output);
  EXPECT_EQ(dom.read("/domains/histogram").shape, (std::vector<std::size_t>{1, 63}));
  EXPECT_EQ(dom.read("/domains/bin_edges").data.size(), 64u);
  // Rich stripes are 4 wide on 64 columns; the pile adds runs of 3 rich cells on 3 columns and 3 rows:
  // (256 * 4 + 6 * 3) / 262.
  const double l = dom.read("/domains/length").data[0];
  EXPECT_DOUBLE_EQ(l, (256.0 * 4 + 6 * 3) / 262);
  EXPECT_EQ(dom.attr_string("/domains", "phase"), std::string("rich"));
}

TEST_F(StructureTools, FilesAndPipesGiveBitIdenticalResults) {
  const std::vector<std::pair<std::string, std::string>> tools = {
      {GG_CLUSTER_EXE, "/cluster"}, {GG_CORRELATE_EXE, "/correlation"}, {GG_DOMAINS_EXE, "/domains"}};
  for (const auto& [exe, group] : tools) {
    const std::string extra = group == "/cluster" ? " --histogram --connectivity 8" : "";
    ASSERT_EQ(sh(exe + " " + path("in.h5") + " -o " + path("file.h5") + extra + " > " + path("stdout.txt")), 0) << err_;
    EXPECT_EQ(fs::file_size(path("stdout.txt")), 0u) << exe << ": stdout must stay empty when writing a file";
    EXPECT_EQ(err_, "") << exe;
    ASSERT_EQ(sh("cat " + path("in.h5") + " | " + exe + " - -o -" + extra + " > " + path("pipe.h5")), 0) << err_;
    H5Input a(path("file.h5")), b(path("pipe.h5"));
    const auto members = a.members(group);
    EXPECT_GE(members.size(), 4u);
    EXPECT_EQ(members, b.members(group));
    for (const auto& m : members) expect_same_bits(a.read(group + "/" + m), b.read(group + "/" + m), exe + " " + m);
  }
}

TEST_F(StructureTools, FramesSelectsSnapshotsCountingFromTheEnd) {
  ASSERT_EQ(sh(std::string(GG_CLUSTER_EXE) + " " + path("in.h5") + " -o " + path("last.h5") + " --frames=-1,0"), 0)
      << err_;
  H5Input in(path("last.h5"));
  EXPECT_EQ(in.read("/cluster/time").data, (std::vector<double>{3.0, 0.0}));
  EXPECT_EQ(sh(std::string(GG_CLUSTER_EXE) + " " + path("in.h5") + " -o " + path("bad.h5") + " --frames 3"), 2);
  EXPECT_FALSE(fs::exists(path("bad.h5")));
}

TEST_F(StructureTools, BadInputGivesOneLineTheRightStatusAndNoOutput) {
  const std::string cl = std::string(GG_CLUSTER_EXE) + " ";
  struct Case {
    std::string cmd;
    int status;
    std::string says;
  };
  const std::vector<Case> cases = {
      {cl + path("in.h5") + " -o " + path("o.h5") + " --grid 65", 2, "larger than the box"},
      {cl + path("in.h5") + " -o " + path("o.h5") + " --rho-c 0", 2, "--rho-c"},
      {cl + path("in.h5") + " -o " + path("o.h5") + " --coarse -1", 2, "--coarse"},
      {cl + path("in.h5") + " -o " + path("o.h5") + " --connectivity 6", 2, "--connectivity"},
      {std::string(GG_CORRELATE_EXE) + " " + path("in.h5") + " -o " + path("o.h5") + " --a 1.5", 2, "--a"},
      {std::string(GG_DOMAINS_EXE) + " " + path("in.h5") + " -o " + path("o.h5") + " --phase dense", 2, "--phase"},
      {cl + path("missing.h5") + " -o " + path("o.h5"), 1, "missing.h5"},
      {cl + path("text.txt") + " -o " + path("o.h5"), 1, "text.txt"},  // not HDF5
      {cl + path("in3d.h5") + " -o " + path("o.h5") + " --connectivity 8", 2, "give 6 (faces) or 26"},
  };
  {  // a 3D H5MD file, written by hand (box/edges a fixed dataset, as other writers give it)
    H5Output out(path("in3d.h5"));
    out.attr("/h5md", "version", std::vector<std::int64_t>{1, 1});
    out.attr("/particles/all/box", "dimension", std::int64_t{3});
    out.write("/particles/all/box/edges", std::vector<double>{8, 8, 8});
    out.write("/particles/all/position/step", std::vector<std::int64_t>{0});
    out.write("/particles/all/position/time", std::vector<double>{0});
    out.write("/particles/all/position/value", Array{{1, 2, 3}, {1, 1, 1, 2, 2, 2}});
    out.commit();
  }
  std::ofstream(path("text.txt")) << "not an HDF5 file\n";
  for (const auto& c : cases) {
    EXPECT_EQ(sh(c.cmd), c.status) << c.cmd << "\n" << err_;
    EXPECT_FALSE(fs::exists(path("o.h5"))) << c.cmd;
    EXPECT_EQ(std::count(err_.begin(), err_.end(), '\n'), 1) << c.cmd << "\n" << err_;
    EXPECT_NE(err_.find(c.says), std::string::npos) << c.cmd << "\n" << err_;
  }
}

TEST_F(StructureTools, OneDimensionalInput) {
  Snapshots s;
  s.dim = 1;
  s.edges = {32.0};
  s.n_particles = 8;
  s.time = {0.0};
  s.step = {0};
  s.position = {0.5, 1.5, 2.5, 3.5, 10.5, 11.5, 12.5, 31.5};  // runs of rich cells: {31, 0..3}, {10..12}
  {
    H5Output out(path("in1d.h5"));
    write_snapshots(out, s, "test");
    out.commit();
  }
  ClusterConfig c;
  c.input = path("in1d.h5");
  c.output = path("c1d.h5");
  c.grain.coarse = 0;
  ASSERT_EQ(run_cluster(c, CommonFlags{false, true}, {"gg-cluster"}), 0);
  H5Input in(c.output);
  EXPECT_EQ(in.read_int("/cluster/count"), (std::vector<std::int64_t>{2}));
  EXPECT_EQ(in.read_int("/cluster/largest"), (std::vector<std::int64_t>{5}));
  EXPECT_EQ(in.read("/cluster/mean_mass").data, (std::vector<double>{4.0}));

  DomainsConfig d;
  d.input = c.input;
  d.output = path("d1d.h5");
  d.grain.coarse = 0;
  ASSERT_EQ(run_domains(d, CommonFlags{false, true}, {"gg-domains"}), 0);
  // Runs: rich 5, poor 6, rich 3, poor 18: mean 8.
  EXPECT_EQ(H5Input(d.output).read("/domains/length").data, (std::vector<double>{8.0}));
}

}  // namespace
}  // namespace gg
