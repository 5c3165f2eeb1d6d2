// End-to-end tests of the gg-fit executable: small HDF5 files in, numbers and tables out,
// exit codes and messages for bad input. GG_FIT_EXE is the built executable (tests/analyze/fit/CMakeLists.txt).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

#include "fit/haff.hpp"
#include "gg/h5file.hpp"

namespace fs = std::filesystem;

namespace {

struct Result {
  int status = -1;
  std::string out, err;
};

class GgFit : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("gg_fit_cli_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  // Runs a shell command line in the test directory ("gg-fit" replaced by the built executable).
  Result run(const std::string& cmdline) const {
    std::string cmd;
    for (std::size_t i = 0; i < cmdline.size();) {
      if (cmdline.compare(i, 6, "gg-fit") == 0) {
        cmd += std::string("'") + GG_FIT_EXE + "'";
        i += 6;
      } else {
        cmd += cmdline[i++];
      }
    }
    const std::string out = path("stdout.txt"), err = path("stderr.txt");
    const std::string full = "cd '" + dir_.string() + "' && { " + cmd + " ; } > '" + out + "' 2> '" + err + "'";
    Result r;
    const int raw = std::system(full.c_str());
    r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    r.out = slurp(out);
    r.err = slurp(err);
    return r;
  }

  static std::string slurp(const std::string& p) {
    std::ifstream f(p);
    std::stringstream s;
    s << f.rdbuf();
    return s.str();
  }

  // A run: m(t) = 2 t^0.6 (1 + 2% noise), 41 samples over t = 1 .. 1e4, plus Haff energies.
  void write_run(const std::string& name, int seed, std::size_t samples = 41) const {
    gg::H5Output out(path(name));
    std::vector<double> t, m;
    unsigned long x = 12345 + 7919 * static_cast<unsigned long>(seed);
    auto uniform = [&x] {  // small LCG: deterministic everywhere
      x = x * 6364136223846793005ULL + 1442695040888963407ULL;
      return static_cast<double>(x >> 11) / 9007199254740992.0;
    };
    for (std::size_t i = 0; i < samples; ++i) {
      t.push_back(std::pow(10.0, 4.0 * static_cast<double>(i) / 40));
      m.push_back(2 * std::pow(t.back(), 0.6) * (1 + 0.02 * (2 * uniform() - 1) * std::sqrt(3.0)));
    }
    out.write("/cluster/time", t);
    out.write("/cluster/mean_mass", m);
    const double t0 = gg::fit::enskog_haff(2, 0.37, 0.9, 1.0).t0;
    std::vector<double> te, E;
    for (int i = 0; i <= 100; ++i) {
      te.push_back(0.05 * i);
      E.push_back(1.0 / std::pow(1 + te.back() / t0, 2));
    }
    out.write("/observables/kinetic_energy/time", te);
    out.write("/observables/kinetic_energy/value", E);
    out.attr("/parameters", "rho", 0.37);
    out.attr("/parameters", "e", 0.9);
    out.attr("/parameters", "T0", 1.0);
    out.attr("/parameters", "dim", std::int64_t{2});
    out.commit();
  }

  // Non-comment lines of a table, split at tabs.
  static std::vector<std::vector<double>> rows(const std::string& text) {
    std::vector<std::vector<double>> r;
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) {
      if (line.empty() || line[0] == '#') continue;
      std::vector<double> v;
      std::istringstream cells(line);
      std::string cell;
      while (std::getline(cells, cell, '\t')) v.push_back(std::stod(cell));
      r.push_back(v);
    }
    return r;
  }

  fs::path dir_;
};

}  // namespace

TEST_F(GgFit, AveragePowerLawAndTable) {
  for (int k = 0; k < 6; ++k) write_run("run" + std::to_string(k) + ".h5", k);
  Result a = run("gg-fit average run0.h5 run1.h5 run2.h5 run3.h5 run4.h5 run5.h5 --dataset /cluster/mean_mass -o avg.h5");
  ASSERT_EQ(a.status, 0) << a.err;
  EXPECT_TRUE(a.out.empty()) << "stdout carries only data";
  {
    gg::H5Input avg(path("avg.h5"));
    EXPECT_EQ(avg.read("/average/mean").data.size(), 41u);
    EXPECT_EQ(avg.read("/average/samples").shape, (std::vector<std::size_t>{6, 41}));
    EXPECT_TRUE(avg.exists("/parameters/provenance/inputs/5"));
    EXPECT_EQ(avg.attr_double("/parameters", "rho").value_or(0), 0.37);
  }

  Result p = run("gg-fit power-law avg.h5:/average/mean --window 10 1000 -o fit.h5");
  ASSERT_EQ(p.status, 0) << p.err;
  EXPECT_NE(p.err.find("z = "), std::string::npos) << p.err;
  EXPECT_EQ(std::count(p.err.begin(), p.err.end(), '\n'), 1) << "one readable line: " << p.err;
  gg::H5Input fit(path("fit.h5"));
  const double z = fit.read("/fit/exponent").data.at(0), se = fit.read("/fit/exponent_stderr").data.at(0);
  EXPECT_GT(se, 0);
  EXPECT_LT(se, 0.02);
  EXPECT_NEAR(z, 0.6, 4 * se);
  EXPECT_NEAR(fit.read("/fit/amplitude").data.at(0), 2.0, 0.1);
  EXPECT_EQ(fit.read("/fit/window").data, (std::vector<double>{10, 1000}));
  EXPECT_TRUE(fit.exists("/fit/chi2_dof"));
  EXPECT_TRUE(fit.exists("/fit/amplitude_stderr"));
  EXPECT_EQ(fit.attr_string("/fit", "input").value_or(""), "avg.h5:/average/mean");
  EXPECT_NE(fit.attr_string("/fit", "method").value_or("").find("power-law"), std::string::npos);
  EXPECT_NE(fit.attr_string("/fit", "errors").value_or("").find("jackknife over 6 runs"), std::string::npos);
  EXPECT_TRUE(fit.exists("/parameters/provenance/inputs/0"));

  Result t = run("gg-fit table fit.h5:/fit/exponent fit.h5:/fit/exponent_stderr");
  ASSERT_EQ(t.status, 0) << t.err;
  auto r = rows(t.out);
  ASSERT_EQ(r.size(), 1u) << t.out;
  ASSERT_EQ(r[0].size(), 2u);
  EXPECT_NEAR(r[0][0], z, 1e-9 * std::abs(z));
  EXPECT_NEAR(r[0][1], se, 1e-9 * se);

  Result series = run("gg-fit table run0.h5:/cluster/mean_mass avg.h5:/average/mean avg.h5:/average/stderr");
  ASSERT_EQ(series.status, 0) << series.err;
  auto s = rows(series.out);
  ASSERT_EQ(s.size(), 41u);
  ASSERT_EQ(s[0].size(), 4u);  // time first
  EXPECT_DOUBLE_EQ(s[0][0], 1.0);
  EXPECT_DOUBLE_EQ(s[40][0], 1e4);
  EXPECT_EQ(series.out.rfind("# time\t", 0), 0u) << series.out;
}

TEST_F(GgFit, ThroughPipes) {
  for (int k = 0; k < 3; ++k) write_run("run" + std::to_string(k) + ".h5", k);
  Result p = run("gg-fit average run0.h5 run1.h5 run2.h5 --dataset /cluster/mean_mass -o - | "
                 "gg-fit power-law -:/average/mean --window 10 1000 -o - | gg-fit table -");
  ASSERT_EQ(p.status, 0) << p.err;
  auto r = rows(p.out);
  ASSERT_EQ(r.size(), 1u) << p.out;
  ASSERT_EQ(r[0].size(), 5u) << p.out;  // amplitude, amplitude_stderr, chi2_dof, exponent, exponent_stderr
  EXPECT_NEAR(r[0][3], 0.6, 0.02);
  Result whole = run("gg-fit table run0.h5");
  ASSERT_EQ(whole.status, 0) << whole.err;
  EXPECT_NE(whole.out.find("# /cluster"), std::string::npos);
  EXPECT_NE(whole.out.find("# /observables/kinetic_energy"), std::string::npos);
}

// A [T][R] dataset prints "time x value" rows, x being what its group pairs with the columns: r
// (gg-correlate's C), the bin centres of bin_edges (gg-domains' histogram), or else the column index.
// --help says so (it once said "time index value" for all three).
TEST_F(GgFit, TableOfA2DDatasetPrintsItsAxisAndHelpSaysWhich) {
  {
    gg::H5Output out(path("two.h5"));
    out.write("/correlation/time", std::vector<double>{1, 2});
    out.write("/correlation/r", std::vector<double>{0, 1.5, 3});
    out.write("/correlation/C", gg::Array{{2, 3}, {1, 0.5, 0.1, 1, 0.7, 0.2}});
    out.write("/domains/time", std::vector<double>{1, 2});
    out.write("/domains/bin_edges", std::vector<double>{0, 2, 4});
    out.write("/domains/histogram", gg::Array{{2, 2}, {0.3, 0.2, 0.25, 0.25}});
    out.write("/other/time", std::vector<double>{1, 2});
    out.write("/other/grid", gg::Array{{2, 2}, {5, 6, 7, 8}});
    out.commit();
  }
  Result c = run("gg-fit table two.h5:/correlation/C");
  ASSERT_EQ(c.status, 0) << c.err;
  EXPECT_EQ(c.out.rfind("# time\tr\t", 0), 0u) << c.out;
  auto rc = rows(c.out);
  ASSERT_EQ(rc.size(), 6u) << c.out;
  EXPECT_EQ(rc[1], (std::vector<double>{1, 1.5, 0.5}));
  EXPECT_EQ(rc[5], (std::vector<double>{2, 3, 0.2}));
  Result d = run("gg-fit table two.h5:/domains/histogram");
  ASSERT_EQ(d.status, 0) << d.err;
  EXPECT_EQ(d.out.rfind("# time\tbin_centre\t", 0), 0u) << d.out;
  EXPECT_EQ(rows(d.out)[1], (std::vector<double>{1, 3, 0.2}));
  Result o = run("gg-fit table two.h5:/other/grid");
  ASSERT_EQ(o.status, 0) << o.err;
  EXPECT_EQ(o.out.rfind("# time\tindex\t", 0), 0u) << o.out;
  EXPECT_EQ(rows(o.out)[3], (std::vector<double>{2, 1, 8}));

  Result h = run("gg-fit table --help");
  ASSERT_EQ(h.status, 0) << h.err;
  EXPECT_EQ(h.out.find("'time index value'"), std::string::npos) << h.out;
  for (const char* says : {"'time x value'", "x = r", "bin_edges", "column index"})
    EXPECT_NE(h.out.find(says), std::string::npos) << says << " missing from:\n" << h.out;
}

TEST_F(GgFit, HaffReadsParametersAndGivesBackT0) {
  write_run("sim.h5", 0);
  Result h = run("gg-fit haff sim.h5:/observables/kinetic_energy/value -o haff.h5");
  ASSERT_EQ(h.status, 0) << h.err;
  gg::H5Input f(path("haff.h5"));
  EXPECT_NEAR(f.read("/fit/t0_ratio").data.at(0), 1.0, 1e-6);
  EXPECT_NEAR(f.read("/fit/t0_enskog").data.at(0), 9.2541, 1e-3);
  EXPECT_NE(f.attr_string("/fit", "contact_value").value_or("").find("Henderson"), std::string::npos);
}

TEST_F(GgFit, BadInputGivesOneClearLineAndNoOutput) {
  write_run("a.h5", 1);
  write_run("b.h5", 2, 40);  // one sample shorter
  Result w = run("gg-fit power-law a.h5:/cluster/mean_mass --window 100 10 -o out.h5");
  EXPECT_EQ(w.status, 2);
  EXPECT_NE(w.err.find("empty window"), std::string::npos) << w.err;
  EXPECT_EQ(std::count(w.err.begin(), w.err.end(), '\n'), 1) << w.err;
  // A window that reaches t = 0 is the caller's choice, so a usage error (exit 2), as an empty one is.
  Result zero = run("gg-fit power-law a.h5:/observables/kinetic_energy/value --window -1 3 -o out.h5");
  EXPECT_EQ(zero.status, 2);
  EXPECT_NE(zero.err.find("start the window after t = 0"), std::string::npos) << zero.err;
  Result few = run("gg-fit power-law a.h5:/cluster/mean_mass --window 10 13 -o out.h5");
  EXPECT_EQ(few.status, 1);
  EXPECT_NE(few.err.find("need at least 3"), std::string::npos) << few.err;
  Result len = run("gg-fit average a.h5:/cluster/mean_mass b.h5:/cluster/mean_mass -o out.h5");
  EXPECT_EQ(len.status, 1);
  EXPECT_NE(len.err.find("--interpolate"), std::string::npos) << len.err;
  EXPECT_FALSE(fs::exists(path("out.h5")));
  Result ok = run("gg-fit average a.h5:/cluster/mean_mass b.h5:/cluster/mean_mass --interpolate -o out.h5");
  EXPECT_EQ(ok.status, 0) << ok.err;
  Result missing = run("gg-fit power-law a.h5:/cluster/nothing --window 10 100");
  EXPECT_EQ(missing.status, 1);
  EXPECT_NE(missing.err.find("/cluster/nothing"), std::string::npos) << missing.err;
  // Leftover temporaries would look like output.
  for (const auto& e : fs::directory_iterator(dir_)) EXPECT_EQ(e.path().string().find(".tmp"), std::string::npos) << e.path();
}

// The finite-size extrapolation end to end: ratios with errors at three box sizes, the limit of the
// line through them in 1/L, and the verdict written and printed.
TEST_F(GgFit, ExtrapolateFitsInInverseSizeAndJudgesTheRatio) {
  const std::vector<double> L{256, 512, 1024};
  for (std::size_t i = 0; i < L.size(); ++i) {
    gg::H5Output out(path("c" + std::to_string(i) + ".h5"));
    // [0] the reference (1 +- 0), [1] a ratio 0.6 + 40/L (exactly linear), [2] 1.0 everywhere.
    out.write("/fit/amplitude_ratio", std::vector<double>{1.0, 0.6 + 40 / L[i], 1.0});
    out.write("/fit/amplitude_ratio_stderr", std::vector<double>{0.0, 0.01, 0.01});
    out.commit();
  }
  Result r = run("gg-fit extrapolate c0.h5:/fit/amplitude_ratio c1.h5:/fit/amplitude_ratio "
                 "c2.h5:/fit/amplitude_ratio -o x.h5 --L 256 512 1024");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("[0] reference"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("rejected at the largest L"), std::string::npos) << r.err;
  Result limit = run("gg-fit table --no-header x.h5:/extrapolate/limit x.h5:/extrapolate/verdict_largest");
  ASSERT_EQ(limit.status, 0) << limit.err;
  auto rows_ = rows(limit.out);
  ASSERT_EQ(rows_.size(), 3u);
  // No time axis: the columns are the two datasets, one row per component.
  ASSERT_EQ(rows_[1].size(), 2u);
  EXPECT_NEAR(rows_[1][0], 0.6, 1e-9);  // the limit of 0.6 + 40/L
  EXPECT_EQ(rows_[1][1], -1);            // 0.6390625 +- 0.01 at L = 1024: rejected
  EXPECT_NEAR(rows_[2][0], 1.0, 1e-9);
  EXPECT_EQ(rows_[2][1], 1);             // 1 +- 0.01: supported within 10%
  // With the degrees of freedom of a jackknife over 4 runs (3): 1 +- 0.04 has the interval 1 +- 0.13
  // (Student's t, 3.31) and is undecided, where the normal's 1 +- 0.08 would be supported.
  for (std::size_t i = 0; i < L.size(); ++i) {
    gg::H5Output out(path("d" + std::to_string(i) + ".h5"));
    out.write("/fit/amplitude_ratio", std::vector<double>{1.0, 1.0});
    out.write("/fit/amplitude_ratio_stderr", std::vector<double>{0.0, 0.04});
    if (i == 2) out.write("/fit/amplitude_ratio_dof", std::vector<double>{0, 3});
    out.commit();
  }
  Result dof = run("gg-fit extrapolate d0.h5:/fit/amplitude_ratio d1.h5:/fit/amplitude_ratio d2.h5:/fit/amplitude_ratio "
                   "-o z.h5 --L 256 512 1024");
  ASSERT_EQ(dof.status, 0) << dof.err;
  EXPECT_NE(dof.err.find("undecided at the largest L"), std::string::npos) << dof.err;
  // Bad input: one --L per input, increasing; one line each, no output.
  Result count = run("gg-fit extrapolate c0.h5:/fit/amplitude_ratio c1.h5:/fit/amplitude_ratio -o y.h5 --L 256");
  EXPECT_EQ(count.status, 2);
  EXPECT_NE(count.err.find("one box size per input"), std::string::npos) << count.err;
  Result order = run("gg-fit extrapolate c0.h5:/fit/amplitude_ratio c1.h5:/fit/amplitude_ratio -o y.h5 --L 512 256");
  EXPECT_EQ(order.status, 2);
  EXPECT_EQ(std::count(order.err.begin(), order.err.end(), '\n'), 1) << order.err;
  Result noerr = run("gg-fit extrapolate c0.h5:/fit/amplitude_ratio_stderr c1.h5:/fit/amplitude_ratio_stderr -o y.h5 --L 256 512");
  EXPECT_EQ(noerr.status, 1);
  EXPECT_NE(noerr.err.find("no error bars"), std::string::npos) << noerr.err;
  EXPECT_FALSE(fs::exists(path("y.h5")));
}

// The late-growth subcommands end to end: runs of m = 2 t^0.6 and runs of the same shifted in time by
// 5 (m = 2 (t/5)^0.6): shift gives c = 5 and a constant lag, ratio at equal times gives 5^-0.6,
// late-exponent gives 0.6 settled; a factor is never returned without its runs or a common range.
TEST_F(GgFit, ShiftRatioAndLateExponentOfAShiftedEnsemble) {
  for (int k = 0; k < 4; ++k) write_run("a" + std::to_string(k) + ".h5", k);
  ASSERT_EQ(run("gg-fit average --dataset /cluster/mean_mass a0.h5 a1.h5 a2.h5 a3.h5 -o A.h5").status, 0);
  ASSERT_EQ(run("gg-fit average --dataset /cluster/mean_mass a0.h5 a1.h5 -o A2.h5").status, 0);
  for (int k = 0; k < 4; ++k) {  // the same runs, m multiplied by 5^-0.6: m(t) = 2 (t/5)^0.6
    gg::H5Output out(path("b" + std::to_string(k) + ".h5"));
    gg::H5Input in(path("a" + std::to_string(k) + ".h5"));
    std::vector<double> m = in.read("/cluster/mean_mass").data;
    for (double& y : m) y *= std::pow(5.0, -0.6);
    out.write("/cluster/time", in.read("/cluster/time").data);
    out.write("/cluster/mean_mass", m);
    out.commit();
  }
  ASSERT_EQ(run("gg-fit average --dataset /cluster/mean_mass b0.h5 b1.h5 b2.h5 b3.h5 -o B.h5").status, 0);
  Result s = run("gg-fit shift A.h5:/average/mean B.h5:/average/mean --window 10 1000 --window 50 10000 -o s.h5");
  ASSERT_EQ(s.status, 0) << s.err;
  Result f = run("gg-fit table s.h5:/shift/factor s.h5:/shift/factor_stderr s.h5:/shift/lag/constant");
  const auto r = rows(f.out);
  ASSERT_EQ(r.size(), 2u) << f.out;
  EXPECT_NEAR(r[1][0], 5.0, 0.05) << s.err;
  EXPECT_LT(r[1][1], 0.5);
  EXPECT_EQ(r[1][2], 1.0) << "a pure shift has a constant lag: " << s.err;
  Result q = run("gg-fit ratio A.h5:/average/mean B.h5:/average/mean --window 100 1000 -o q.h5");
  ASSERT_EQ(q.status, 0) << q.err;
  EXPECT_NEAR(rows(run("gg-fit table q.h5:/ratio/ratio").out).at(0).at(0), std::pow(5.0, -0.6), 1e-9);
  EXPECT_NE(q.err.find("rejected"), std::string::npos) << q.err;
  Result z = run("gg-fit late-exponent A.h5:/average/mean --end 1e4 -o z.h5");
  ASSERT_EQ(z.status, 0) << z.err;
  EXPECT_NEAR(rows(run("gg-fit table z.h5:/late/exponent").out).at(0).at(0), 0.6, 0.02);
  EXPECT_NE(z.err.find("settled"), std::string::npos) << z.err;
  // compare: B's exponent is A's (B = A 5^-0.6); C's, of m t^0.1, is 0.1 larger.
  for (int k = 0; k < 4; ++k) {
    gg::H5Output out(path("c" + std::to_string(k) + ".h5"));
    gg::H5Input in(path("a" + std::to_string(k) + ".h5"));
    std::vector<double> t = in.read("/cluster/time").data, m = in.read("/cluster/mean_mass").data;
    for (std::size_t i = 0; i < m.size(); ++i) m[i] *= std::pow(t[i], 0.1);
    out.write("/cluster/time", t);
    out.write("/cluster/mean_mass", m);
    out.commit();
  }
  ASSERT_EQ(run("gg-fit average --dataset /cluster/mean_mass c0.h5 c1.h5 c2.h5 c3.h5 -o C.h5").status, 0);
  ASSERT_EQ(run("gg-fit late-exponent B.h5:/average/mean --end 1e4 -o zb.h5").status, 0);
  ASSERT_EQ(run("gg-fit late-exponent C.h5:/average/mean --end 1e4 -o zc.h5").status, 0);
  Result cmp = run("gg-fit compare z.h5:/late/exponent zb.h5:/late/exponent zc.h5:/late/exponent -o cmp.h5");
  ASSERT_EQ(cmp.status, 0) << cmp.err;
  gg::H5Input ci(path("cmp.h5"));
  EXPECT_EQ(ci.read("/compare/agree").data, (std::vector<double>{1, 1, 0})) << cmp.err;
  EXPECT_NEAR(ci.read("/compare/difference").data.at(2), 0.1, 1e-9);
  EXPECT_NEAR(ci.read("/compare/difference_dof").data.at(1), 6, 1e-9);  // equal errors, 3 dof each
  Result bare = run("gg-fit compare z.h5:/late/change z.h5:/late/exponent -o no.h5");  // no _dof
  EXPECT_EQ(bare.status, 1);
  EXPECT_NE(bare.err.find("/late/change_dof"), std::string::npos) << bare.err;
  // Two runs: no jackknife, so no factor.
  Result two = run("gg-fit shift A2.h5:/average/mean B.h5:/average/mean --window 10 1000 -o no.h5");
  EXPECT_EQ(two.status, 2);
  EXPECT_NE(two.err.find(">= 3"), std::string::npos) << two.err;
  EXPECT_EQ(std::count(two.err.begin(), two.err.end(), '\n'), 1) << two.err;
  // Windows whose m ranges do not overlap: said, not fitted.
  Result apart = run("gg-fit shift A.h5:/average/mean B.h5:/average/mean --window 1 10 --window 1000 10000 -o no.h5");
  EXPECT_EQ(apart.status, 1);
  EXPECT_NE(apart.err.find("no common range"), std::string::npos) << apart.err;
  EXPECT_FALSE(fs::exists(path("no.h5")));
}

// at-equal end to end: runs b are runs a with time stretched by 2 (E_b(t) = E_a(t / 2)) and m raised by
// 1.5, so at every equal energy m_b / m_a = 1.5 exactly, although at equal times the energies differ.
TEST_F(GgFit, AtEqualComparesMAtEqualEnergy) {
  for (int k = 0; k < 4; ++k) {
    const std::string a = "a" + std::to_string(k) + ".h5", b = "b" + std::to_string(k) + ".h5";
    write_run(a, k);
    gg::H5Input in(path(a));
    gg::H5Output out(path(b));
    for (const char* g : {"/cluster", "/observables/kinetic_energy"}) {
      const std::string time = std::string(g) + "/time";
      std::vector<double> t = in.read(time).data;
      for (double& x : t) x *= 2;
      out.write(time, t);
    }
    std::vector<double> m = in.read("/cluster/mean_mass").data;
    for (double& y : m) y *= 1.5;
    out.write("/cluster/mean_mass", m);
    out.write("/observables/kinetic_energy/value", in.read("/observables/kinetic_energy/value").data);
    out.commit();
  }
  for (const char* s : {"a", "b"}) {
    const std::string runs = std::string(s) + "0.h5 " + s + "1.h5 " + s + "2.h5 " + s + "3.h5";
    ASSERT_EQ(run(std::string("gg-fit average --dataset /cluster/mean_mass ") + runs + " -o " + s + "m.h5").status, 0);
    ASSERT_EQ(run(std::string("gg-fit average --dataset /observables/kinetic_energy/value ") + runs + " -o " + s + "E.h5").status, 0);
  }
  // Levels the energy of a crosses at t = 2 and 4 (m is sampled from t = 1).
  const double t0 = gg::fit::enskog_haff(2, 0.37, 0.9, 1.0).t0;
  const double e2 = 1 / std::pow(1 + 2 / t0, 2), e4 = 1 / std::pow(1 + 4 / t0, 2);
  const std::string at = " --at " + std::to_string(e2) + " " + std::to_string(e4);
  Result r = run("gg-fit at-equal aE.h5:/average/mean am.h5:/average/mean bE.h5:/average/mean bm.h5:/average/mean" + at + " -o q.h5");
  ASSERT_EQ(r.status, 0) << r.err;
  gg::H5Input q(path("q.h5"));
  const std::vector<double> ratio = q.read("/at_equal/ratio").data, t = q.read("/at_equal/crossing_time").data;
  ASSERT_EQ(ratio.size(), 4u);  // [2 ensembles][2 levels]
  EXPECT_EQ(ratio[0], 1.0);
  for (std::size_t l : {2u, 3u}) EXPECT_NEAR(ratio[l], 1.5, 1e-9);
  EXPECT_NEAR(t[1], 4.0, 0.05);       // a crosses e4 near t = 4 (its mean energy carries no noise)
  EXPECT_NEAR(t[3], 2 * t[1], 1e-9);  // b crosses it at twice a's time
  EXPECT_NE(r.err.find("rejected"), std::string::npos) << r.err;
  // A level one ensemble's energy never reaches; an odd number of inputs.
  Result low = run("gg-fit at-equal aE.h5:/average/mean am.h5:/average/mean bE.h5:/average/mean bm.h5:/average/mean --at 1e-9 -o no.h5");
  EXPECT_EQ(low.status, 1);
  EXPECT_NE(low.err.find("never crosses"), std::string::npos) << low.err;
  EXPECT_EQ(std::count(low.err.begin(), low.err.end(), '\n'), 1) << low.err;
  Result odd = run("gg-fit at-equal aE.h5:/average/mean am.h5:/average/mean bE.h5:/average/mean" + at + " -o no.h5");
  EXPECT_EQ(odd.status, 2);
  EXPECT_FALSE(fs::exists(path("no.h5")));
}

// gg-fit crossing end to end: per-run shares 0.5 + 0.1 ln(t / t_c) + d_r with offsets d_r that average
// to 0, so the mean crosses 1/2 at exactly t_c; t_c = 100 (L / 512)^0.5 at three box edges. The
// jackknife of ln t* is then that of a mean: sd(d) / sqrt(R) / 0.1.
TEST_F(GgFit, CrossingTimesTheirErrorsAndTheSlopeAgainstL) {
  const std::vector<double> L{512, 1024, 2048}, d{-0.02, -0.01, 0.01, 0.02};
  std::vector<double> t;
  for (int k = 0; k <= 32; ++k) t.push_back(std::pow(10.0, k / 8.0));
  for (std::size_t j = 0; j < L.size(); ++j) {
    std::string runs;
    for (std::size_t r = 0; r < d.size(); ++r) {
      const std::string name = "L" + std::to_string(j) + "r" + std::to_string(r) + ".h5";
      gg::H5Output out(path(name));
      std::vector<double> share, wraps;
      for (std::size_t k = 0; k < t.size(); ++k) {
        share.push_back(0.5 + 0.1 * std::log(t[k] / (100 * std::sqrt(L[j] / 512))) + d[r]);
        wraps.push_back(k >= 10 + r + j ? 1 : 0);  // a quarter of the runs more at each sample from 10 + j on
      }
      out.write("/cluster/time", t);
      out.write("/cluster/largest_share_of_clustered", share);
      out.write("/cluster/wraps_any", wraps);
      out.commit();
      runs += " " + name;
    }
    ASSERT_EQ(run("gg-fit average --dataset /cluster/largest_share_of_clustered" + runs + " -o s" + std::to_string(j) + ".h5").status, 0);
    ASSERT_EQ(run("gg-fit average --dataset /cluster/wraps_any" + runs + " -o w" + std::to_string(j) + ".h5").status, 0);
  }
  Result r = run("gg-fit crossing s0.h5:/average/mean s1.h5:/average/mean s2.h5:/average/mean --level 0.5 --x 512 1024 2048 -o c.h5");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 5) << r.err;  // a header, one line per input, the slope
  EXPECT_NE(r.err.find("grows with x"), std::string::npos) << r.err;
  gg::H5Input c(path("c.h5"));
  const std::vector<double> time = c.read("/crossing/time").data, se = c.read("/crossing/log_time_stderr").data;
  const double se_exact = std::sqrt((0.02 * 0.02 + 0.01 * 0.01) * 2 / 3) / 2 / 0.1;
  for (std::size_t j = 0; j < 3; ++j) {
    EXPECT_NEAR(time[j], 100 * std::sqrt(L[j] / 512), 1e-9 * time[j]);
    EXPECT_NEAR(se[j], se_exact, 1e-9);
    EXPECT_EQ(c.read("/crossing/log_time_dof").data[j], 3);
    EXPECT_EQ(c.read("/crossing/runs_reaching").data[j], 4);
  }
  EXPECT_NEAR(c.read("/crossing/ratio").data[2], 2, 1e-9);
  EXPECT_NEAR(c.read("/crossing/slope").data[0], 0.5, 1e-9);
  // Equal weights: the slope is (ln t*_2 - ln t*_0) / (2 ln 2), with 2 x 3 dof by Welch.
  EXPECT_NEAR(c.read("/crossing/slope_stderr").data[0], se_exact * std::sqrt(2.0) / (2 * std::log(2.0)), 1e-9);
  EXPECT_NEAR(c.read("/crossing/slope_dof").data[0], 6, 1e-9);
  EXPECT_EQ(c.attr_string("/crossing", "verdict"), "grows with x");

  // The fraction of runs wrapping steps by 1/4 a sample: 0.5 is reached at the sample 11 + j, exactly.
  Result w = run("gg-fit crossing w0.h5:/average/mean w1.h5:/average/mean w2.h5:/average/mean --level 0.5 -o w.h5");
  ASSERT_EQ(w.status, 0) << w.err;
  gg::H5Input wf(path("w.h5"));
  for (std::size_t j = 0; j < 3; ++j) EXPECT_NEAR(wf.read("/crossing/time").data[j], t[11 + j], 1e-9 * t[11 + j]);
  EXPECT_TRUE(std::isnan(wf.read("/crossing/slope").data[0]));
  // A level the mean never reaches: NaN, with the reason, and no run reaches it.
  Result never = run("gg-fit crossing s0.h5:/average/mean --level 2 -o n.h5");
  ASSERT_EQ(never.status, 0) << never.err;
  EXPECT_NE(never.err.find("never reaches 2"), std::string::npos) << never.err;
  gg::H5Input nf(path("n.h5"));
  EXPECT_TRUE(std::isnan(nf.read("/crossing/time").data[0]));
  EXPECT_EQ(nf.read("/crossing/runs_reaching").data[0], 0);
}

TEST_F(GgFit, CrossingRefusesBadInputInOneLine) {
  std::string runs;
  for (int k = 0; k < 3; ++k) {
    write_run("run" + std::to_string(k) + ".h5", k);
    runs += " run" + std::to_string(k) + ".h5";
  }
  ASSERT_EQ(run("gg-fit average --dataset /cluster/mean_mass" + runs + " -o a.h5").status, 0);
  ASSERT_EQ(run("gg-fit average --dataset /cluster/mean_mass run0.h5 run1.h5 -o two.h5").status, 0);
  for (const std::string& bad : {std::string("gg-fit crossing a.h5:/average/mean -o out.h5"),
                                 std::string("gg-fit crossing two.h5:/average/mean --level 10 -o out.h5"),
                                 std::string("gg-fit crossing a.h5:/average/mean a.h5:/average/mean --level 10 --x 512 -o out.h5"),
                                 std::string("gg-fit crossing a.h5:/average/mean a.h5:/average/mean --level 10 --x 512 -1 -o out.h5"),
                                 std::string("gg-fit crossing a.h5:/average/mean a.h5:/average/mean --level 10 --x 512 0 -o out.h5")}) {
    Result r = run(bad);
    EXPECT_EQ(r.status, 2) << bad << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << bad << ": " << r.err;
  }
  EXPECT_FALSE(fs::exists(path("out.h5")));
  Result stays = run("gg-fit crossing a.h5:/average/mean --level 10 --stays");
  EXPECT_EQ(stays.status, 0) << stays.err;
  EXPECT_NE(stays.err.find("stays at or beyond 10"), std::string::npos) << stays.err;
}
