#pragma once
// What the HDF5 reader (h5_input.cpp) and writer (h5_output.cpp) share: the handle that closes
// HDF5 identifiers, the pieces of their messages, the refusal of sizes a damaged file claims, and
// the property lists and types both make. Private to ggcommon, like HDF5 itself.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <hdf5.h>

#include "gg/h5file.hpp"

namespace gg::h5detail {

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
void silence_hdf5();

std::string in_quotes(const std::string& s);

std::string shape_text(const std::vector<std::size_t>& shape);

std::size_t element_count(const std::vector<std::size_t>& shape);

// `values` (a double: a product of damaged dimensions may not fit in size_t) of `type` claimed by
// the dataset or attribute `where` of `file`.
void check_claim(hid_t file, hid_t type, double values, const std::string& where);

// Absolute path, so "cluster/time" and "/cluster/time" name the same object.
std::string absolute(const std::string& path);

Handle dataspace_for(const std::vector<std::size_t>& shape);

Handle utf8_string_type();

// File locks buy nothing here (outputs appear by rename) and fail on some cluster filesystems.
Handle file_access(bool strong_close);

std::string attr_where(const H5Input& in, const std::string& object, const std::string& name);

// Elements of attribute `attr` of `type`, refused if the file cannot hold them (see check_claim).
std::size_t attr_count(const H5Input& in, hid_t attr, hid_t type, const std::string& where);

}  // namespace gg::h5detail
