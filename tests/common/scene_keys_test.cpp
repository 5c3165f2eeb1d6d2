// Scene files written by hand in INI or TOML style with - or _ in keys, and "did you mean" for a
// mistyped option or scene key (common/src/cli.cpp).
#include <gtest/gtest.h>

#include <sstream>

#include "gg/cli.hpp"
#include "gg/errors.hpp"
#include "test_support.hpp"

namespace gg {
namespace {

struct SceneTool {
  CLI::App app{"A test tool", "gg-test"};
  CommonFlags flags;
  double t_max = 0, rho = 0;
  int dim = 0;
  SceneTool() {
    add_common_flags(app, flags);
    app.add_option("--t-max", t_max, "Stop time");
    app.add_option("--rho", rho, "Density");
    app.add_option("--dim", dim, "Dimension");
    app.set_config("--scene");
  }
  // The exit status (-1: go on) and what went to stderr.
  std::pair<int, std::string> parse(std::vector<std::string> args) {
    args.insert(args.begin(), "gg-test");
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    std::ostringstream err;
    std::streambuf* old = std::cerr.rdbuf(err.rdbuf());
    const int status = parse_cli(app, static_cast<int>(argv.size()), argv.data());
    std::cerr.rdbuf(old);
    return {status, err.str()};
  }
};

TEST(CommonSceneKeys, IniAndTomlStylesWithDashesOrUnderscores) {
  test::TempDir dir;
  const std::vector<std::pair<std::string, std::string>> scenes{
      {"ini.ini", "t-max = 250\nrho = 0.37\ndim = 2\n"},
      {"underscore.ini", "t_max = 250\nrho=0.37\ndim=2\n"},
      {"toml.toml", "# a TOML scene\nt_max = 250.0\nrho = 0.37\ndim = 2\n"},
      {"quoted.toml", "\"t-max\" = 250\nrho = 0.37 # density\ndim = 2\n"}};
  for (const auto& [name, text] : scenes) {
    test::write_bytes(dir.file(name), text);
    SceneTool t;
    const auto [status, err] = t.parse({"--scene", dir.file(name)});
    EXPECT_EQ(status, -1) << name << ": " << err;
    EXPECT_EQ(t.t_max, 250) << name;
    EXPECT_EQ(t.rho, 0.37) << name;
    EXPECT_EQ(t.dim, 2) << name;
  }
}

TEST(CommonSceneKeys, MistypedOptionGetsTheNearestName) {
  SceneTool t;
  const auto [status, err] = t.parse({"--t-mx", "5"});
  EXPECT_EQ(status, kExitUsage);
  EXPECT_NE(err.find("did you mean --t-max?"), std::string::npos) << err;
  EXPECT_EQ(err.find('\n'), err.size() - 1) << "one line: " << err;
}

TEST(CommonSceneKeys, SwappedLettersAndEqualsFormAreRecognised) {
  SceneTool t;
  const auto [status, err] = t.parse({"--rhp=0.3"});
  EXPECT_EQ(status, kExitUsage);
  EXPECT_NE(err.find("did you mean --rho?"), std::string::npos) << err;
  SceneTool u;
  EXPECT_NE(u.parse({"--tmax", "5"}).second.find("did you mean --t-max?"), std::string::npos);
}

TEST(CommonSceneKeys, FarOffNamesGetNoGuess) {
  SceneTool t;
  const auto [status, err] = t.parse({"--temperature", "5"});
  EXPECT_EQ(status, kExitUsage);
  EXPECT_EQ(err.find("did you mean"), std::string::npos) << err;
}

TEST(CommonSceneKeys, MistypedSceneKeyKeepsItsSpellingAndGetsAGuess) {
  test::TempDir dir;
  test::write_bytes(dir.file("typo.toml"), "t_mxa = 5\n");
  SceneTool t;
  const auto [status, err] = t.parse({"--scene", dir.file("typo.toml")});
  EXPECT_EQ(status, kExitUsage);
  EXPECT_NE(err.find("unknown key 't_mxa'"), std::string::npos) << err;
  EXPECT_NE(err.find("did you mean 't-max'?"), std::string::npos) << err;
}

}  // namespace
}  // namespace gg
