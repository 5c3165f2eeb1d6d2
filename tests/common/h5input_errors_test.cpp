// Every bad input gives one RuntimeError line that names the file (and dataset) and the fix.
#include <gtest/gtest.h>

#include <hdf5.h>

#include "gg/errors.hpp"
#include "gg/h5file.hpp"
#include "test_support.hpp"

namespace gg {
namespace {

using test::expect_error;
using test::TempDir;

class CommonH5InputErrors : public ::testing::Test {
 protected:
  void SetUp() override {
    H5Output out(good_);
    out.write("/g/vec", std::vector<double>{1, 2, 3});
    out.commit();
  }
  TempDir dir_;
  std::string good_ = dir_.file("good.h5");
};

TEST_F(CommonH5InputErrors, MissingFile) {
  expect_error<RuntimeError>([&] { H5Input in(dir_.file("absent.h5")); }, {"absent.h5", "No such file", "check the path"});
}

TEST_F(CommonH5InputErrors, Directory) {
  expect_error<RuntimeError>([&] { H5Input in(dir_.path().string()); }, {dir_.path().string(), "is a directory"});
}

TEST_F(CommonH5InputErrors, EmptyFile) {
  test::write_bytes(dir_.file("empty.h5"), "");
  expect_error<RuntimeError>([&] { H5Input in(dir_.file("empty.h5")); }, {"empty.h5", "empty file"});
}

TEST_F(CommonH5InputErrors, TextFile) {
  test::write_bytes(dir_.file("notes.txt"), "t,value\n0,1\n1,2\n");
  expect_error<RuntimeError>([&] { H5Input in(dir_.file("notes.txt")); }, {"notes.txt", "not an HDF5 file"});
}

TEST_F(CommonH5InputErrors, TruncatedFile) {
  const std::string bytes = test::read_bytes(good_);
  test::write_bytes(dir_.file("cut.h5"), bytes.substr(0, bytes.size() / 2));
  expect_error<RuntimeError>([&] { H5Input in(dir_.file("cut.h5")); }, {"cut.h5", "truncated or damaged"});
}

TEST_F(CommonH5InputErrors, MissingDataset) {
  H5Input in(good_);
  expect_error<RuntimeError>([&] { in.read("/g/nope"); }, {"good.h5", "/g/nope", "h5ls"});
  expect_error<RuntimeError>([&] { in.read_int("/nope/deeper"); }, {"good.h5", "/nope/deeper"});
}

TEST_F(CommonH5InputErrors, GroupInsteadOfDataset) {
  H5Input in(good_);
  expect_error<RuntimeError>([&] { in.read("/g"); }, {"good.h5", "'/g'", "is a group"});
}

TEST_F(CommonH5InputErrors, WrongRank) {
  H5Input in(good_);
  expect_error<RuntimeError>([&] { in.read("/g/vec", 2); }, {"good.h5", "/g/vec", "rank 1", "expected rank 2"});
}

TEST_F(CommonH5InputErrors, NonNumericDataset) {
  // H5Output writes numbers only, so a string dataset is made with the C API.
  const std::string path = dir_.file("strings.h5");
  const hid_t file = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  const hid_t type = H5Tcopy(H5T_C_S1);
  H5Tset_size(type, 8);
  const hsize_t n = 2;
  const hid_t space = H5Screate_simple(1, &n, nullptr);
  const hid_t ds = H5Dcreate2(file, "/names", type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  H5Dwrite(ds, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, "alpha\0\0\0beta\0\0\0\0");
  H5Dclose(ds);
  H5Sclose(space);
  H5Tclose(type);
  H5Fclose(file);

  H5Input in(path);
  expect_error<RuntimeError>([&] { in.read("/names"); }, {"strings.h5", "/names", "does not hold numbers"});
  expect_error<RuntimeError>([&] { in.read_int("/names"); }, {"strings.h5", "/names"});
}

}  // namespace
}  // namespace gg
