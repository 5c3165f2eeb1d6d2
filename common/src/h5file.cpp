// HDF5 reading and writing through the C API (the only file that includes HDF5).
// Every message names the file and the dataset, and says what to do, because it ends up as the
// one line a user sees (DESIGN.md "Conventions of every tool").
#include "gg/h5file.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <numeric>
#include <set>
#include <stdexcept>
#include <utility>

#include <hdf5.h>
#include <hdf5_hl.h>  // H5LTpath_valid
#include <sys/stat.h>
#include <unistd.h>

#include "gg/errors.hpp"
#include "gg/scratch_file.hpp"
#include "temp_files.hpp"

namespace gg {
namespace {

static_assert(sizeof(hid_t) == sizeof(std::int64_t), "hid_t is exposed as int64 in h5file.hpp");

// Owns one HDF5 identifier and closes it with the matching H5*close function.
class Handle {
 public:
  Handle(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
  Handle(Handle&& o) noexcept : id_(std::exchange(o.id_, -1)), close_(o.close_) {}
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  Handle& operator=(Handle&&) = delete;
  ~Handle() {
    if (id_ >= 0) close_(id_);
  }
  hid_t get() const { return id_; }
  bool ok() const { return id_ >= 0; }

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

// Our messages replace HDF5's multi-line error stack dumps.
void silence_hdf5() { H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); }

std::string in_quotes(const std::string& s) { return "'" + s + "'"; }

std::string shape_text(const std::vector<std::size_t>& shape) {
  if (shape.empty()) return "scalar";
  std::string t;
  for (std::size_t k = 0; k < shape.size(); ++k) t += (k ? "x" : "") + std::to_string(shape[k]);
  return t;
}

std::size_t element_count(const std::vector<std::size_t>& shape) {
  return std::accumulate(shape.begin(), shape.end(), std::size_t{1}, std::multiplies<>());
}

// "8.8 TB": sizes in the messages about them.
std::string bytes_text(double bytes) {
  const char* units[] = {"bytes", "kB", "MB", "GB", "TB", "PB", "EB"};
  int u = 0;
  for (; bytes >= 1000 && u < 6; ++u) bytes /= 1000;
  char text[32];
  std::snprintf(text, sizeof text, u ? "%.3g %s" : "%.0f %s", bytes, units[u]);
  return text;
}

// A damaged header, or a chunked dataset whose chunks were never written, may claim terabytes in a
// file of a few kB; such a claim is refused before anything is allocated for it. Stored data grow
// at most by the compression ratio of a filter when read, and deflate's best is 1032:1, so values
// of more than 1032 times the file's bytes cannot be data of this file.
constexpr double kMaxExpansion = 1032;

// `values` (a double: a product of damaged dimensions may not fit in size_t) of `type` claimed by
// the dataset or attribute `where` of `file`.
void check_claim(hid_t file, hid_t type, double values, const std::string& where) {
  hsize_t file_size = 0;
  H5Fget_filesize(file, &file_size);
  const double bytes = values * static_cast<double>(H5Tget_size(type));
  if (bytes > kMaxExpansion * static_cast<double>(file_size))
    throw RuntimeError(where + " claims " + bytes_text(bytes) + " of values but the file has only " +
                       bytes_text(static_cast<double>(file_size)) +
                       " (damaged, or its data were never written); rewrite the file");
}

// Absolute path, so "cluster/time" and "/cluster/time" name the same object.
std::string absolute(const std::string& path) { return path.empty() || path[0] != '/' ? "/" + path : path; }

Handle dataspace_for(const std::vector<std::size_t>& shape) {
  if (shape.empty()) return {H5Screate(H5S_SCALAR), H5Sclose};
  const std::vector<hsize_t> dims(shape.begin(), shape.end());
  return {H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr), H5Sclose};
}

std::vector<std::size_t> shape_of(hid_t space) {
  const int rank = H5Sget_simple_extent_ndims(space);
  std::vector<hsize_t> dims(std::max(rank, 0));
  if (rank > 0) H5Sget_simple_extent_dims(space, dims.data(), nullptr);
  return {dims.begin(), dims.end()};
}

Handle utf8_string_type() {
  Handle t(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(t.get(), H5T_VARIABLE);
  H5Tset_cset(t.get(), H5T_CSET_UTF8);
  return t;
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

// File locks buy nothing here (outputs appear by rename) and fail on some cluster filesystems.
Handle file_access(bool strong_close) {
  Handle fapl(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
  H5Pset_file_locking(fapl.get(), false, true);
  if (strong_close) H5Pset_fclose_degree(fapl.get(), H5F_CLOSE_STRONG);
  return fapl;
}

}  // namespace

std::string hdf5_version() {
  unsigned major = 0, minor = 0, release = 0;
  H5get_libversion(&major, &minor, &release);
  return std::to_string(major) + "." + std::to_string(minor) + "." + std::to_string(release);
}

// ---------------------------------------------------------------------------------------------
// H5Input

H5Input::H5Input(const std::string& path) : path_(path == "-" ? "<stdin>" : path) {
  silence_hdf5();
  if (path == "-") {
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
  if (H5Fis_hdf5(path.c_str()) <= 0)
    throw RuntimeError(in_quotes(path) + ": not an HDF5 file; give a .h5 file written by a gg tool");
  Handle fapl = file_access(false);
  file_ = H5Fopen(path.c_str(), H5F_ACC_RDONLY, fapl.get());
  if (file_ < 0) throw RuntimeError(in_quotes(path) + ": HDF5 file cannot be opened (truncated or damaged?); rewrite it");
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

std::string attr_where(const H5Input& in, const std::string& object, const std::string& name) {
  return in_quotes(in.path()) + ": attribute " + in_quotes(name) + " of " + in_quotes(object);
}

// Elements of attribute `attr` of `type`, refused if the file cannot hold them (see check_claim).
std::size_t attr_count(const H5Input& in, hid_t attr, hid_t type, const std::string& where) {
  Handle space(H5Aget_space(attr), H5Sclose);
  const hssize_t n = H5Sget_simple_extent_npoints(space.get());
  if (n <= 0) return 0;
  check_claim(in.hid(), type, static_cast<double>(n), where);
  return static_cast<std::size_t>(n);
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

// ---------------------------------------------------------------------------------------------
// H5Output

namespace {

// Same content -> same bytes: no object timestamps, one fixed file-format version (1.8: readable
// by every HDF5 since 2008, with compact/dense attribute storage so long argv lists fit).
Handle object_create(hid_t cls) {
  Handle p(H5Pcreate(cls), H5Pclose);
  H5Pset_obj_track_times(p.get(), false);
  return p;
}

Handle output_access() {
  Handle fapl = file_access(true);
  H5Pset_libver_bounds(fapl.get(), H5F_LIBVER_V18, H5F_LIBVER_V18);
  return fapl;
}

}  // namespace

H5Output::H5Output(const std::string& path) : path_(path) {
  silence_hdf5();
  if (path.empty()) throw UsageError("empty output file name; give -o FILE.h5 or -o - for stdout");
  std::string create_name;
  if (path == "-") {
    if (isatty(STDOUT_FILENO))
      throw UsageError("'-o -' writes binary HDF5 to stdout, which is a terminal; pipe it into another tool or give a file");
    // Written to a scratch file and copied to stdout when complete (HDF5 must seek while it
    // writes): nothing reaches the pipe unless the file is whole.
    for_stdout_.reset(new ScratchFile(ScratchFile::in_temp_dir("gg.stdout")));
    create_name = for_stdout_->path();
  } else {
    namespace fs = std::filesystem;
    const fs::path target(path);
    std::error_code ec;
    if (fs::is_directory(target, ec)) throw UsageError("output " + in_quotes(path) + " is a directory; give a file name");
    const fs::path dir = target.parent_path().empty() ? fs::path(".") : target.parent_path();
    if (!fs::is_directory(dir, ec))
      throw UsageError("output directory " + in_quotes(dir.string()) + " does not exist; create it first (mkdir -p)");
    if (access(dir.c_str(), W_OK) != 0)
      throw UsageError("output directory " + in_quotes(dir.string()) + " is not writable; choose another -o");
    // Hidden name in the same directory: rename() is then atomic, and a leftover is not taken
    // for a finished output.
    tmp_ = (dir / ("." + target.filename().string() + ".tmp." + std::to_string(getpid()))).string();
    create_name = tmp_;
    detail::track_temp_file(tmp_);
  }
  Handle fcpl = object_create(H5P_FILE_CREATE);
  Handle fapl = output_access();
  file_ = H5Fcreate(create_name.c_str(), H5F_ACC_TRUNC, fcpl.get(), fapl.get());
  if (for_stdout_) for_stdout_->drop_name();
  if (file_ < 0) {
    if (!tmp_.empty()) detail::untrack_temp_file(tmp_);
    throw RuntimeError("cannot create HDF5 file " + in_quotes(path == "-" ? "<stdout>" : tmp_) + "; check disk space");
  }
}

H5Output::~H5Output() {
  if (file_ >= 0) H5Fclose(file_);
  if (!committed_ && !tmp_.empty()) {
    std::remove(tmp_.c_str());
    detail::untrack_temp_file(tmp_);
  }
}

namespace {

void require_open(hid_t file, const std::string& path) {
  if (file < 0) throw std::logic_error("H5Output " + path + ": used after commit()");
}

// Creates every missing group along the absolute `path`, `path` included, without timestamps.
// (Not H5Pset_create_intermediate_group: the groups it makes carry timestamps.)
void create_groups(hid_t file, const std::string& path, const std::string& out_path) {
  std::size_t end = 0;
  do {
    end = std::min(path.find('/', end + 1), path.size());
    const std::string prefix = path.substr(0, end);
    if (H5Lexists(file, prefix.c_str(), H5P_DEFAULT) > 0) continue;
    Handle gcpl = object_create(H5P_GROUP_CREATE);
    Handle g(H5Gcreate2(file, prefix.c_str(), H5P_DEFAULT, gcpl.get(), H5P_DEFAULT), H5Gclose);
    if (!g.ok()) throw RuntimeError("cannot create group " + in_quotes(prefix) + " in " + in_quotes(out_path));
  } while (end < path.size());
}

void create_parents(hid_t file, const std::string& path, const std::string& out_path) {
  const auto slash = path.find_last_of('/');
  if (slash != 0 && slash != std::string::npos) create_groups(file, path.substr(0, slash), out_path);
}

std::string write_failed(const std::string& path, const std::string& out_path) {
  if (out_path == "-")  // the file for stdout is written in $TMPDIR first
    return "cannot write dataset " + in_quotes(path) + " for stdout to its temporary file in " +
           in_quotes(ScratchFile::temp_dir()) + "; free space there or set TMPDIR to a directory with space";
  return "cannot write dataset " + in_quotes(path) + " to " + in_quotes(out_path) + "; check disk space";
}

// A new dataset at the absolute `path`, its values still to be written (all of them: no fill value).
Handle new_dataset(hid_t file, const std::string& out_path, const std::string& path, hid_t file_type,
                   const std::vector<std::size_t>& shape) {
  create_parents(file, path, out_path);
  if (H5Lexists(file, path.c_str(), H5P_DEFAULT) > 0)
    throw std::logic_error("H5Output: " + path + " written twice in " + out_path);
  Handle space = dataspace_for(shape);
  Handle dcpl = object_create(H5P_DATASET_CREATE);
  H5Pset_fill_time(dcpl.get(), H5D_FILL_TIME_NEVER);  // every element is written right away
  Handle ds(H5Dcreate2(file, path.c_str(), file_type, space.get(), H5P_DEFAULT, dcpl.get(), H5P_DEFAULT), H5Dclose);
  if (!ds.ok()) throw RuntimeError(write_failed(path, out_path));
  return ds;
}

void create_dataset(hid_t file, const std::string& out_path, const std::string& dataset, hid_t file_type,
                    hid_t mem_type, const std::vector<std::size_t>& shape, const void* data, std::size_t n) {
  const std::string path = absolute(dataset);
  if (n != element_count(shape))
    throw std::invalid_argument("H5Output: " + path + " has " + std::to_string(n) + " values for shape " +
                                shape_text(shape));
  Handle ds = new_dataset(file, out_path, path, file_type, shape);
  if (n > 0 && H5Dwrite(ds.get(), mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) < 0)
    throw RuntimeError(write_failed(path, out_path));
}

// Writes attribute `name` on `object` (created as a group if missing), replacing an old one.
void write_attr(hid_t file, const std::string& out_path, const std::string& object, const std::string& name,
                hid_t file_type, hid_t mem_type, const std::vector<std::size_t>& shape, const void* data) {
  const std::string path = absolute(object);
  if (H5LTpath_valid(file, path.c_str(), true) <= 0) create_groups(file, path, out_path);
  if (H5Aexists_by_name(file, path.c_str(), name.c_str(), H5P_DEFAULT) > 0)
    H5Adelete_by_name(file, path.c_str(), name.c_str(), H5P_DEFAULT);
  // HDF5 refuses zero-sized simple dataspaces for attributes; an empty list gets a null one.
  const bool empty = element_count(shape) == 0;
  Handle space = empty ? Handle(H5Screate(H5S_NULL), H5Sclose) : dataspace_for(shape);
  Handle attr(H5Acreate_by_name(file, path.c_str(), name.c_str(), file_type, space.get(), H5P_DEFAULT, H5P_DEFAULT,
                                H5P_DEFAULT),
              H5Aclose);
  if (!attr.ok() || (!empty && H5Awrite(attr.get(), mem_type, data) < 0))
    throw RuntimeError("cannot write attribute " + in_quotes(name) + " of " + in_quotes(path) + " to " + in_quotes(out_path));
}

}  // namespace

void H5Output::write(const std::string& dataset, const Array& a) {
  require_open(file_, path_);
  create_dataset(file_, path_, dataset, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, a.shape, a.data.data(), a.data.size());
}

void H5Output::write(const std::string& dataset, const std::vector<double>& values) {
  write(dataset, Array{{values.size()}, values});
}

void H5Output::write(const std::string& dataset, const std::vector<std::int64_t>& values) {
  require_open(file_, path_);
  create_dataset(file_, path_, dataset, H5T_STD_I64LE, H5T_NATIVE_INT64, {values.size()}, values.data(),
                 values.size());
}

void H5Output::write_float(const std::string& dataset, const Array& a) {
  require_open(file_, path_);
  const std::vector<float> narrow(a.data.begin(), a.data.end());
  create_dataset(file_, path_, dataset, H5T_IEEE_F32LE, H5T_NATIVE_FLOAT, a.shape, narrow.data(), narrow.size());
}

void H5Output::write_rows(const std::string& dataset, const std::vector<std::size_t>& shape, const RowFill& fill,
                          bool single_precision) {
  require_open(file_, path_);
  if (shape.empty()) throw std::invalid_argument("H5Output::write_rows: " + dataset + " needs a shape of rank >= 1");
  const std::string path = absolute(dataset);
  Handle ds = new_dataset(file_, path_, path, single_precision ? H5T_IEEE_F32LE : H5T_IEEE_F64LE, shape);
  const std::vector<std::size_t> row_shape(shape.begin() + 1, shape.end());
  const std::size_t n = element_count(row_shape);
  if (n == 0) return;
  std::vector<double> row(n);
  std::vector<float> narrow(single_precision ? n : 0);
  Handle file_space(H5Dget_space(ds.get()), H5Sclose);
  Handle row_space = dataspace_for(row_shape);
  std::vector<hsize_t> start(shape.size(), 0), count(shape.begin(), shape.end());
  count[0] = 1;
  for (std::size_t k = 0; k < shape[0]; ++k) {
    fill(k, row.data());
    if (single_precision) std::copy(row.begin(), row.end(), narrow.begin());
    start[0] = k;
    if (H5Sselect_hyperslab(file_space.get(), H5S_SELECT_SET, start.data(), nullptr, count.data(), nullptr) < 0 ||
        H5Dwrite(ds.get(), single_precision ? H5T_NATIVE_FLOAT : H5T_NATIVE_DOUBLE, row_space.get(), file_space.get(),
                 H5P_DEFAULT, single_precision ? static_cast<const void*>(narrow.data()) : row.data()) < 0)
      throw RuntimeError(write_failed(path, path_));
  }
}

void H5Output::write_scalar(const std::string& dataset, double value) {
  require_open(file_, path_);
  create_dataset(file_, path_, dataset, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, {}, &value, 1);
}

void H5Output::write_scalar(const std::string& dataset, std::int64_t value) {
  require_open(file_, path_);
  create_dataset(file_, path_, dataset, H5T_STD_I64LE, H5T_NATIVE_INT64, {}, &value, 1);
}

void H5Output::create_group(const std::string& group) {
  require_open(file_, path_);
  const std::string path = absolute(group);
  if (path != "/") create_groups(file_, path, path_);
}

void H5Output::attr(const std::string& object, const std::string& name, const std::string& value) {
  require_open(file_, path_);
  Handle type = utf8_string_type();
  const char* p = value.c_str();
  write_attr(file_, path_, object, name, type.get(), type.get(), {}, &p);
}

void H5Output::attr(const std::string& object, const std::string& name, double value) {
  require_open(file_, path_);
  write_attr(file_, path_, object, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, {}, &value);
}

void H5Output::attr(const std::string& object, const std::string& name, std::int64_t value) {
  require_open(file_, path_);
  write_attr(file_, path_, object, name, H5T_STD_I64LE, H5T_NATIVE_INT64, {}, &value);
}

void H5Output::attr(const std::string& object, const std::string& name, std::uint64_t value) {
  require_open(file_, path_);
  write_attr(file_, path_, object, name, H5T_STD_U64LE, H5T_NATIVE_UINT64, {}, &value);
}

void H5Output::attr(const std::string& object, const std::string& name, const std::vector<double>& value) {
  require_open(file_, path_);
  write_attr(file_, path_, object, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, {value.size()}, value.data());
}

void H5Output::attr(const std::string& object, const std::string& name, const std::vector<std::int64_t>& value) {
  require_open(file_, path_);
  write_attr(file_, path_, object, name, H5T_STD_I64LE, H5T_NATIVE_INT64, {value.size()}, value.data());
}

void H5Output::attr(const std::string& object, const std::string& name, const std::vector<std::string>& value) {
  require_open(file_, path_);
  Handle type = utf8_string_type();
  std::vector<const char*> ptrs;
  for (const std::string& s : value) ptrs.push_back(s.c_str());
  write_attr(file_, path_, object, name, type.get(), type.get(), {value.size()}, ptrs.data());
}

namespace {

herr_t collect_name(hid_t, const char* name, const H5A_info_t*, void* names) {
  static_cast<std::vector<std::string>*>(names)->push_back(name);
  return 0;
}

// Copies the attributes of object `from` of `src` onto object `to` of `out`, each read into memory
// (in the native form of its type) and written again.
void copy_attributes(const H5Input& src, const std::string& from, hid_t out, const std::string& to,
                     const std::string& out_path) {
  Handle s(H5Oopen(src.hid(), from.c_str(), H5P_DEFAULT), H5Oclose);
  Handle d(H5Oopen(out, to.c_str(), H5P_DEFAULT), H5Oclose);
  std::vector<std::string> names;
  hsize_t next = 0;
  if (!s.ok() || !d.ok() || H5Aiterate2(s.get(), H5_INDEX_NAME, H5_ITER_INC, &next, collect_name, &names) < 0)
    throw RuntimeError("cannot copy the attributes of " + in_quotes(from) + " of " + in_quotes(src.path()) +
                       " (damaged file?); rewrite it");
  for (const std::string& name : names) {
    const std::string where = attr_where(src, from, name);
    Handle attr(H5Aopen(s.get(), name.c_str(), H5P_DEFAULT), H5Aclose);
    Handle type(H5Aget_type(attr.get()), H5Tclose);
    if (H5Tdetect_class(type.get(), H5T_REFERENCE) > 0) continue;  // would point into the input file
    Handle mem(H5Tget_native_type(type.get(), H5T_DIR_ASCEND), H5Tclose);
    Handle space(H5Aget_space(attr.get()), H5Sclose);
    if (!attr.ok() || !mem.ok() || !space.ok()) throw RuntimeError(where + " cannot be read (damaged file?); rewrite it");
    std::vector<char> buf(attr_count(src, attr.get(), type.get(), where) * H5Tget_size(mem.get()));
    Handle copy(H5Acreate2(d.get(), name.c_str(), type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
    // An empty attribute (null dataspace) has no values to read or write.
    const bool read = !buf.empty() && H5Aread(attr.get(), mem.get(), buf.data()) >= 0;
    const bool ok = copy.ok() && (buf.empty() || (read && H5Awrite(copy.get(), mem.get(), buf.data()) >= 0));
    if (read) H5Dvlen_reclaim(mem.get(), space.get(), H5P_DEFAULT, buf.data());  // frees variable-length strings
    if (!ok) throw RuntimeError("cannot copy " + where + " to " + in_quotes(out_path) + " (damaged input?)");
  }
}

}  // namespace

void H5Output::copy_from(const H5Input& src, const std::string& object, const std::string& dest) {
  require_open(file_, path_);
  if (!src.exists(object))
    throw RuntimeError(in_quotes(src.path()) + ": no object " + in_quotes(object) + " to copy; list the file with h5ls -r");
  const std::string from = absolute(object), target = absolute(dest);
  create_parents(file_, target, path_);
  // The objects without their attributes, then the attributes one by one: HDF5 before 1.14.4
  // crashes copying variable-length strings kept in dense attribute storage, i.e. on an object with
  // more than 8 attributes (HDFGroup/hdf5#2414).
  Handle ocpypl(H5Pcreate(H5P_OBJECT_COPY), H5Pclose);
  H5Pset_copy_object(ocpypl.get(), H5O_COPY_WITHOUT_ATTR_FLAG);
  if (H5Ocopy(src.hid(), from.c_str(), file_, target.c_str(), ocpypl.get(), H5P_DEFAULT) < 0)
    throw RuntimeError("cannot copy " + in_quotes(object) + " of " + in_quotes(src.path()) + " to " + in_quotes(target) +
                       " in " + in_quotes(path_) + " (damaged input file?)");
  copy_attributes(src, from, file_, target, path_);
  // H5Ocopy copied the tree of hard links, each object once: the same objects as objects_below.
  for (const std::string& p : src.objects_below(from))
    copy_attributes(src, p, file_, target + (from == "/" ? p : p.substr(from.size())), path_);
}

void H5Output::commit() {
  require_open(file_, path_);
  if (path_ == "-") {
    const ScratchFile& f = *for_stdout_;
    if (H5Fclose(std::exchange(file_, -1)) < 0)
      throw RuntimeError("cannot finish the HDF5 file for stdout in " + in_quotes(f.path()) + "; set TMPDIR to a directory with space");
    struct stat st {};
    if (fstat(f.fd(), &st) != 0) throw RuntimeError("cannot read back the HDF5 file for stdout: " + std::string(std::strerror(errno)));
    std::vector<char> chunk(std::size_t{1} << 20);
    for (off_t at = 0; at < st.st_size;) {
      const std::size_t n = static_cast<std::size_t>(std::min<off_t>(st.st_size - at, static_cast<off_t>(chunk.size())));
      if (const int err = f.read_at(chunk.data(), n, at))
        throw RuntimeError("cannot read back the HDF5 file for stdout: " + std::string(err > 0 ? std::strerror(err) : "it is shorter than written"));
      if (std::fwrite(chunk.data(), 1, n, stdout) != n)
        throw RuntimeError("cannot write the HDF5 file to stdout: " + std::string(std::strerror(errno)));
      at += static_cast<off_t>(n);
    }
    if (std::fflush(stdout) != 0) throw RuntimeError("cannot write the HDF5 file to stdout: " + std::string(std::strerror(errno)));
    committed_ = true;
    return;
  }
  if (H5Fclose(std::exchange(file_, -1)) < 0)
    throw RuntimeError("cannot finish writing " + in_quotes(tmp_) + "; check disk space");
  if (std::rename(tmp_.c_str(), path_.c_str()) != 0)
    throw RuntimeError("cannot rename " + in_quotes(tmp_) + " to " + in_quotes(path_) + ": " + std::strerror(errno));
  committed_ = true;
  detail::untrack_temp_file(tmp_);
}

}  // namespace gg
