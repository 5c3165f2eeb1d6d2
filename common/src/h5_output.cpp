// H5Output: writing HDF5 files through the C API, published whole (by rename, or to stdout).
// Every message names the file and the dataset, and says what to do, because it ends up as the
// one line a user sees (docs/DESIGN.md "Conventions of every tool").
#include "gg/h5file.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <utility>

#include <hdf5.h>
#include <hdf5_hl.h>  // H5LTpath_valid
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "gg/dataset_ref.hpp"
#include "gg/errors.hpp"
#include "gg/scratch_file.hpp"
#include "gg/seal.hpp"
#include "h5_support.hpp"
#include "output_target.hpp"
#include "temp_files.hpp"

namespace gg {

using namespace h5detail;

namespace {

// Same content -> same bytes: no object timestamps, one fixed file-format version (1.8: readable
// by every HDF5 since 2008, with compact/dense attribute storage so long argv lists fit).
constexpr unsigned kCompactLinks = 64;

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

H5Output::H5Output(const std::string& path, bool sealed) : path_(path), sealed_(sealed) {
  silence_hdf5();
  const detail::OutputTarget target = detail::resolve_output(path);
  std::string create_name;
  if (target.kind != detail::OutputTarget::kFile) {
    // Written to a scratch file and copied out when complete (HDF5 must seek while it writes):
    // nothing reaches the stream unless the file is whole.
    stream_.reset(new ScratchFile(ScratchFile::in_temp_dir("gg.stream")));
    stream_to_ = target.kind == detail::OutputTarget::kStream ? target.path : std::string();
    create_name = stream_->path();
  } else {
    namespace fs = std::filesystem;
    final_ = target.path;
    // Hidden name in the same directory: rename() is then atomic, and a leftover is not taken
    // for a finished output. ('.' a char: "." + a temporary string trips GCC 12's false -Wrestrict.)
    tmp_ = (fs::path(target.dir) / ('.' + fs::path(final_).filename().string() + ".tmp." + std::to_string(getpid()))).string();
    create_name = tmp_;
    detail::track_temp_file(tmp_);
  }
  Handle fcpl = object_create(H5P_FILE_CREATE);
  if (sealed_) H5Pset_userblock(fcpl.get(), kSealBytes);
  Handle fapl = output_access();
  errno = 0;
  file_ = H5Fcreate(create_name.c_str(), H5F_ACC_TRUNC, fcpl.get(), fapl.get());
  const int why = errno;
  if (stream_) stream_->drop_name();
  if (file_ < 0) {
    const std::string reason = why != 0 ? std::string(" (") + std::strerror(why) + ")" : std::string();
    if (stream_) throw RuntimeError("cannot create the HDF5 file for " + in_quotes(path) + " in " + in_quotes(stream_->path()) +
                                    reason + "; set TMPDIR to a directory with space");
    detail::untrack_temp_file(tmp_);
    throw RuntimeError("cannot create a file in " + in_quotes(std::filesystem::path(tmp_).parent_path().string()) + " for " +
                       in_quotes(path) + reason + "; choose a directory you can write to, or free space there");
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
    // Links kept in the group's header up to kCompactLinks (HDF5's default: 8): a group of more goes to a
    // fractal heap, whose damage HDF5 1.10 does not survive (a crash in H5Lget_name_by_idx where a
    // header's damage is refused), and an analysis group holds a dozen datasets.
    H5Pset_link_phase_change(gcpl.get(), kCompactLinks, kCompactLinks - 8);
    Handle g(H5Gcreate2(file, prefix.c_str(), H5P_DEFAULT, gcpl.get(), H5P_DEFAULT), H5Gclose);
    if (!g.ok()) throw RuntimeError("cannot create group " + in_quotes(prefix) + " in " + in_quotes(out_path));
  } while (end < path.size());
}

void create_parents(hid_t file, const std::string& path, const std::string& out_path) {
  const auto slash = path.find_last_of('/');
  if (slash != 0 && slash != std::string::npos) create_groups(file, path.substr(0, slash), out_path);
}

std::string write_failed(const std::string& path, const std::string& out_path) {
  if (out_path == "-")  // the file for stdout is written in $TMPDIR first (so is one for a stream)
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

namespace {

// write_rows with the rows stored as `Stored` (file type `file_type`, memory type `mem_type`).
template <class Stored>
void write_rows_as(hid_t file, const std::string& out_path, const std::string& dataset,
                   const std::vector<std::size_t>& shape, const H5Output::RowFill& fill, hid_t file_type,
                   hid_t mem_type) {
  if (shape.empty()) throw std::invalid_argument("H5Output::write_rows: " + dataset + " needs a shape of rank >= 1");
  const std::string path = absolute(dataset);
  Handle ds = new_dataset(file, out_path, path, file_type, shape);
  const std::vector<std::size_t> row_shape(shape.begin() + 1, shape.end());
  const std::size_t n = element_count(row_shape);
  if (n == 0) return;
  std::vector<double> row(n);
  std::vector<Stored> stored(n);
  Handle file_space(H5Dget_space(ds.get()), H5Sclose);
  Handle row_space = dataspace_for(row_shape);
  std::vector<hsize_t> start(shape.size(), 0), count(shape.begin(), shape.end());
  count[0] = 1;
  for (std::size_t k = 0; k < shape[0]; ++k) {
    fill(k, row.data());
    std::transform(row.begin(), row.end(), stored.begin(), [](double x) { return static_cast<Stored>(x); });
    start[0] = k;
    if (H5Sselect_hyperslab(file_space.get(), H5S_SELECT_SET, start.data(), nullptr, count.data(), nullptr) < 0 ||
        H5Dwrite(ds.get(), mem_type, row_space.get(), file_space.get(), H5P_DEFAULT, stored.data()) < 0)
      throw RuntimeError(write_failed(path, out_path));
  }
}

}  // namespace

void H5Output::write_rows(const std::string& dataset, const std::vector<std::size_t>& shape, const RowFill& fill,
                          bool single_precision) {
  require_open(file_, path_);
  if (single_precision) write_rows_as<float>(file_, path_, dataset, shape, fill, H5T_IEEE_F32LE, H5T_NATIVE_FLOAT);
  else write_rows_as<double>(file_, path_, dataset, shape, fill, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE);
}

void H5Output::write_int_rows(const std::string& dataset, const std::vector<std::size_t>& shape, const RowFill& fill) {
  require_open(file_, path_);
  write_rows_as<std::int32_t>(file_, path_, dataset, shape, fill, H5T_STD_I32LE, H5T_NATIVE_INT32);
}

void H5Output::link(const std::string& object, const std::string& name) {
  require_open(file_, path_);
  const std::string target = absolute(object), path = absolute(name);
  create_parents(file_, path, path_);
  if (H5Lcreate_hard(file_, target.c_str(), file_, path.c_str(), H5P_DEFAULT, H5P_DEFAULT) < 0)
    throw RuntimeError("cannot link " + in_quotes(path) + " to " + in_quotes(target) + " in " + in_quotes(path_));
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

namespace {

// Copies the finished file for a stream (built in `f`) to descriptor `fd`; `name` is for messages.
void copy_out(const ScratchFile& f, int fd, const std::string& name) {
  struct stat st {};
  if (fstat(f.fd(), &st) != 0) throw RuntimeError("cannot read back the HDF5 file for " + name + ": " + std::strerror(errno));
  std::vector<char> chunk(std::size_t{1} << 20);
  for (off_t at = 0; at < st.st_size;) {
    const std::size_t n = static_cast<std::size_t>(std::min<off_t>(st.st_size - at, static_cast<off_t>(chunk.size())));
    if (const int err = f.read_at(chunk.data(), n, at))
      throw RuntimeError("cannot read back the HDF5 file for " + name + ": " +
                         std::string(err > 0 ? std::strerror(err) : "it is shorter than written"));
    for (std::size_t done = 0; done < n;) {
      const ssize_t wrote = ::write(fd, chunk.data() + done, n - done);
      if (wrote < 0 && errno == EINTR) continue;
      if (wrote <= 0)
        throw RuntimeError("cannot write the HDF5 file to " + name + ": " + std::strerror(wrote < 0 ? errno : ENOSPC));
      done += static_cast<std::size_t>(wrote);
    }
    at += static_cast<off_t>(n);
  }
}

}  // namespace

void H5Output::commit() {
  require_open(file_, path_);
  if (stream_) {
    const std::string name = stream_to_.empty() ? "stdout" : in_quotes(stream_to_);
    if (H5Fclose(std::exchange(file_, -1)) < 0)
      throw RuntimeError("cannot finish the HDF5 file for " + name + " in " + in_quotes(stream_->path()) +
                         "; set TMPDIR to a directory with space");
    if (stream_to_.empty()) {
      std::fflush(stdout);
      copy_out(*stream_, STDOUT_FILENO, name);
    } else {
      const int fd = open(stream_to_.c_str(), O_WRONLY | O_NOCTTY | O_CLOEXEC);
      if (fd < 0) throw RuntimeError("cannot open " + name + " for writing: " + std::strerror(errno));
      try {
        copy_out(*stream_, fd, name);
      } catch (...) {
        close(fd);
        throw;
      }
      if (close(fd) != 0) throw RuntimeError("cannot write the HDF5 file to " + name + ": " + std::strerror(errno));
    }
    committed_ = true;
    return;
  }
  if (H5Fclose(std::exchange(file_, -1)) < 0)
    throw RuntimeError("cannot finish writing " + in_quotes(tmp_) + "; check disk space");
  if (sealed_) {
    const int fd = open(tmp_.c_str(), O_RDWR | O_CLOEXEC);
    if (fd < 0) throw RuntimeError("cannot reopen " + in_quotes(tmp_) + " to seal it: " + std::strerror(errno));
    try {
      write_seal(fd, in_quotes(tmp_));
    } catch (...) {
      close(fd);
      throw;
    }
    close(fd);
  }
  if (std::rename(tmp_.c_str(), final_.c_str()) != 0)
    throw RuntimeError("cannot rename " + in_quotes(tmp_) + " to " + in_quotes(final_) + ": " + std::strerror(errno) +
                       "; nothing was replaced");
  committed_ = true;
  detail::untrack_temp_file(tmp_);
}

bool is_stream_output(const std::string& path) {
  struct stat st {};
  return path == "-" || (stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode) && !S_ISDIR(st.st_mode));
}

std::string scratch_dir_for_output(const std::string& path) {
  const detail::OutputTarget target = detail::resolve_output(path);
  return target.kind == detail::OutputTarget::kFile ? target.dir : ScratchFile::temp_dir();
}

void require_writable_output(const std::string& path, const std::string& flag) {
  detail::OutputTarget target;
  try {
    target = detail::resolve_output(path);
  } catch (const UsageError& e) {
    if (path == "-") throw;  // its message names -o - already
    throw UsageError(flag + " " + in_quotes(path) + ": " + e.what());
  }
  if (target.kind != detail::OutputTarget::kFile) return;
  // What the end of the run will do there, tried now: create a file, rename it, remove it.
  std::string probe = (std::filesystem::path(target.dir) / ".gg-probe.XXXXXX").string();
  const int fd = mkostemp(probe.data(), O_CLOEXEC);
  if (fd < 0)
    throw UsageError(flag + " " + in_quotes(path) + ": cannot create a file in " + in_quotes(target.dir) + " (" +
                     std::strerror(errno) + "); choose a directory you can write to");
  close(fd);
  const std::string moved = probe + ".renamed";
  const bool renamed = std::rename(probe.c_str(), moved.c_str()) == 0;
  const int err = errno;
  std::remove(renamed ? moved.c_str() : probe.c_str());
  if (!renamed)
    throw UsageError(flag + " " + in_quotes(path) + ": files cannot be renamed in " + in_quotes(target.dir) + " (" +
                     std::strerror(err) + "), which finishing an output needs; choose another directory");
}

bool same_file(const std::string& a, const std::string& b) {
  namespace fs = std::filesystem;
  if (a.empty() || b.empty() || a == "-" || b == "-") return false;
  std::error_code ea, eb;
  if (fs::exists(a, ea) && fs::exists(b, eb)) return fs::equivalent(a, b, ea);
  const fs::path pa = fs::weakly_canonical(a, ea), pb = fs::weakly_canonical(b, eb);
  return !ea && !eb && pa == pb;
}

void require_output_is_not_an_input(const std::string& output, const std::vector<std::string>& inputs) {
  namespace fs = std::filesystem;
  for (const std::string& input : inputs) {
    std::error_code ec;
    // "dir:/x.h5" may be a plain file in a directory named "dir:", so only a name that is not
    // itself an existing file is read as FILE:/dataset.
    const std::string file =
        input.find(":/") == std::string::npos || fs::exists(input, ec) ? input : parse_dataset_ref(input).file;
    if (same_file(file, output))
      throw UsageError("output " + in_quotes(output) + " is also an input" +
                       (file == output ? "" : " (" + in_quotes(file) + ")") +
                       ": it would be replaced; choose another -o");
  }
}

}  // namespace gg
