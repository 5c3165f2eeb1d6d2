// Provenance of every output (docs/DESIGN.md "Conventions of every tool").
#include "gg/provenance.hpp"

#include <ctime>
#include <iostream>
#include <optional>
#include <string_view>

#include <fftw3.h>
#include <gsl/gsl_version.h>

#include "gg/errors.hpp"
#include "gg/h5file.hpp"
#include "gg/version.hpp"

namespace gg {
namespace {

const std::string kGroup = "/parameters/provenance";

}  // namespace

std::string utc_now_iso8601() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

namespace {

// fftw_version reads "fftw-3.3.10-sse2-avx"; keep "3.3.10".
std::string fftw_release() {
  std::string_view v = fftw_version;
  if (v.starts_with("fftw-")) v.remove_prefix(5);
  return std::string(v.substr(0, v.find('-')));
}

}  // namespace

std::string library_versions() {
  return "HDF5 " + hdf5_version() + ", FFTW " + fftw_release() + ", GSL " + gsl_version;
}

namespace {

// How the run that wrote `in` ended, if it ended early: gg-sim's /parameters/stop_reason
// "interrupted" or "collapse" ("" otherwise, or if the file has no such attribute).
std::string early_stop(const H5Input& in) {
  try {
    const std::optional<std::string> why = in.attr_string("/parameters", "stop_reason");
    if (why && (*why == "interrupted" || *why == "collapse")) return *why;
  } catch (const RuntimeError&) {  // not ours to judge: a file from elsewhere
  }
  return {};
}

// The early-stopped runs behind `in` that its own provenance lists (an analysis of an analysis).
std::vector<std::string> early_stops_behind(const H5Input& in) {
  try {
    return in.attr_strings(kGroup, "incomplete_inputs");
  } catch (const RuntimeError&) {
    return {};
  }
}

}  // namespace

void write_provenance(H5Output& out, const Provenance& p, const std::vector<const H5Input*>& inputs) {
  out.attr(kGroup, "program", p.program);
  out.attr(kGroup, "version", std::string(kVersion));
  out.attr(kGroup, "git_hash", std::string(kGitHash));
  out.attr(kGroup, "argv", p.argv);
  out.attr(kGroup, "utc_time", utc_now_iso8601());
  if (p.seed) out.attr(kGroup, "seed", *p.seed);
  out.attr(kGroup, "libraries", library_versions());
  // inputs/<k> exists for every input, so k always matches the input's position; it holds the
  // input's own provenance (with that file's inputs, hence the whole lineage) when it has one.
  for (std::size_t k = 0; k < inputs.size(); ++k) {
    const std::string dest = kGroup + "/inputs/" + std::to_string(k);
    if (inputs[k]->exists(kGroup))
      out.copy_from(*inputs[k], kGroup, dest);
    else
      out.create_group(dest);
    out.attr(dest, "file", inputs[k]->path());
  }
  // An input from a run that stopped early (Ctrl-C, a time limit, a collapse) holds less than its
  // scene asked for: the analysis says so on stderr and in its output, and so does every analysis
  // of that analysis.
  std::vector<std::string> incomplete;
  for (const H5Input* in : inputs) {
    if (const std::string why = early_stop(*in); !why.empty()) {
      incomplete.push_back(in->path() + ": stop_reason = " + why);
      std::cerr << p.program << ": warning: " << in->path() << " is from a run that stopped early (stop_reason = "
                << why << "), so it holds less than its scene asked for; the output records this in "
                << kGroup << "/incomplete_inputs\n";
    }
    const std::vector<std::string> behind = early_stops_behind(*in);
    if (!behind.empty())
      std::cerr << p.program << ": warning: " << in->path() << " was made from a run that stopped early (" << behind.front()
                << (behind.size() > 1 ? ", and more" : "") << "); the output records this in " << kGroup
                << "/incomplete_inputs\n";
    for (const std::string& b : behind) incomplete.push_back(in->path() + " <- " + b);
  }
  if (!incomplete.empty()) out.attr(kGroup, "incomplete_inputs", incomplete);
}

}  // namespace gg
