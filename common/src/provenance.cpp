// Provenance of every output (docs/DESIGN.md "Conventions of every tool").
#include "gg/provenance.hpp"

#include <ctime>
#include <string_view>

#include <fftw3.h>
#include <gsl/gsl_version.h>

#include "gg/h5file.hpp"
#include "gg/version.hpp"

namespace gg {
namespace {

const std::string kGroup = "/parameters/provenance";

std::string utc_now_iso8601() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

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
}

}  // namespace gg
