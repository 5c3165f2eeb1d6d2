#include "ggsim/snapshot_store.hpp"

#include <cstring>
#include <filesystem>

#include <sys/types.h>  // off_t

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
                             const SnapshotFields& fields)
    : fields_(fields), file_(frames_file(output)) {
  file_.drop_name();
  index_.dim = dim;
  index_.edges = edges;
  index_.n_particles = n;
  const auto d = static_cast<std::size_t>(dim);
  std::vector<std::size_t> components{d, fields.velocities ? d : 0, fields.images ? d : 0};
  for (const FrameField& f : fields.more) components.push_back(f.components);
  for (std::size_t c : components) {
    stored_.push_back({c, frame_bytes_});
    frame_bytes_ += n * c * sizeof(double);
  }
}

void SnapshotStore::append(double time, std::int64_t step, const FrameValues& v) {
  const std::size_t k = index_.frames();
  std::vector<const double*> values{v.position, v.velocity, v.image};
  values.insert(values.end(), v.more.begin(), v.more.end());
  for (std::size_t field = 0; field < stored_.size(); ++field) {
    if (stored_[field].components == 0) continue;
    const int err = file_.write_at(values.at(field), bytes(field), static_cast<off_t>(k * frame_bytes_ + stored_[field].offset));
    if (err != 0)
      throw gg::RuntimeError("cannot write snapshot " + std::to_string(k) + " to the temporary file " +
                             in_quotes(file_.path()) + ": " + std::strerror(err) + "; free space there (each snapshot takes " +
                             std::to_string(frame_bytes_) + " bytes)");
  }
  index_.time.push_back(time);
  index_.step.push_back(step);
}

void SnapshotStore::read(std::size_t k, std::size_t field, double* values) const {
  const int err = file_.read_at(values, bytes(field), static_cast<off_t>(k * frame_bytes_ + stored_[field].offset));
  if (err != 0)
    throw gg::RuntimeError("cannot read snapshot " + std::to_string(k) + " back from the temporary file " +
                           in_quotes(file_.path()) + ": " + (err > 0 ? std::strerror(err) : "the file is shorter than written"));
}

std::size_t SnapshotStore::bytes(std::size_t field) const {
  return index_.n_particles * stored_[field].components * sizeof(double);
}

gg::FrameReader SnapshotStore::reader(std::size_t field) const {
  if (stored_[field].components == 0) return {};
  return [this, field](std::size_t k, double* values) { read(k, field, values); };
}

gg::FrameReader SnapshotStore::positions() const { return reader(kPositions); }
gg::FrameReader SnapshotStore::velocities() const { return reader(kVelocities); }
gg::FrameReader SnapshotStore::images() const { return reader(kImages); }
gg::FrameReader SnapshotStore::more(std::size_t m) const { return reader(kMore + m); }

}  // namespace ggsim
