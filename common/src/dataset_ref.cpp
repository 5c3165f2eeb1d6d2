// "file.h5:/group/dataset" on command lines, and the time axis that goes with a dataset.
#include "gg/dataset_ref.hpp"

#include "gg/errors.hpp"
#include "gg/h5file.hpp"

namespace gg {
namespace {

std::string parent_group(const std::string& path) {
  const auto slash = path.find_last_of('/');
  return slash == 0 || slash == std::string::npos ? "" : path.substr(0, slash);
}

}  // namespace

DatasetRef parse_dataset_ref(const std::string& text) {
  // The last ":/" splits, so a file name may itself contain ':' (e.g. "run:3.h5:/cluster/mean_mass").
  const auto split = text.rfind(":/");
  if (split == std::string::npos || split == 0 || split + 2 == text.size())
    throw UsageError("'" + text + "' does not name a dataset; write FILE.h5:/group/dataset");
  return {text.substr(0, split), text.substr(split + 1)};
}

std::string paired_time(const H5Input& in, const std::string& dataset) {
  // docs/DESIGN.md: /g/time, else /g/../time, else the H5MD `time` sibling of `value`. The H5MD
  // layout /g/{step,time,value} puts that sibling at /g/time, so the first rule already finds it.
  const std::string group = parent_group(dataset);
  const std::string candidates[] = {group + "/time", parent_group(group) + "/time"};
  for (const std::string& c : candidates)
    if (in.is_dataset(c)) return c;
  throw RuntimeError("'" + in.path() + "': no time axis for '" + dataset + "' (looked for " + candidates[0] + " and " +
                     candidates[1] + "); name a dataset that sits beside a 'time' dataset");
}

}  // namespace gg
