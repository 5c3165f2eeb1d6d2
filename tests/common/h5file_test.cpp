// H5Input / H5Output on files: exact round trips, attributes, atomic publication, determinism.
#include "gg/h5file.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <limits>

#include <sys/wait.h>
#include <unistd.h>

#include "gg/errors.hpp"
#include "test_support.hpp"

namespace gg {
namespace {

using test::TempDir;

TEST(CommonH5File, DoubleArrayRoundTripKeepsShapeAndExactValues) {
  TempDir dir;
  const Array a{{2, 3, 2}, {0.1, -2.5, 1e-300, 1e300, 3.141592653589793, -0.0, 7, 8, 9, 10, 11, 1.0 / 3}};
  {
    H5Output out(dir.file("a.h5"));
    out.write("/g/sub/a", a);
    out.write("/g/v", std::vector<double>{1.5, 2.5});
    out.write("/empty", std::vector<double>{});
    out.commit();
  }
  H5Input in(dir.file("a.h5"));
  const Array back = in.read("/g/sub/a", 3);
  EXPECT_EQ(back.shape, a.shape);
  EXPECT_EQ(back.data, a.data);  // bitwise equal doubles, no tolerance
  EXPECT_EQ(in.read("/g/v", 1).data, (std::vector<double>{1.5, 2.5}));
  EXPECT_EQ(in.read("/empty").shape, (std::vector<std::size_t>{0}));
  EXPECT_EQ(in.shape("/g/sub/a"), a.shape);
}

TEST(CommonH5File, Int64AndScalarsRoundTrip) {
  TempDir dir;
  const std::vector<std::int64_t> big{0, -1, std::numeric_limits<std::int64_t>::max(), std::numeric_limits<std::int64_t>::min()};
  {
    H5Output out(dir.file("i.h5"));
    out.write("/steps", big);
    out.write_scalar("/s/d", 2.75);
    out.write_scalar("/s/i", std::int64_t{42});
    out.write_scalar("/s/int", 7);  // plain int goes through the integral overload
    out.commit();
  }
  H5Input in(dir.file("i.h5"));
  EXPECT_EQ(in.read_int("/steps"), big);
  const Array d = in.read("/s/d", 0);
  EXPECT_TRUE(d.shape.empty());
  EXPECT_EQ(d.data, std::vector<double>{2.75});
  EXPECT_EQ(in.read_int("/s/i"), std::vector<std::int64_t>{42});
  EXPECT_EQ(in.read_int("/s/int"), std::vector<std::int64_t>{7});
}

TEST(CommonH5File, ReadIntAcceptsIntegralFloatsOnly) {
  TempDir dir;
  {
    H5Output out(dir.file("f.h5"));
    out.write("/whole", std::vector<double>{1, 2, -3});
    out.write("/fraction", std::vector<double>{1, 2.5});
    out.commit();
  }
  H5Input in(dir.file("f.h5"));
  EXPECT_EQ(in.read_int("/whole"), (std::vector<std::int64_t>{1, 2, -3}));
  test::expect_error<RuntimeError>([&] { in.read_int("/fraction"); }, {"f.h5", "/fraction", "non-integer"});
}

TEST(CommonH5File, Float32StoresSinglePrecision) {
  TempDir dir;
  const Array a{{2, 2}, {0.1, 1.0 / 3, 1e10, -2}};
  {
    H5Output out(dir.file("f.h5"));
    out.write_float("/x", a);
    out.commit();
  }
  H5Input in(dir.file("f.h5"));
  const Array back = in.read("/x", 2);
  EXPECT_EQ(back.shape, a.shape);
  for (std::size_t i = 0; i < a.data.size(); ++i) EXPECT_EQ(back.data[i], static_cast<double>(static_cast<float>(a.data[i])));
  EXPECT_NE(back.data[0], 0.1);  // really narrowed, not stored as double

  // 4 bytes per value on disk instead of 8.
  const Array big{{10000}, std::vector<double>(10000, 0.5)};
  for (const bool narrow : {true, false}) {
    H5Output out(dir.file(narrow ? "f32.h5" : "f64.h5"));
    narrow ? out.write_float("/v", big) : out.write("/v", big);
    out.commit();
  }
  EXPECT_NEAR(double(std::filesystem::file_size(dir.file("f64.h5")) - std::filesystem::file_size(dir.file("f32.h5"))),
              40000.0, 1000.0);
}

// gg-sim writes its snapshots a frame at a time: the file must be the one a single write makes.
TEST(CommonH5File, WriteRowsGivesTheBytesOfOneWrite) {
  TempDir dir;
  const Array a{{3, 2, 2}, {0.1, -2.5, 1e-300, 1e300, 3.141592653589793, -0.0, 7, 8, 9, 10, 11, 1.0 / 3}};
  const auto rows = [&](std::size_t k, double* values) { std::copy_n(a.data.begin() + 4 * k, 4, values); };
  for (const bool narrow : {false, true}) {
    {
      H5Output out(dir.file("whole.h5"));
      narrow ? out.write_float("/g/x", a) : out.write("/g/x", a);
      out.commit();
    }
    {
      H5Output out(dir.file("rows.h5"));
      out.write_rows("/g/x", a.shape, rows, narrow);
      out.commit();
    }
    EXPECT_TRUE(test::read_bytes(dir.file("whole.h5")) == test::read_bytes(dir.file("rows.h5"))) << "float32: " << narrow;
  }
}

TEST(CommonH5File, ReadRowsKeepsRequestedOrder) {
  TempDir dir;
  {
    H5Output out(dir.file("r.h5"));
    out.write("/m", Array{{3, 2}, {0, 1, 10, 11, 20, 21}});
    out.commit();
  }
  H5Input in(dir.file("r.h5"));
  const Array rows = in.read_rows("/m", {2, 0, 2});
  EXPECT_EQ(rows.shape, (std::vector<std::size_t>{3, 2}));
  EXPECT_EQ(rows.data, (std::vector<double>{20, 21, 0, 1, 20, 21}));
  test::expect_error<RuntimeError>([&] { in.read_rows("/m", {3}); }, {"r.h5", "/m", "row 3"});
}

TEST(CommonH5File, ReadRowsOfAnEmptyDataset) {
  TempDir dir;
  {
    H5Output out(dir.file("e.h5"));
    out.write("/frames", Array{{0, 4, 2}, {}});
    out.commit();
  }
  H5Input in(dir.file("e.h5"));
  EXPECT_EQ(in.read_rows("/frames", {}).shape, (std::vector<std::size_t>{0, 4, 2}));
  test::expect_error<RuntimeError>([&] { in.read_rows("/frames", {0}); }, {"e.h5", "has 0 rows"});
}

TEST(CommonH5File, AttributesLargerThanAnObjectHeader) {
  // A long argv (e.g. gg-fit average over thousands of runs) exceeds the 64 KiB that old-style
  // object headers hold; the 1.8 file format stores it densely.
  TempDir dir;
  std::vector<std::string> argv;
  for (int i = 0; i < 5000; ++i) argv.push_back("runs/e0.5/seed" + std::to_string(i) + ".h5:/cluster/mean_mass");
  {
    H5Output out(dir.file("big.h5"));
    out.attr("/parameters/provenance", "argv", argv);
    out.commit();
  }
  EXPECT_EQ(H5Input(dir.file("big.h5")).attr_strings("/parameters/provenance", "argv"), argv);
}

TEST(CommonH5File, AttributesRoundTrip) {
  TempDir dir;
  {
    H5Output out(dir.file("at.h5"));
    out.write("/d", std::vector<double>{1});
    out.attr("/d", "unit", std::string("sigma"));
    out.attr("/d", "scale", 0.25);
    out.attr("/d", "count", std::int64_t{-5});
    out.attr("/d", "n", 12);                 // int
    out.attr("/d", "seed", std::uint64_t{18446744073709551615ull});
    out.attr("/params", "e", 0.5);           // missing object becomes a group
    out.attr("/params", "e", 0.7);           // and a second write replaces
    out.attr("/params", "edges", std::vector<double>{512, 256});
    out.attr("/params", "version", std::vector<std::int64_t>{1, 1});
    out.attr("/params", "names", std::vector<std::string>{"periodic", "périodique", ""});
    out.attr("/params", "none", std::vector<std::string>{});
    out.commit();
  }
  H5Input in(dir.file("at.h5"));
  EXPECT_EQ(in.attr_string("/d", "unit"), "sigma");
  EXPECT_EQ(in.attr_double("/d", "scale"), 0.25);
  EXPECT_EQ(in.attr_double("/d", "count"), -5);
  EXPECT_EQ(in.attr_double("/d", "n"), 12);
  EXPECT_EQ(in.attr_double("/d", "seed"), 18446744073709551615.0);
  EXPECT_EQ(in.attr_double("/params", "e"), 0.7);
  EXPECT_EQ(in.attr_doubles("/params", "edges"), (std::vector<double>{512, 256}));
  EXPECT_EQ(in.attr_doubles("/params", "version"), (std::vector<double>{1, 1}));
  EXPECT_EQ(in.attr_strings("/params", "names"), (std::vector<std::string>{"periodic", "périodique", ""}));
  EXPECT_TRUE(in.attr_strings("/params", "none").empty());
  EXPECT_EQ(in.attr_strings("/d", "unit"), std::vector<std::string>{"sigma"});
  // Missing attribute or object: nothing, not an error.
  EXPECT_FALSE(in.attr_string("/d", "nope").has_value());
  EXPECT_FALSE(in.attr_double("/nowhere", "e").has_value());
  // Wrong type or count: an error naming file, object and attribute.
  test::expect_error<RuntimeError>([&] { in.attr_double("/d", "unit"); }, {"at.h5", "unit", "/d"});
  test::expect_error<RuntimeError>([&] { in.attr_string("/d", "scale"); }, {"at.h5", "scale"});
  test::expect_error<RuntimeError>([&] { in.attr_double("/params", "edges"); }, {"at.h5", "edges", "expected one"});
}

TEST(CommonH5File, ExistsMembersAndKinds) {
  TempDir dir;
  {
    H5Output out(dir.file("m.h5"));
    out.write("/g/b", std::vector<double>{1});
    out.write("/g/a", std::vector<double>{1});
    out.create_group("/g/c/d");
    out.commit();
  }
  H5Input in(dir.file("m.h5"));
  EXPECT_TRUE(in.exists("/g/c/d"));
  EXPECT_TRUE(in.exists("g/a"));  // relative paths are taken from the root
  EXPECT_FALSE(in.exists("/g/zz"));
  EXPECT_FALSE(in.exists("/g/a/below_a_dataset"));
  EXPECT_TRUE(in.is_dataset("/g/a"));
  EXPECT_FALSE(in.is_dataset("/g/c"));
  EXPECT_EQ(in.members("/g"), (std::vector<std::string>{"a", "b", "c"}));
  EXPECT_EQ(in.members("/"), std::vector<std::string>{"g"});
  EXPECT_TRUE(in.members("/g/a").empty());
}

TEST(CommonH5File, WriteCheckedAgainstShapeAndDuplicates) {
  TempDir dir;
  H5Output out(dir.file("w.h5"));
  EXPECT_THROW(out.write("/bad", Array{{2, 2}, {1, 2, 3}}), std::invalid_argument);
  out.write("/once", std::vector<double>{1});
  EXPECT_THROW(out.write("/once", std::vector<double>{2}), std::logic_error);
}

TEST(CommonH5File, UncommittedOutputLeavesNothing) {
  TempDir dir;
  {
    H5Output out(dir.file("x.h5"));
    out.write("/a", std::vector<double>{1, 2});
    // While building, only a hidden temporary exists: nothing looks like a finished output.
    const std::vector<std::string> during = dir.entries();
    ASSERT_EQ(during.size(), 1u);
    EXPECT_EQ(during[0].rfind(".x.h5.tmp.", 0), 0u) << during[0];
  }
  EXPECT_TRUE(dir.entries().empty());
}

TEST(CommonH5File, CommitPublishesUnderFinalName) {
  TempDir dir;
  test::write_bytes(dir.file("x.h5"), "old content");
  {
    H5Output out(dir.file("x.h5"));
    out.write("/a", std::vector<double>{1, 2});
    EXPECT_EQ(test::read_bytes(dir.file("x.h5")), "old content");  // untouched until commit
    out.commit();
  }
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"x.h5"});
  EXPECT_EQ(H5Input(dir.file("x.h5")).read("/a").data, (std::vector<double>{1, 2}));
}

TEST(CommonH5File, KilledWriterLeavesNoTemporary) {
  TempDir dir;
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    H5Output out(dir.file("x.h5"));
    out.write("/a", std::vector<double>{1, 2});
    std::raise(SIGTERM);  // as a Slurm time limit would
    _exit(0);
  }
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM);
  EXPECT_TRUE(dir.entries().empty());
}

TEST(CommonH5File, SameContentGivesSameBytes) {
  TempDir dir;
  auto write = [&](const std::string& name) {
    H5Output out(dir.file(name));
    out.write("/g/a", Array{{2, 2}, {1, 2, 3, 4}});
    out.attr("/g", "label", std::string("x"));
    out.attr("/g/a", "names", std::vector<std::string>{"p", "q"});
    out.commit();
  };
  write("one.h5");
  sleep(1);  // object timestamps have one-second resolution; none must be stored
  write("two.h5");
  EXPECT_TRUE(test::read_bytes(dir.file("one.h5")) == test::read_bytes(dir.file("two.h5")));
}

TEST(CommonH5File, MissingOutputDirectoryIsUsageError) {
  TempDir dir;
  test::expect_error<UsageError>([&] { H5Output out(dir.file("no/such/dir/x.h5")); }, {"no/such/dir", "does not exist"});
  test::expect_error<UsageError>([&] { H5Output out(dir.path().string()); }, {"is a directory"});
}

// gg-cluster sim.h5 -o sim.h5 once replaced the simulation by its analysis: the commit renames over
// the output's path, whatever name the input was read under.
TEST(CommonH5File, OutputNamingAnInputIsRefusedHoweverSpelled) {
  TempDir dir;
  namespace fs = std::filesystem;
  const std::string a = dir.file("a.h5");
  test::write_bytes(a, "the simulation");
  fs::create_directory(dir.path() / "sub");
  fs::create_symlink(a, dir.file("link.h5"));
  fs::create_hard_link(a, dir.file("hard.h5"));
  const std::string spellings[] = {a, dir.file("./a.h5"), dir.file("sub/../a.h5"), dir.file("link.h5"),
                                   dir.file("hard.h5")};
  for (const std::string& output : spellings) {
    SCOPED_TRACE(output);
    test::expect_error<UsageError>([&] { require_output_is_not_an_input(output, {a}); },
                                   {"output '" + output + "'", "also an input", "choose another -o"});
    test::expect_error<UsageError>([&] { require_output_is_not_an_input(a, {output}); }, {"also an input"});
  }
  // The file of a dataset reference counts, wherever it is among the inputs.
  test::expect_error<UsageError>(
      [&] { require_output_is_not_an_input(a, {dir.file("b.h5:/x/y"), dir.file("./a.h5") + ":/cluster/mean_mass"}); },
      {"output '" + a + "'", "'" + dir.file("./a.h5") + "'"});
  // A file in a directory whose name ends in ':' is a file, not FILE:/dataset.
  fs::create_directory(dir.path() / "run:");
  const std::string odd = dir.file("run:/c.h5");
  test::write_bytes(odd, "another simulation");
  test::expect_error<UsageError>([&] { require_output_is_not_an_input(odd, {odd}); }, {"also an input"});
  EXPECT_EQ(test::read_bytes(a), "the simulation");
}

TEST(CommonH5File, OutputThatIsNoInputPasses) {
  TempDir dir;
  const std::string a = dir.file("a.h5"), b = dir.file("b.h5");
  test::write_bytes(a, "one");
  test::write_bytes(b, "two");
  EXPECT_NO_THROW(require_output_is_not_an_input(b, {a, a + ":/cluster/mean_mass"}));  // another file
  EXPECT_NO_THROW(require_output_is_not_an_input(dir.file("new.h5"), {a}));            // not written yet
  EXPECT_NO_THROW(require_output_is_not_an_input(a, {dir.file("missing.h5")}));        // reported when read
  EXPECT_NO_THROW(require_output_is_not_an_input("-", {"-", "-:/cluster/mean_mass"}));  // stdout is not stdin
  EXPECT_NO_THROW(require_output_is_not_an_input(a, {"-"}));
  EXPECT_NO_THROW(require_output_is_not_an_input("", {a}));  // no -o given
  EXPECT_NO_THROW(require_output_is_not_an_input(a, {}));
}

// Names not written yet (gg-sim's output and checkpoint) are one file when their paths resolve alike.
TEST(CommonH5File, SameFileComparesNamesNotWrittenYetByPath) {
  TempDir dir;
  namespace fs = std::filesystem;
  fs::create_directory(dir.path() / "sub");
  const std::string x = dir.file("x.h5");
  EXPECT_TRUE(same_file(x, dir.file("sub/../x.h5")));
  EXPECT_FALSE(same_file(x, dir.file("y.h5")));
  EXPECT_FALSE(same_file("-", "-"));
  EXPECT_FALSE(same_file("", ""));
  test::write_bytes(x, "one");
  EXPECT_TRUE(same_file(dir.file("sub/../x.h5"), x));  // existing: equivalent()
  EXPECT_FALSE(same_file(x, dir.file("y.h5")));
}

}  // namespace
}  // namespace gg
