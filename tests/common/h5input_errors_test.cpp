// Every bad input gives one RuntimeError line that names the file (and dataset) and the fix.
#include <gtest/gtest.h>

#include <hdf5.h>

#include <functional>
#include <vector>

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

// A chunked dataset of 2^40 doubles whose chunks were never written: a valid file of a few kB,
// refused before anything is allocated for it (every way of reading it).
TEST_F(CommonH5InputErrors, HugeClaimOfASparseDataset) {
  const std::string path = dir_.file("sparse.h5");
  const hid_t file = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  const hsize_t dims[2] = {hsize_t{1} << 38, 4}, chunk[2] = {1, 4};
  const hid_t dcpl = H5Pcreate(H5P_DATASET_CREATE);
  H5Pset_chunk(dcpl, 2, chunk);
  const hid_t space = H5Screate_simple(2, dims, nullptr);
  H5Dclose(H5Dcreate2(file, "/big", H5T_IEEE_F64LE, space, H5P_DEFAULT, dcpl, H5P_DEFAULT));
  H5Sclose(space);
  H5Pclose(dcpl);
  H5Fclose(file);

  H5Input in(path);
  EXPECT_EQ(in.shape("/big"), (std::vector<std::size_t>{std::size_t{1} << 38, 4}));  // the claim itself is fine
  for (const auto& read : std::vector<std::function<void()>>{[&] { in.read("/big"); }, [&] { in.read_int("/big"); }})
    expect_error<RuntimeError>(read, {"sparse.h5", "/big", "8.8 TB", "damaged"});
  EXPECT_EQ(in.read_rows("/big", {7}).data, std::vector<double>(4, 0.0));  // one row of it is fine
}

// Hard links may make a cycle (legal HDF5): every object is listed once, on its first path.
TEST_F(CommonH5InputErrors, GroupCycleIsListedOnce) {
  const hid_t file = H5Fopen(good_.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  H5Lcreate_hard(file, "/", file, "/g/root", H5P_DEFAULT, H5P_DEFAULT);
  H5Lcreate_hard(file, "/g/vec", file, "/g/same_vec", H5P_DEFAULT, H5P_DEFAULT);
  H5Lcreate_soft("/g", file, "/g/soft", H5P_DEFAULT, H5P_DEFAULT);
  H5Fclose(file);
  EXPECT_EQ(H5Input(good_).objects_below("/"), (std::vector<std::string>{"/g", "/g/same_vec"}));
}

TEST_F(CommonH5InputErrors, GroupsNestedTooDeep) {
  const hid_t file = H5Fcreate(dir_.file("deep.h5").c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  for (hid_t g = H5Gcreate2(file, "d", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), level = 1; level <= 300; ++level) {
    const hid_t inner = H5Gcreate2(g, "d", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    H5Gclose(g);
    g = level < 300 ? inner : (H5Gclose(inner), -1);
  }
  H5Fclose(file);
  H5Input in(dir_.file("deep.h5"));
  expect_error<RuntimeError>([&] { in.objects_below("/"); }, {"deep.h5", "nested more than 256 levels"});
}

}  // namespace
}  // namespace gg
