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
                             const SnapshotFields& fields)
    : fields_(fields), file_(frames_file(output)) {
  file_.drop_name();
  index_.dim = dim;
  index_.edges = edges;
  index_.n_particles = n;
}

void SnapshotStore::append(double time, std::int64_t step, const FrameValues& v) {
  const std::size_t k = index_.frames();
  const std::size_t frame_bytes = static_cast<std::size_t>(offset(1, kPositions));
  const double* values[] = {v.position, v.velocity, v.image, v.mass, v.radius, v.spin};
  for (Field field : kFields) {
    if (!holds(field)) continue;
    const int err = file_.write_at(values[field], field_bytes(field), offset(k, field));
    if (err != 0)
      throw gg::RuntimeError("cannot write snapshot " + std::to_string(k) + " to the temporary file " +
                             in_quotes(file_.path()) + ": " + std::strerror(err) + "; free space there (each snapshot takes " +
                             std::to_string(frame_bytes) + " bytes)");
  }
  index_.time.push_back(time);
  index_.step.push_back(step);
}

void SnapshotStore::read(std::size_t k, Field field, double* values) const {
  const int err = file_.read_at(values, field_bytes(field), offset(k, field));
  if (err != 0)
    throw gg::RuntimeError("cannot read snapshot " + std::to_string(k) + " back from the temporary file " +
                           in_quotes(file_.path()) + ": " + (err > 0 ? std::strerror(err) : "the file is shorter than written"));
}

std::size_t SnapshotStore::field_bytes(Field field) const {
  std::size_t per_particle = field == kMasses || field == kRadii ? 1 : static_cast<std::size_t>(index_.dim);
  if (field == kSpins) per_particle = index_.dim == 3 ? 3 : 1;
  return index_.n_particles * per_particle * sizeof(double);
}

bool SnapshotStore::holds(Field field) const {
  switch (field) {
    case kPositions: return true;
    case kVelocities: return fields_.velocities;
    case kImages: return fields_.images;
    case kMasses:
    case kRadii: return fields_.sizes;
    case kSpins: return fields_.spins;
  }
  return false;
}

// Frame k is its fields one after the other, in the order of Field (those it holds).
off_t SnapshotStore::offset(std::size_t k, Field field) const {
  std::size_t frame = 0, before = 0;
  for (Field f : kFields) {
    if (!holds(f)) continue;
    if (f < field) before += field_bytes(f);
    frame += field_bytes(f);
  }
  return static_cast<off_t>(k * frame + before);
}

gg::FrameReader SnapshotStore::positions() const {
  return [this](std::size_t k, double* values) { read(k, kPositions, values); };
}

gg::FrameReader SnapshotStore::velocities() const {
  if (!fields_.velocities) return {};
  return [this](std::size_t k, double* values) { read(k, kVelocities, values); };
}

gg::FrameReader SnapshotStore::masses() const {
  if (!fields_.sizes) return {};
  return [this](std::size_t k, double* values) { read(k, kMasses, values); };
}

gg::FrameReader SnapshotStore::radii() const {
  if (!fields_.sizes) return {};
  return [this](std::size_t k, double* values) { read(k, kRadii, values); };
}

gg::FrameReader SnapshotStore::spins() const {
  if (!fields_.spins) return {};
  return [this](std::size_t k, double* values) { read(k, kSpins, values); };
}

gg::FrameReader SnapshotStore::images() const {
  if (!fields_.images) return {};
  return [this](std::size_t k, double* values) { read(k, kImages, values); };
}

}  // namespace ggsim
