// Command-line conventions of every tool: --version, --help, parse errors, scene files,
// --progress/--quiet, and the one-line error report with its exit status (docs/DESIGN.md).
#include "gg/cli.hpp"

#include <gtest/gtest.h>

#include <sstream>

#include "gg/errors.hpp"
#include "gg/version.hpp"
#include "test_support.hpp"

namespace gg {
namespace {

// Captures what a std::ostream (std::cout / std::cerr) receives while alive.
class Capture {
 public:
  explicit Capture(std::ostream& os) : os_(os), old_(os.rdbuf(buffer_.rdbuf())) {}
  ~Capture() { os_.rdbuf(old_); }
  std::string text() const { return buffer_.str(); }

 private:
  std::ostream& os_;
  std::ostringstream buffer_;
  std::streambuf* old_;
};

struct Tool {
  CLI::App app{"A test tool", "gg-test"};
  CommonFlags flags;
  double e = 0.5;
  std::uint64_t count = 0;
  Tool() {
    add_common_flags(app, flags);
    app.add_option("--e", e, "Restitution")->check(CLI::Range(0.0, 1.0));
    app.add_option("--count", count, "A count")->transform(whole_number());
    app.set_config("--scene");
  }
  int parse(std::vector<std::string> args) {
    args.insert(args.begin(), "/some/dir/gg-test");
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    return parse_cli(app, static_cast<int>(argv.size()), argv.data());
  }
};

TEST(CommonCli, VersionPrintsNameVersionAndGitHashAndExitsZero) {
  Tool t;
  Capture out(std::cout);
  EXPECT_EQ(t.parse({"--version"}), 0);
  EXPECT_EQ(out.text(), std::string("gg-test ") + kVersion + " (git " + kGitHash + ")\n");
}

TEST(CommonCli, HelpExitsZeroAndDescribesCommonFlags) {
  Tool t;
  Capture out(std::cout);
  EXPECT_EQ(t.parse({"--help"}), 0);
  for (const char* flag : {"--version", "--progress", "--quiet", "--e"})
    EXPECT_NE(out.text().find(flag), std::string::npos) << flag;
}

// Each option line shows its type and default and nothing of the checks behind it: the check for
// blank values, which every option has, would otherwise end every line in ":non-blank".
TEST(CommonCli, HelpShowsTypesAndDefaultsWithoutValidatorNames) {
  Tool t;
  t.app.add_option("--rho", t.e, "A density")->capture_default_str();
  Capture out(std::cout);
  EXPECT_EQ(t.parse({"--help"}), 0);
  EXPECT_NE(out.text().find("--rho FLOAT=0.5 "), std::string::npos) << out.text();
  EXPECT_NE(out.text().find("--count UINT "), std::string::npos) << out.text();
  EXPECT_EQ(out.text().find("non-blank"), std::string::npos) << out.text();
}

TEST(CommonCli, ValidFlagsContinue) {
  Tool t;
  EXPECT_EQ(t.parse({"--e", "0.9", "--quiet"}), -1);
  EXPECT_EQ(t.e, 0.9);
  EXPECT_TRUE(t.flags.quiet);
}

TEST(CommonCli, ParseErrorsAreOneLineAndStatusTwo) {
  for (const std::vector<std::string>& args : {std::vector<std::string>{"--bogus"}, {"--e", "1.5"}, {"--e", "x"},
                                                {"--progress", "--quiet"}}) {
    Tool t;
    Capture err(std::cerr);
    EXPECT_EQ(t.parse(args), kExitUsage) << args[0];
    const std::string text = err.text();
    EXPECT_EQ(text.rfind("gg-test: error: ", 0), 0u) << text;
    EXPECT_NE(text.find("; see --help\n"), std::string::npos) << text;
    EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 1) << text;
  }
}

TEST(CommonCli, CountsTakeDigitsOrExactFloatingPointNotation) {
  const std::pair<const char*, std::uint64_t> cases[] = {
      {"12", 12}, {"4e6", 4000000}, {"1.5E3", 1500}, {"2.50e1", 25}, {"1e18", 1000000000000000000u}, {"0e0", 0}};
  for (const auto& [text, value] : cases) {
    Tool t;
    EXPECT_EQ(t.parse({"--count", text}), -1) << text;
    EXPECT_EQ(t.count, value) << text;
  }
  test::TempDir dir;
  test::write_bytes(dir.file("scene.ini"), "count = 2e5\n");
  Tool t;
  EXPECT_EQ(t.parse({"--scene", dir.file("scene.ini")}), -1);
  EXPECT_EQ(t.count, 200000u);
}

TEST(CommonCli, CountsThatAreNotWholeAreOneLineErrorsThatSayWhatToWrite) {
  // 2^63 = 9.223372036854775808e18: the first double too large.
  for (const char* text : {"2.5", "1e-3", "-1e3", "9.3e18", "4e6x", "inf", "nan", "1e", "many"}) {
    Tool t;
    Capture err(std::cerr);
    EXPECT_EQ(t.parse({"--count", text}), kExitUsage) << text;
    const std::string message = err.text();
    EXPECT_NE(message.find(std::string("'") + text + "' is not a whole number"), std::string::npos) << message;
    EXPECT_NE(message.find("4e6"), std::string::npos) << message;
    EXPECT_EQ(std::count(message.begin(), message.end(), '\n'), 1) << message;
  }
}

TEST(CommonCli, SceneFileKeysAreFlagsAndUnknownKeysAreErrors) {
  test::TempDir dir;
  test::write_bytes(dir.file("good.ini"), "e = 0.7\n");
  test::write_bytes(dir.file("typo.ini"), "e = 0.7\nrho_typo = 0.37\n");
  {
    Tool t;
    EXPECT_EQ(t.parse({"--scene", dir.file("good.ini")}), -1);
    EXPECT_EQ(t.e, 0.7);
  }
  {  // a flag overrides the scene
    Tool t;
    EXPECT_EQ(t.parse({"--scene", dir.file("good.ini"), "--e", "0.2"}), -1);
    EXPECT_EQ(t.e, 0.2);
  }
  {
    Tool t;
    Capture err(std::cerr);
    EXPECT_EQ(t.parse({"--scene", dir.file("typo.ini")}), kExitUsage);
    EXPECT_NE(err.text().find("rho_typo"), std::string::npos) << err.text();
  }
}

TEST(CommonCli, ShowProgressFollowsFlags) {
  CommonFlags f;
  f.quiet = true;
  EXPECT_FALSE(f.show_progress());
  f = {};
  f.progress = true;
  EXPECT_TRUE(f.show_progress());
  f = {};
  EXPECT_EQ(f.show_progress(), static_cast<bool>(isatty(2)));  // default: only on a terminal
}

TEST(CommonCli, ArgvStrings) {
  char a[] = "gg-x", b[] = "-o", c[] = "-";
  char* argv[] = {a, b, c};
  EXPECT_EQ(argv_strings(3, argv), (std::vector<std::string>{"gg-x", "-o", "-"}));
}

TEST(CommonErrors, GuardedMainReportsOneLineWithExitStatus) {
  struct Case {
    std::function<int()> body;
    int status;
    std::string line;
  };
  const std::vector<Case> cases{
      {[] { return 0; }, 0, ""},
      {[]() -> int { throw UsageError("--L must be positive; got -1"); }, kExitUsage,
       "gg-x: error: --L must be positive; got -1\n"},
      {[]() -> int { throw RuntimeError("'a.h5': not an HDF5 file"); }, kExitRuntime,
       "gg-x: error: 'a.h5': not an HDF5 file\n"},
      {[]() -> int { throw std::out_of_range("two\nlines"); }, kExitRuntime, "gg-x: error: two lines\n"},
      {[]() -> int { throw std::bad_alloc(); }, kExitRuntime,
       "gg-x: error: out of memory; reduce the sizes asked for (or run where more memory is available)\n"},
  };
  for (const Case& c : cases) {
    Capture err(std::cerr);
    EXPECT_EQ(guarded_main("gg-x", c.body), c.status);
    EXPECT_EQ(err.text(), c.line);
  }
}

TEST(CommonErrors, GuardedMainSaysWhatToReduceWhenOutOfMemory) {
  Capture err(std::cerr);
  EXPECT_EQ(guarded_main("gg-x", []() -> int { throw std::bad_alloc(); }, "--frames"), kExitRuntime);
  EXPECT_EQ(err.text(), "gg-x: error: out of memory; reduce --frames (or run where more memory is available)\n");
}

}  // namespace
}  // namespace gg
