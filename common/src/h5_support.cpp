#include "h5_support.hpp"

#include <cstdio>
#include <numeric>

#include "gg/errors.hpp"

namespace gg {
namespace h5detail {
namespace {

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

}  // namespace

void silence_hdf5() { H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); }

std::string in_quotes(const std::string& s) { return "'" + s + "'"; }

std::string shape_text(const std::vector<std::size_t>& shape) {
  if (shape.empty()) return "scalar";
  std::string t;
  // Appended piece by piece: a short literal + a temporary string trips GCC 12's false -Wrestrict.
  for (std::size_t k = 0; k < shape.size(); ++k) {
    if (k) t += 'x';
    t += std::to_string(shape[k]);
  }
  return t;
}

std::size_t element_count(const std::vector<std::size_t>& shape) {
  return std::accumulate(shape.begin(), shape.end(), std::size_t{1}, std::multiplies<>());
}

void check_claim(hid_t file, hid_t type, double values, const std::string& where) {
  hsize_t file_size = 0;
  H5Fget_filesize(file, &file_size);
  const double bytes = values * static_cast<double>(H5Tget_size(type));
  if (bytes > kMaxExpansion * static_cast<double>(file_size))
    throw RuntimeError(where + " claims " + bytes_text(bytes) + " of values but the file has only " +
                       bytes_text(static_cast<double>(file_size)) +
                       " (damaged, or its data were never written); rewrite the file");
}

std::string absolute(const std::string& path) { return path.empty() || path[0] != '/' ? "/" + path : path; }

Handle dataspace_for(const std::vector<std::size_t>& shape) {
  if (shape.empty()) return {H5Screate(H5S_SCALAR), H5Sclose};
  const std::vector<hsize_t> dims(shape.begin(), shape.end());
  return {H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr), H5Sclose};
}

Handle utf8_string_type() {
  Handle t(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(t.get(), H5T_VARIABLE);
  H5Tset_cset(t.get(), H5T_CSET_UTF8);
  return t;
}

Handle file_access(bool strong_close) {
  Handle fapl(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
  H5Pset_file_locking(fapl.get(), false, true);
  if (strong_close) H5Pset_fclose_degree(fapl.get(), H5F_CLOSE_STRONG);
  return fapl;
}

std::string attr_where(const H5Input& in, const std::string& object, const std::string& name) {
  return in_quotes(in.path()) + ": attribute " + in_quotes(name) + " of " + in_quotes(object);
}

std::size_t attr_count(const H5Input& in, hid_t attr, hid_t type, const std::string& where) {
  Handle space(H5Aget_space(attr), H5Sclose);
  const hssize_t n = H5Sget_simple_extent_npoints(space.get());
  if (n <= 0) return 0;
  check_claim(in.hid(), type, static_cast<double>(n), where);
  return static_cast<std::size_t>(n);
}

}  // namespace h5detail

std::string hdf5_version() {
  unsigned major = 0, minor = 0, release = 0;
  H5get_libversion(&major, &minor, &release);
  return std::to_string(major) + "." + std::to_string(minor) + "." + std::to_string(release);
}

}  // namespace gg
