// "file.h5:/group/dataset" and the time axis paired with a dataset (docs/DESIGN.md).
#include "gg/dataset_ref.hpp"

#include <gtest/gtest.h>

#include "gg/errors.hpp"
#include "gg/h5file.hpp"
#include "test_support.hpp"

namespace gg {
namespace {

TEST(CommonDatasetRef, SplitsAtTheLastColonSlash) {
  const DatasetRef a = parse_dataset_ref("runs/e0.5.h5:/cluster/mean_mass");
  EXPECT_EQ(a.file, "runs/e0.5.h5");
  EXPECT_EQ(a.dataset, "/cluster/mean_mass");
  const DatasetRef b = parse_dataset_ref("odd:/name.h5:/average/mean");  // a ':/' inside the file name
  EXPECT_EQ(b.file, "odd:/name.h5");
  EXPECT_EQ(b.dataset, "/average/mean");
  const DatasetRef c = parse_dataset_ref("-:/fit/exponent");
  EXPECT_EQ(c.file, "-");
  EXPECT_EQ(c.dataset, "/fit/exponent");
}

TEST(CommonDatasetRef, RejectsTextWithoutADataset) {
  for (const std::string bad : {"run.h5", "run.h5:cluster/mean_mass", ":/cluster/mean_mass", "run.h5:/"})
    test::expect_error<UsageError>([&] { parse_dataset_ref(bad); }, {bad, "FILE.h5:/group/dataset"});
}

class CommonPairedTime : public ::testing::Test {
 protected:
  void SetUp() override {
    H5Output out(path_);
    out.write("/cluster/time", std::vector<double>{1, 2});          // rule 1: same group
    out.write("/cluster/mean_mass", std::vector<double>{3, 4});
    out.write("/cluster/sub/mean_mass", std::vector<double>{3, 4}); // rule 2: parent group
    out.write("/observables/kinetic_energy/time", std::vector<double>{0, 1});  // H5MD element
    out.write("/observables/kinetic_energy/value", std::vector<double>{1, 0.5});
    out.write("/lonely/data", std::vector<double>{1});
    out.create_group("/fake/time");  // a group called time is not a time axis
    out.write("/fake/data", std::vector<double>{1});
    out.commit();
  }
  test::TempDir dir_;
  std::string path_ = dir_.file("p.h5");
};

TEST_F(CommonPairedTime, TimeInTheSameGroup) {
  EXPECT_EQ(paired_time(H5Input(path_), "/cluster/mean_mass"), "/cluster/time");
}

TEST_F(CommonPairedTime, TimeInTheParentGroup) {
  EXPECT_EQ(paired_time(H5Input(path_), "/cluster/sub/mean_mass"), "/cluster/time");
}

TEST_F(CommonPairedTime, H5mdTimeSiblingOfValue) {
  EXPECT_EQ(paired_time(H5Input(path_), "/observables/kinetic_energy/value"), "/observables/kinetic_energy/time");
}

TEST_F(CommonPairedTime, NoTimeAxisIsRuntimeError) {
  H5Input in(path_);
  test::expect_error<RuntimeError>([&] { paired_time(in, "/lonely/data"); }, {"p.h5", "/lonely/data", "/lonely/time"});
  test::expect_error<RuntimeError>([&] { paired_time(in, "/fake/data"); }, {"p.h5", "/fake/data"});
}

}  // namespace
}  // namespace gg
