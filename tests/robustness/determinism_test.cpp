// Determinism (docs/DESIGN.md "Conventions of every tool"): the same scene and seed give
// bit-identical data on repeated runs, a different seed gives different data, and the analysis
// tools run twice on the same input write identical results. "Data" is every dataset and
// attribute except /parameters/provenance (which holds the wall-clock time and the command line).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "h5_contents.hpp"
#include "robustness_support.hpp"

namespace gg::robust {
namespace {

const std::vector<std::string> kNotData{"/parameters/provenance"};

struct Scene {
  std::string name;
  std::string ini;                // scene file contents ("" = none)
  std::vector<std::string> args;  // flags after --scene
};

std::ostream& operator<<(std::ostream& os, const Scene& s) { return os << s.name; }

const std::vector<Scene> kScenes{
    // 2D with snapshots, velocities and pressure, from a scene file (flags add to it).
    {"Disks2dSnapshotsVelocitiesPressure",
     "dim = 2\nN = 300\nrho = 0.3\ne = 0.8\nseed = 7\nt-max = 5\nsnapshots = 0,1,2.5,5\nvelocities = true\n"
     "pressure = true\n",
     {}},
    // 1D rods with the velocity cutoff delta (Fig. 7 regime, small).
    {"Rods1dDelta", "",
     {"--dim", "1", "--N", "400", "--rho", "0.3", "--e", "0.5", "--delta", "0.005", "--seed", "11", "--t-max", "40",
      "--snapshots-per-decade", "2", "--velocities"}},
    // The TC model, strongly inelastic.
    {"Disks2dTc", "",
     {"--dim", "2", "--N", "300", "--rho", "0.3", "--e", "0.3", "--tc", "0.001", "--seed", "5", "--t-max", "20",
      "--snapshots", "0,20", "--pressure"}},
    // Lattice start, elastic equilibration, a collision budget and single-precision snapshots.
    {"Disks2dLatticeEquilibrateFloat", "",
     {"--dim", "2", "--N", "256", "--L", "32", "--init", "lattice", "--equilibrate", "5", "--e", "0.9", "--seed", "3",
      "--max-collisions", "20000", "--snapshots-per-decade", "3", "--float-snapshots", "--velocities"}},
};

class Determinism : public ::testing::TestWithParam<Scene> {
 protected:
  void SetUp() override {
    fs::create_directory(dir_.path() / "capture");
    if (!GetParam().ini.empty()) write_bytes(dir_.file("scene.ini"), GetParam().ini);
  }
  // gg-sim on the scene, with `extra` flags, to `out` ("-": stdout, kept as `out_name`).
  // `seed` replaces the scene's seed when given.
  void sim(const std::string& out, const std::string& seed = "", const std::string& stdout_to = "") {
    std::vector<std::string> args;
    if (!GetParam().ini.empty()) args = {"--scene", "scene.ini"};
    for (std::size_t i = 0; i < GetParam().args.size(); ++i) {
      if (!seed.empty() && GetParam().args[i] == "--seed") {
        ++i;
        continue;
      }
      args.push_back(GetParam().args[i]);
    }
    if (!seed.empty()) args.insert(args.end(), {"--seed", seed});
    args.insert(args.end(), {"--quiet", "-o", out});
    const RunResult r = run_tool(GG_SIM_EXE, args, dir_.path(), dir_.path() / "capture");
    ASSERT_EQ(r.status, 0) << r.describe();
    if (!stdout_to.empty()) write_bytes(dir_.file(stdout_to), r.out);
  }
  Contents data(const std::string& name) const { return h5_contents(dir_.file(name), kNotData); }
  TempDir dir_;
};

TEST_P(Determinism, SameSeedSameData) {
  sim("a.h5");
  sim("b.h5");
  sim("-", "", "c.h5");  // through stdout: the same data as through a file
  const Contents a = data("a.h5");
  ASSERT_GT(a.size(), 20u);
  ASSERT_TRUE(a.count("/particles/all/position/value"));
  EXPECT_EQ(differences(a, data("b.h5")), std::vector<std::string>{});
  EXPECT_EQ(differences(a, data("c.h5")), std::vector<std::string>{});
}

TEST_P(Determinism, OtherSeedOtherData) {
  sim("a.h5");
  sim("d.h5", "12345");
  const Contents a = data("a.h5"), d = data("d.h5");
  for (const char* ds : {"/particles/all/position/value", "/observables/kinetic_energy/value"})
    EXPECT_NE(a.at(ds), d.at(ds)) << ds << " does not depend on the seed";
}

INSTANTIATE_TEST_SUITE_P(Scenes, Determinism, ::testing::ValuesIn(kScenes),
                         [](const ::testing::TestParamInfo<Scene>& i) { return i.param.name; });

// The analysis tools, each run twice on the same input (and gg-fit on the same tables).
TEST(DeterminismAnalysis, ToolsGiveIdenticalOutputs) {
  TempDir dir;
  const fs::path d = dir.path(), cap = d / "capture";
  fs::create_directory(cap);
  auto run = [&](const std::string& exe, const std::vector<std::string>& args) {
    const RunResult r = run_tool(exe, args, d, cap);
    EXPECT_EQ(r.status, 0) << exe << ": " << r.describe();
    return r;
  };
  for (const char* seed : {"1", "2"})
    run(GG_SIM_EXE, {"--dim", "2", "--N", "400", "--rho", "0.35", "--e", "0.5", "--seed", seed, "--t-max", "30",
                     "--snapshots", "1,10,30", "--quiet", "-o", std::string("sim") + seed + ".h5"});
  struct Tool {
    std::string exe;
    std::vector<std::string> args;
  };
  const std::vector<Tool> tools{
      {GG_CLUSTER_EXE, {"sim1.h5", "--histogram", "--connectivity", "8"}},
      {GG_CORRELATE_EXE, {"sim1.h5", "--grid", "2"}},
      {GG_DOMAINS_EXE, {"sim1.h5", "--coarse", "2"}},
      {GG_FIT_EXE, {"average", "sim1.h5:/observables/kinetic_energy/value", "sim2.h5:/observables/kinetic_energy/value"}},
      {GG_FIT_EXE, {"power-law", "sim1.h5:/observables/kinetic_energy/value", "--window", "1", "30"}},
      {GG_FIT_EXE, {"haff", "sim1.h5:/observables/kinetic_energy/value"}},
      {GG_FIT_EXE, {"local-exponent", "sim1.h5:/observables/collisions_per_particle/value", "--window", "0.5"}},
  };
  int k = 0;
  for (const auto& t : tools) {
    std::vector<std::string> first = t.args, second = t.args;
    const std::string a = "out" + std::to_string(k) + "a.h5", b = "out" + std::to_string(k++) + "b.h5";
    first.insert(first.end(), {"-o", a});
    second.insert(second.end(), {"-o", b});
    const RunResult ra = run(t.exe, first), rb = run(t.exe, second);
    if (ra.status || rb.status) continue;
    EXPECT_EQ(ra.err, rb.err) << "the printed line differs";
    const Contents ca = h5_contents((d / a).string(), kNotData);
    EXPECT_GT(ca.size(), 2u) << t.exe << " " << t.args[0];
    EXPECT_EQ(differences(ca, h5_contents((d / b).string(), kNotData)), std::vector<std::string>{})
        << t.exe << " " << t.args[0];
  }
  // Tables on stdout, byte for byte.
  const RunResult t1 = run(GG_FIT_EXE, {"table", "out0a.h5"}), t2 = run(GG_FIT_EXE, {"table", "out0a.h5"});
  EXPECT_FALSE(t1.out.empty());
  EXPECT_EQ(t1.out, t2.out);
}

}  // namespace
}  // namespace gg::robust
