// H5Input: reading HDF5 files through the C API.
// Every message names the file and the dataset, and says what to do, because it ends up as the
// one line a user sees (docs/DESIGN.md "Conventions of every tool").
#include "gg/h5file.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <numeric>
#include <set>
#include <utility>

#include <hdf5.h>
#include <hdf5_hl.h>  // H5LTpath_valid
#include <sys/stat.h>
#include <unistd.h>

#include "gg/errors.hpp"
#include "gg/scratch_file.hpp"
#include "gg/standard_streams.hpp"
#include "h5_support.hpp"

namespace gg {

using namespace h5detail;

namespace {

std::vector<std::size_t> shape_of(hid_t space) {
  const int rank = H5Sget_simple_extent_ndims(space);
  std::vector<hsize_t> dims(std::max(rank, 0));
  if (rank > 0) H5Sget_simple_extent_dims(space, dims.data(), nullptr);
  return {dims.begin(), dims.end()};
}

// Reads every element of a string attribute, fixed- or variable-length; `where` names it in errors.
std::vector<std::string> read_strings(hid_t attr, hid_t type, std::size_t n, const std::string& where) {
  std::vector<std::string> out;
  if (n == 0) return out;
  if (H5Tis_variable_str(type) > 0) {
    Handle mem = utf8_string_type();
    H5Tset_cset(mem.get(), H5Tget_cset(type));
    std::vector<char*> buf(n, nullptr);
    if (H5Aread(attr, mem.get(), buf.data()) < 0) throw RuntimeError(where + ": read failed");
    for (char* s : buf) out.emplace_back(s ? s : "");
    Handle space(H5Aget_space(attr), H5Sclose);
    H5Dvlen_reclaim(mem.get(), space.get(), H5P_DEFAULT, buf.data());
    return out;
  }
  const std::size_t size = H5Tget_size(type);
  std::vector<char> buf(n * size);
  if (H5Aread(attr, type, buf.data()) < 0) throw RuntimeError(where + ": read failed");
  const bool space_padded = H5Tget_strpad(type) == H5T_STR_SPACEPAD;
  for (std::size_t i = 0; i < n; ++i) {
    std::string s(buf.data() + i * size, size);
    s.resize(std::min(s.size(), s.find('\0')));
    if (space_padded) s.erase(s.find_last_not_of(' ') + 1);
    out.push_back(std::move(s));
  }
  return out;
}

// HDF5 reads a file by seeking, which a pipe cannot do: a piped file is copied to a scratch file
// (disk, not memory: a file of snapshots can be larger than the memory). Returns its size.
std::size_t copy_stdin_to(const ScratchFile& file) {
  std::vector<char> chunk(std::size_t{1} << 20);
  std::size_t size = 0;
  for (;;) {
    const ssize_t got = ::read(STDIN_FILENO, chunk.data(), chunk.size());
    if (got == 0) return size;
    if (got < 0) {
      if (errno == EINTR) continue;
      throw RuntimeError("<stdin>: cannot read: " + std::string(std::strerror(errno)));
    }
    if (const int err = file.write_at(chunk.data(), static_cast<std::size_t>(got), static_cast<off_t>(size)))
      throw RuntimeError("<stdin>: cannot copy the piped file to " + in_quotes(file.path()) + ": " + std::strerror(err) +
                         "; set TMPDIR to a directory with space");
    size += static_cast<std::size_t>(got);
  }
}

}  // namespace

H5Input::H5Input(const std::string& path) : path_(path == "-" ? "<stdin>" : path) {
  silence_hdf5();
  if (path == "-") {
    if (closed_at_start(STDIN_FILENO))
      throw UsageError("'-' reads an HDF5 file from stdin, but stdin is closed; pipe or redirect a file in");
    if (isatty(STDIN_FILENO))
      throw UsageError("'-' reads an HDF5 file from stdin, but stdin is a terminal; pipe or redirect a file in");
    // A redirected file is opened as it is; a pipe is copied first.
    std::string name = "/proc/self/fd/0";
    struct stat st {};
    std::size_t size = 0;
    if (fstat(STDIN_FILENO, &st) == 0 && S_ISREG(st.st_mode)) {
      size = static_cast<std::size_t>(st.st_size);
    } else {
      piped_.reset(new ScratchFile(ScratchFile::in_temp_dir("gg.stdin")));  // built in place: ScratchFile cannot move
      size = copy_stdin_to(*piped_);
      name = piped_->path();
    }
    if (size == 0) throw RuntimeError("<stdin>: no data; the command before the pipe wrote nothing (did it fail?)");
    Handle fapl = file_access(false);
    file_ = H5Fopen(name.c_str(), H5F_ACC_RDONLY, fapl.get());
    if (piped_) piped_->drop_name();
    if (file_ < 0)
      throw RuntimeError("<stdin>: not an HDF5 file; pipe in the output of a gg tool written with -o -");
    return;
  }
  struct stat st {};
  if (stat(path.c_str(), &st) != 0)
    throw RuntimeError(in_quotes(path) + ": cannot open: " + std::strerror(errno) + "; check the path");
  if (S_ISDIR(st.st_mode)) throw RuntimeError(in_quotes(path) + ": is a directory; give an HDF5 file");
  if (st.st_size == 0)
    throw RuntimeError(in_quotes(path) + ": empty file (0 bytes); rerun the tool that should have written it");
  if (access(path.c_str(), R_OK) != 0)
    throw RuntimeError(in_quotes(path) + ": cannot read: " + std::strerror(errno) + "; check its permissions");
  // Opened first and asked what it is only if that fails: a file is opened once (a resumed run's
  // checkpoint, read whole for its seal before, twice in all).
  Handle fapl = file_access(false);
  file_ = H5Fopen(path.c_str(), H5F_ACC_RDONLY, fapl.get());
  if (file_ >= 0) return;
  if (H5Fis_hdf5(path.c_str()) <= 0)
    throw RuntimeError(in_quotes(path) + ": not an HDF5 file; give a .h5 file written by a gg tool");
  throw RuntimeError(in_quotes(path) + ": HDF5 file cannot be opened (truncated or damaged?); rewrite it");
}

H5Input::~H5Input() {
  if (file_ >= 0) H5Fclose(file_);
}

std::int64_t H5Input::hid() const { return file_; }

bool H5Input::exists(const std::string& object) const {
  return H5LTpath_valid(file_, absolute(object).c_str(), true) > 0;
}

bool H5Input::is_dataset(const std::string& object) const {
  if (!exists(object)) return false;
  Handle obj(H5Oopen(file_, absolute(object).c_str(), H5P_DEFAULT), H5Oclose);
  return obj.ok() && H5Iget_type(obj.get()) == H5I_DATASET;
}

namespace {

std::string where(const H5Input& in, const std::string& dataset) {
  return in_quotes(in.path()) + ": dataset " + in_quotes(dataset);
}

// Opens a dataset of numbers, or throws naming the file, the dataset and the fix.
Handle open_numeric(const H5Input& in, const std::string& dataset) {
  if (!in.exists(dataset))
    throw RuntimeError(in_quotes(in.path()) + ": no dataset " + in_quotes(dataset) + "; list the file's contents with h5ls -r");
  if (!in.is_dataset(dataset))
    throw RuntimeError(where(in, dataset) + " is a group, not a dataset; name a dataset inside it");
  Handle ds(H5Dopen2(in.hid(), absolute(dataset).c_str(), H5P_DEFAULT), H5Dclose);
  if (!ds.ok()) throw RuntimeError(where(in, dataset) + " cannot be opened (damaged file?)");
  Handle type(H5Dget_type(ds.get()), H5Tclose);
  const H5T_class_t cls = H5Tget_class(type.get());
  if (cls != H5T_INTEGER && cls != H5T_FLOAT)
    throw RuntimeError(where(in, dataset) + " does not hold numbers; name a numeric dataset");
  Handle space(H5Dget_space(ds.get()), H5Sclose);
  if (H5Sget_simple_extent_type(space.get()) == H5S_NULL)
    throw RuntimeError(where(in, dataset) + " holds no data (null dataspace)");
  return ds;
}

std::vector<std::size_t> dataset_shape(hid_t ds) {
  Handle space(H5Dget_space(ds), H5Sclose);
  return shape_of(space.get());
}

// Refuses `values` values of dataset `ds` that the file cannot hold (see check_claim).
void check_dataset_claim(const H5Input& in, hid_t ds, double values, const std::string& where) {
  Handle type(H5Dget_type(ds), H5Tclose);
  check_claim(in.hid(), type.get(), values, where);
}

double value_count(const std::vector<std::size_t>& shape) {
  return std::accumulate(shape.begin(), shape.end(), 1.0, std::multiplies<>());
}

void read_all(hid_t ds, hid_t mem_type, void* buf, std::size_t n, const std::string& where) {
  if (n > 0 && H5Dread(ds, mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, buf) < 0)
    throw RuntimeError(where + ": read failed (damaged file or values out of range)");
}

}  // namespace

std::vector<std::size_t> H5Input::shape(const std::string& dataset) const {
  Handle ds = open_numeric(*this, dataset);
  return dataset_shape(ds.get());
}

Array H5Input::read(const std::string& dataset, int rank) const {
  Handle ds = open_numeric(*this, dataset);
  Array a;
  a.shape = dataset_shape(ds.get());
  if (rank >= 0 && static_cast<int>(a.shape.size()) != rank)
    throw RuntimeError(where(*this, dataset) + " has rank " + std::to_string(a.shape.size()) + " (shape " +
                       shape_text(a.shape) + "), expected rank " + std::to_string(rank) + "; name a matching dataset");
  check_dataset_claim(*this, ds.get(), value_count(a.shape), where(*this, dataset));
  a.data.resize(element_count(a.shape));
  read_all(ds.get(), H5T_NATIVE_DOUBLE, a.data.data(), a.data.size(), where(*this, dataset));
  return a;
}

Array H5Input::read_rows(const std::string& dataset, const std::vector<std::size_t>& rows) const {
  Handle ds = open_numeric(*this, dataset);
  const std::vector<std::size_t> shape = dataset_shape(ds.get());
  if (shape.empty()) throw RuntimeError(where(*this, dataset) + " is a scalar; rows need rank >= 1");
  for (std::size_t row : rows)
    if (row >= shape[0])
      throw RuntimeError(where(*this, dataset) + " has " + std::to_string(shape[0]) + " rows; row " +
                         std::to_string(row) + " does not exist");
  Array a;
  a.shape = shape;
  a.shape[0] = rows.size();
  const std::vector<std::size_t> row_shape(shape.begin() + 1, shape.end());
  check_dataset_claim(*this, ds.get(), static_cast<double>(rows.size()) * value_count(row_shape), where(*this, dataset));
  const std::size_t row_size = element_count(row_shape);
  a.data.resize(rows.size() * row_size);
  if (row_size == 0) return a;
  // One read per row keeps the caller's order (a union of hyperslabs would come back sorted).
  std::vector<hsize_t> start(shape.size(), 0), count(shape.begin(), shape.end());
  count[0] = 1;
  Handle file_space(H5Dget_space(ds.get()), H5Sclose);
  Handle mem_space = dataspace_for({row_size});
  for (std::size_t i = 0; i < rows.size(); ++i) {
    start[0] = rows[i];
    H5Sselect_hyperslab(file_space.get(), H5S_SELECT_SET, start.data(), nullptr, count.data(), nullptr);
    if (H5Dread(ds.get(), H5T_NATIVE_DOUBLE, mem_space.get(), file_space.get(), H5P_DEFAULT,
                a.data.data() + i * row_size) < 0)
      throw RuntimeError(where(*this, dataset) + ": read failed (damaged file?)");
  }
  return a;
}

std::vector<std::int64_t> H5Input::read_int(const std::string& dataset) const {
  Handle ds = open_numeric(*this, dataset);
  const std::vector<std::size_t> shape = dataset_shape(ds.get());
  check_dataset_claim(*this, ds.get(), value_count(shape), where(*this, dataset));
  const std::size_t n = element_count(shape);
  Handle type(H5Dget_type(ds.get()), H5Tclose);
  std::vector<std::int64_t> out(n);
  if (H5Tget_class(type.get()) == H5T_INTEGER) {
    read_all(ds.get(), H5T_NATIVE_INT64, out.data(), n, where(*this, dataset));
    return out;
  }
  std::vector<double> values(n);
  read_all(ds.get(), H5T_NATIVE_DOUBLE, values.data(), n, where(*this, dataset));
  for (std::size_t i = 0; i < n; ++i) {
    // 2^63 bounds the int64 range; values beyond it, or fractional, are not counts.
    if (!(std::fabs(values[i]) < 9.2e18) || values[i] != std::trunc(values[i]))
      throw RuntimeError(where(*this, dataset) + " holds non-integer value " + std::to_string(values[i]) +
                         "; expected integers");
    out[i] = static_cast<std::int64_t>(values[i]);
  }
  return out;
}

namespace {

// Opens attribute `name` of `object`; an invalid handle if either is missing.
Handle open_attr(const H5Input& in, const std::string& object, const std::string& name) {
  if (!in.exists(object) || H5Aexists_by_name(in.hid(), absolute(object).c_str(), name.c_str(), H5P_DEFAULT) <= 0)
    return {-1, H5Aclose};
  return {H5Aopen_by_name(in.hid(), absolute(object).c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose};
}

}  // namespace

std::vector<std::string> H5Input::attr_strings(const std::string& object, const std::string& name) const {
  Handle attr = open_attr(*this, object, name);
  if (!attr.ok()) return {};
  Handle type(H5Aget_type(attr.get()), H5Tclose);
  if (H5Tget_class(type.get()) != H5T_STRING) throw RuntimeError(attr_where(*this, object, name) + " is not a string");
  const std::string where = attr_where(*this, object, name);
  return read_strings(attr.get(), type.get(), attr_count(*this, attr.get(), type.get(), where), where);
}

std::optional<std::string> H5Input::attr_string(const std::string& object, const std::string& name) const {
  if (!open_attr(*this, object, name).ok()) return std::nullopt;
  std::vector<std::string> all = attr_strings(object, name);
  if (all.size() != 1)
    throw RuntimeError(attr_where(*this, object, name) + " holds " + std::to_string(all.size()) + " strings, expected one");
  return all[0];
}

std::vector<double> H5Input::attr_doubles(const std::string& object, const std::string& name) const {
  Handle attr = open_attr(*this, object, name);
  if (!attr.ok()) return {};
  Handle type(H5Aget_type(attr.get()), H5Tclose);
  const H5T_class_t cls = H5Tget_class(type.get());
  if (cls != H5T_INTEGER && cls != H5T_FLOAT) throw RuntimeError(attr_where(*this, object, name) + " is not numeric");
  std::vector<double> values(attr_count(*this, attr.get(), type.get(), attr_where(*this, object, name)));
  if (!values.empty() && H5Aread(attr.get(), H5T_NATIVE_DOUBLE, values.data()) < 0)
    throw RuntimeError(attr_where(*this, object, name) + ": read failed");
  return values;
}

std::optional<double> H5Input::attr_double(const std::string& object, const std::string& name) const {
  if (!open_attr(*this, object, name).ok()) return std::nullopt;
  std::vector<double> all = attr_doubles(object, name);
  if (all.size() != 1)
    throw RuntimeError(attr_where(*this, object, name) + " holds " + std::to_string(all.size()) + " values, expected one");
  return all[0];
}

namespace {

// Names of the links of an open group, sorted.
std::vector<std::string> link_names(hid_t group) {
  H5G_info_t info{};
  if (H5Gget_info(group, &info) < 0) return {};
  std::vector<std::string> names;
  for (hsize_t i = 0; i < info.nlinks; ++i) {
    const ssize_t len = H5Lget_name_by_idx(group, ".", H5_INDEX_NAME, H5_ITER_INC, i, nullptr, 0, H5P_DEFAULT);
    if (len < 0) continue;
    std::string name(static_cast<std::size_t>(len) + 1, '\0');
    H5Lget_name_by_idx(group, ".", H5_INDEX_NAME, H5_ITER_INC, i, name.data(), name.size(), H5P_DEFAULT);
    name.resize(static_cast<std::size_t>(len));
    names.push_back(std::move(name));
  }
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace

std::vector<std::string> H5Input::members(const std::string& group) const {
  if (!exists(group) || is_dataset(group)) return {};
  Handle g(H5Gopen2(file_, absolute(group).c_str(), H5P_DEFAULT), H5Gclose);
  return g.ok() ? link_names(g.get()) : std::vector<std::string>{};
}

namespace {

// Deeper nesting is no file a gg tool or an H5MD writer makes: a provenance lineage adds two levels
// per generation of tools.
constexpr int kMaxDepth = 256;

// The identity of object `name` in `loc` within its file (its address), so that two hard links to
// one object compare equal; empty if there is none.
std::string object_identity(hid_t loc, const char* name) {
#if H5_VERSION_GE(1, 12, 0)
  H5O_info2_t info{};
  if (H5Oget_info_by_name3(loc, name, &info, H5O_INFO_BASIC, H5P_DEFAULT) < 0) return {};
  return std::string(reinterpret_cast<const char*>(&info.token), sizeof info.token);
#else
  H5O_info_t info{};
  if (H5Oget_info_by_name2(loc, name, &info, H5O_INFO_BASIC, H5P_DEFAULT) < 0) return {};
  return std::to_string(info.addr);
#endif
}

// Walks the open `group` (at `path`) by links relative to it: looking every object up by its
// absolute path would cost a walk from the root each time.
void list_below(const H5Input& in, hid_t group, const std::string& path, int depth, std::set<std::string>& seen,
                std::vector<std::string>& out) {
  if (depth > kMaxDepth)
    throw RuntimeError(in_quotes(in.path()) + ": groups nested more than " + std::to_string(kMaxDepth) +
                       " levels deep at " + in_quotes(path) + " (damaged file?); name datasets as FILE.h5:/group/dataset");
  for (const std::string& name : link_names(group)) {
    H5L_info_t link{};
    if (H5Lget_info(group, name.c_str(), &link, H5P_DEFAULT) < 0 || link.type != H5L_TYPE_HARD ||
        !seen.insert(object_identity(group, name.c_str())).second)
      continue;
    Handle child(H5Oopen(group, name.c_str(), H5P_DEFAULT), H5Oclose);
    const H5I_type_t type = child.ok() ? H5Iget_type(child.get()) : H5I_BADID;
    if (type != H5I_GROUP && type != H5I_DATASET) continue;
    const std::string child_path = (path == "/" ? "/" : path + "/") + name;
    out.push_back(child_path);
    if (type == H5I_GROUP) list_below(in, child.get(), child_path, depth + 1, seen, out);
  }
}

}  // namespace

std::vector<std::string> H5Input::objects_below(const std::string& group) const {
  std::vector<std::string> out;
  if (!exists(group) || is_dataset(group)) return out;
  Handle g(H5Gopen2(file_, absolute(group).c_str(), H5P_DEFAULT), H5Gclose);
  std::set<std::string> seen{object_identity(file_, absolute(group).c_str()), ""};  // "": unreadable, skipped
  if (g.ok()) list_below(*this, g.get(), absolute(group), 0, seen, out);
  return out;
}

}  // namespace gg
