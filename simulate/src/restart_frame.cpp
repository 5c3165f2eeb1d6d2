#include "ggsim/restart_frame.hpp"

#include <cmath>

#include "gg/errors.hpp"

namespace ggsim {

namespace {
const std::string kGroup = "/restart";
}  // namespace

void write_restart_frame(gg::H5Output& out, const SnapshotStore& snaps) {
  const gg::Snapshots& index = snaps.index();
  if (index.frames() == 0) return;
  const std::size_t last = index.frames() - 1;
  const std::vector<std::size_t> shape{1, index.n_particles, static_cast<std::size_t>(index.dim)};
  out.write_scalar(kGroup + "/time", index.time[last]);
  out.write_scalar(kGroup + "/step", index.step[last]);
  const gg::FrameReader position = snaps.positions(), velocity = snaps.velocities();
  out.write_rows(kGroup + "/position", shape, [&](std::size_t, double* values) { position(last, values); });
  if (velocity) out.write_rows(kGroup + "/velocity", shape, [&](std::size_t, double* values) { velocity(last, values); });
}

bool use_restart_frame(const gg::H5Input& in, gg::Snapshots& last) {
  if (!in.is_dataset(kGroup + "/position") || last.frames() != 1) return false;
  const std::string name = "'" + in.path() + "'";
  const gg::Array time = in.read(kGroup + "/time");
  if (time.data.size() != 1 || time.data[0] != last.time[0]) return false;  // a copy of another frame
  const std::size_t values = last.n_particles * static_cast<std::size_t>(last.dim);
  const auto frame = [&](const std::string& dataset) {
    const std::vector<std::size_t> shape = in.shape(dataset);
    if (shape != std::vector<std::size_t>{1, last.n_particles, static_cast<std::size_t>(last.dim)})
      throw gg::RuntimeError(name + ": " + dataset + " does not hold one frame of the snapshots' shape; the file is damaged");
    std::vector<double> a = in.read_rows(dataset, {0}).data;
    for (double x : a)
      if (!std::isfinite(x)) throw gg::RuntimeError(name + ": " + dataset + " holds a non-finite value; the file is damaged");
    return a;
  };
  std::vector<double> position = frame(kGroup + "/position");
  for (std::size_t i = 0; i < values; ++i) {
    const double L = last.edges[i % static_cast<std::size_t>(last.dim)];
    if (!(position[i] >= 0 && position[i] < L))
      throw gg::RuntimeError(name + ": " + kGroup + "/position has a particle outside the box; the file is damaged");
  }
  last.position = std::move(position);
  if (!last.velocity.empty()) {
    if (!in.is_dataset(kGroup + "/velocity"))
      throw gg::RuntimeError(name + ": " + kGroup + " has positions but no velocities; the file is damaged");
    last.velocity = frame(kGroup + "/velocity");
  }
  return true;
}

}  // namespace ggsim
