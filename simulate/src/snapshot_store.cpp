#include "ggsim/snapshot_store.hpp"

#include <cstring>
#include <filesystem>

#include "gg/errors.hpp"
#include "gg/h5file.hpp"

namespace ggsim {

namespace {

// Beside the output (the disk chosen for the run's data, hidden like H5Output's temporary), or in
// $TMPDIR for stdout and streams.
gg::ScratchFile frames_file(const std::string& output) {
  namespace fs = std::filesystem;
  const std::string dir = gg::scratch_dir_for_output(output);
  if (dir == gg::ScratchFile::temp_dir()) return gg::ScratchFile::in_temp_dir("gg-sim.frames");
  std::string stem = ".";  // no "." + string: GCC 12 -Wrestrict
  stem += fs::path(output).filename().string();
  stem += ".frames";
  return gg::ScratchFile(dir, stem, "give -o in an existing, writable directory with space");
}

std::string in_quotes(const std::string& s) { return "'" + s + "'"; }

}  // namespace

SnapshotStore::SnapshotStore(const std::string& output, std::size_t n, int dim, const std::vector<double>& edges,
                             bool velocities, bool images)
    : velocities_(velocities), images_(images), file_(frames_file(output)) {
  file_.drop_name();
  index_.dim = dim;
  index_.edges = edges;
  index_.n_particles = n;
}

void SnapshotStore::append(double time, std::int64_t step, const double* position, const double* velocity,
                           const double* image) {
  const std::size_t bytes = field_bytes(), k = index_.frames();
  std::vector<const double*> values{position};
  if (velocities_) values.push_back(velocity);
  if (images_) values.push_back(image);
  for (std::size_t field = 0; field < values.size(); ++field) {
    const int err = file_.write_at(values[field], bytes, offset(k, field));
    if (err != 0)
      throw gg::RuntimeError("cannot write snapshot " + std::to_string(k) + " to the temporary file " +
                             in_quotes(file_.path()) + ": " + std::strerror(err) + "; free space there (each snapshot takes " +
                             std::to_string(fields() * bytes) + " bytes)");
  }
  index_.time.push_back(time);
  index_.step.push_back(step);
}

void SnapshotStore::read(std::size_t k, std::size_t field, double* values) const {
  const int err = file_.read_at(values, field_bytes(), offset(k, field));
  if (err != 0)
    throw gg::RuntimeError("cannot read snapshot " + std::to_string(k) + " back from the temporary file " +
                           in_quotes(file_.path()) + ": " + (err > 0 ? std::strerror(err) : "the file is shorter than written"));
}

std::size_t SnapshotStore::field_bytes() const {
  return index_.n_particles * static_cast<std::size_t>(index_.dim) * sizeof(double);
}

off_t SnapshotStore::offset(std::size_t k, std::size_t field) const {
  return static_cast<off_t>((k * fields() + field) * field_bytes());
}

gg::FrameReader SnapshotStore::positions() const {
  return [this](std::size_t k, double* values) { read(k, 0, values); };
}

gg::FrameReader SnapshotStore::velocities() const {
  if (!velocities_) return {};
  return [this](std::size_t k, double* values) { read(k, 1, values); };
}

gg::FrameReader SnapshotStore::images() const {
  if (!images_) return {};
  return [this](std::size_t k, double* values) { read(k, fields() - 1, values); };
}

}  // namespace ggsim
