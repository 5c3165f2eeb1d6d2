#pragma once
// Naming a dataset on a command line: "file.h5:/group/dataset" (docs/DESIGN.md).
// Its time axis is the `time` dataset in the same group, or in the parent group, or the H5MD
// `time` sibling of `value`.
#include <string>
#include <vector>

namespace gg {
class H5Input;

struct DatasetRef {
  std::string file;     // "-" allowed
  std::string dataset;  // absolute path inside the file
};

// Splits at the last ':' followed by '/'. Throws UsageError if there is no ":/".
DatasetRef parse_dataset_ref(const std::string& text);

// Path of the time dataset paired with `dataset`; throws RuntimeError if none exists.
std::string paired_time(const H5Input& in, const std::string& dataset);

}  // namespace gg
