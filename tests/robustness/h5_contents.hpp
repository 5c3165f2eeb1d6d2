#pragma once
// Everything an HDF5 file holds, as a map from "path" (datasets: type, shape and raw bytes) and
// "path@attribute" (attributes: type, shape and value) to bytes, for comparing two files exactly.
// Read with HDF5's C API so that nothing is converted on the way: two entries are equal only if
// the stored values are bit-identical. Groups appear as "path/" (so an empty group counts too).
#include <hdf5.h>

#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace gg::robust {

using Contents = std::map<std::string, std::string>;

namespace detail {

inline std::string type_and_shape(hid_t type, hid_t space) {
  std::string d = "class " + std::to_string(static_cast<int>(H5Tget_class(type))) + " size " +
                  std::to_string(H5Tget_size(type)) + " shape";
  const int rank = H5Sget_simple_extent_ndims(space);
  std::vector<hsize_t> dims(static_cast<std::size_t>(rank > 0 ? rank : 0));
  if (rank > 0) H5Sget_simple_extent_dims(space, dims.data(), nullptr);
  for (hsize_t n : dims) d += ' ' + std::to_string(n);
  if (H5Sget_simple_extent_type(space) == H5S_NULL) d += " null";
  return d + ": ";
}

// Values as bytes: numbers in their native form, variable-length strings spelled out.
template <class ReadFn>
std::string value_bytes(hid_t type, hid_t space, ReadFn read) {
  const hssize_t points = H5Sget_simple_extent_type(space) == H5S_NULL ? 0 : H5Sget_simple_extent_npoints(space);
  if (points <= 0) return {};
  const auto n = static_cast<std::size_t>(points);
  if (H5Tis_variable_str(type) > 0) {
    const hid_t mem = H5Tcopy(H5T_C_S1);
    H5Tset_size(mem, H5T_VARIABLE);
    H5Tset_cset(mem, H5Tget_cset(type));
    std::vector<char*> strings(n, nullptr);
    std::string out;
    if (read(mem, strings.data()) >= 0) {
      for (char* s : strings) out += std::string(s ? s : "<null>") + '\0';
      H5Dvlen_reclaim(mem, space, H5P_DEFAULT, strings.data());
    } else {
      out = "<unreadable>";
    }
    H5Tclose(mem);
    return out;
  }
  const hid_t mem = H5Tget_class(type) == H5T_STRING ? H5Tcopy(type) : H5Tget_native_type(type, H5T_DIR_ASCEND);
  std::string out(n * H5Tget_size(mem), '\0');
  if (read(mem, out.data()) < 0) out = "<unreadable>";
  H5Tclose(mem);
  return out;
}

struct AttrVisit {
  Contents* contents;
  std::string path;
};

inline herr_t add_attribute(hid_t obj, const char* name, const H5A_info_t*, void* data) {
  auto* v = static_cast<AttrVisit*>(data);
  const hid_t attr = H5Aopen(obj, name, H5P_DEFAULT);
  const hid_t type = H5Aget_type(attr), space = H5Aget_space(attr);
  (*v->contents)[v->path + "@" + name] =
      type_and_shape(type, space) + value_bytes(type, space, [&](hid_t mem, void* buf) { return H5Aread(attr, mem, buf); });
  H5Sclose(space);
  H5Tclose(type);
  H5Aclose(attr);
  return 0;
}

inline void add_object(hid_t file, const std::string& path, Contents& contents, int depth) {
  if (depth > 32) throw std::runtime_error("h5_contents: groups nested deeper than 32 at " + path);
  const hid_t obj = H5Oopen(file, path.c_str(), H5P_DEFAULT);
  if (obj < 0) throw std::runtime_error("h5_contents: cannot open " + path);
  AttrVisit visit{&contents, path};
  hsize_t idx = 0;
  H5Aiterate2(obj, H5_INDEX_NAME, H5_ITER_INC, &idx, add_attribute, &visit);
  if (H5Iget_type(obj) == H5I_DATASET) {
    const hid_t type = H5Dget_type(obj), space = H5Dget_space(obj);
    contents[path] = type_and_shape(type, space) + value_bytes(type, space, [&](hid_t mem, void* buf) {
                       return H5Dread(obj, mem, H5S_ALL, H5S_ALL, H5P_DEFAULT, buf);
                     });
    H5Sclose(space);
    H5Tclose(type);
  } else if (H5Iget_type(obj) == H5I_GROUP) {
    contents[path == "/" ? "/" : path + "/"] = "group";
    H5G_info_t info{};
    H5Gget_info(obj, &info);
    std::vector<std::string> names;
    for (hsize_t i = 0; i < info.nlinks; ++i) {
      char name[1024];
      if (H5Lget_name_by_idx(obj, ".", H5_INDEX_NAME, H5_ITER_INC, i, name, sizeof name, H5P_DEFAULT) > 0)
        names.emplace_back(name);
    }
    for (const auto& n : names) add_object(file, (path == "/" ? "/" : path + "/") + n, contents, depth + 1);
  }
  H5Oclose(obj);
}

}  // namespace detail

// Every object and attribute of `file`, except those under one of the `skip` paths.
inline Contents h5_contents(const std::string& file, const std::vector<std::string>& skip = {}) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (f < 0) throw std::runtime_error("h5_contents: cannot open " + file);
  Contents all;
  detail::add_object(f, "/", all, 0);
  H5Fclose(f);
  Contents kept;
  for (auto& [key, value] : all) {
    bool skipped = false;
    for (const auto& s : skip) skipped = skipped || key.rfind(s, 0) == 0;
    if (!skipped) kept.emplace(key, std::move(value));
  }
  return kept;
}

// The keys whose values differ, or that only one side has (at most `max` of them).
inline std::vector<std::string> differences(const Contents& a, const Contents& b, std::size_t max = 10) {
  std::vector<std::string> d;
  for (const auto& [k, v] : a) {
    if (d.size() >= max) return d;
    auto it = b.find(k);
    if (it == b.end()) d.push_back(k + " (only in the first)");
    else if (it->second != v) d.push_back(k);
  }
  for (const auto& [k, v] : b)
    if (d.size() < max && !a.count(k)) d.push_back(k + " (only in the second)");
  return d;
}

}  // namespace gg::robust
