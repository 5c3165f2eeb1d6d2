#pragma once
// Provenance written into every output under /parameters/provenance (docs/DESIGN.md):
// program, version, git hash, argv, UTC time, seed, library versions; the provenance of
// every input file under /parameters/provenance/inputs/<k>.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace gg {
class H5Input;
class H5Output;

struct Provenance {
  std::string program;                 // e.g. "gg-sim"
  std::vector<std::string> argv;       // the command line as given
  std::optional<std::uint64_t> seed;   // only tools that draw random numbers
};

// Writes /parameters/provenance and copies each input's /parameters/provenance (if any)
// to /parameters/provenance/inputs/<k>, k = 0, 1, ... in the order given.
void write_provenance(H5Output& out, const Provenance& p, const std::vector<const H5Input*>& inputs = {});

// The time now, "2026-01-31T12:00:00Z".
std::string utc_now_iso8601();

// "HDF5 1.10.8, FFTW 3.3.10, GSL 2.7.1" (the libraries linked into this program).
std::string library_versions();

}  // namespace gg
