#include "ggsim/resources.hpp"

#include <cmath>
#include <cstdio>
#include <string>

#include "gg/errors.hpp"
#include "gg/machine.hpp"
#include "ggsim/scene_effect.hpp"

namespace ggsim {
namespace {

// Peak resident bytes per particle of a run, measured (/usr/bin/time, N = 1e6, rho = 0.37 and 0.05,
// 1e6 collisions): 148 in 2D, 113 in 1D, +8 with t_c and the pressure; the engine's own 110 of them
// (simulate/PERFORMANCE.md), the rest the start it is built from; the effects add their own
// (SceneEffect::footprint).
double bytes_per_particle(const SimConfig& cfg, const SceneFootprint& effects) {
  return (cfg.dim == 1 ? 120.0 : 155.0) + effects.particle_bytes;
}

// What the scene's effects add, summed.
SceneFootprint effects_footprint(const SimConfig& cfg) {
  SceneFootprint sum;
  for (const SceneEffect* effect : scene_effects()) {
    const SceneFootprint f = effect->footprint(cfg);
    sum.particle_bytes += f.particle_bytes;
    sum.frame_bytes += f.frame_bytes;
    sum.sample_values += f.sample_values;
  }
  return sum;
}

// Bytes of the program itself before any particle (libraries, HDF5's caches).
constexpr double kBaseBytes = 32e6;

// Times on a log grid of `per_decade` from `from` to `t_max` (inf if t_max is: unknown, not counted).
double grid_times(double per_decade, double from, double t_max) {
  if (!std::isfinite(t_max)) return 0;
  return t_max > from ? per_decade * std::log10(t_max / from) + 2 : 2;
}

// A count for a message: 2016, or 2e+09.
std::string count_text(double x) {
  char text[32];
  std::snprintf(text, sizeof text, x < 1e6 ? "%.0f" : "%.3g", x);
  return text;
}

}  // namespace

void require_resources(const SimConfig& cfg, std::size_t n, const std::string& scratch_dir) {
  if (!cfg.resource_check) return;
  const double particles = static_cast<double>(n);
  const double samples = grid_times(cfg.samples_per_decade, cfg.sample_from, cfg.t_max);
  const double frames = cfg.snapshots_per_decade > 0 ? grid_times(cfg.snapshots_per_decade, cfg.snapshots_from, cfg.t_max)
                                                     : static_cast<double>(cfg.snapshots.size());
  const SceneFootprint effects = effects_footprint(cfg);
  // Each sample: time, step and value of E(t) and of the collisions (and of the effects'
  // observables), in vectors that may have doubled past their size, plus one copy while the output
  // is written.
  const double per_sample = (2 + effects.sample_values) * 24.0 * 2 + 8;
  const double memory_parts[] = {particles * bytes_per_particle(cfg, effects), samples * per_sample, frames * 2 * 16.0};
  const char* why[] = {"lower --N, --L or --rho", "lower --samples-per-decade or --t-max", "take fewer snapshots"};
  const char* what[] = {" particles", " samples of E(t)", " snapshot times"};
  const double counts[] = {particles, samples, frames};
  double memory = kBaseBytes;
  int largest = 0;
  for (int k = 0; k < 3; ++k) {
    memory += memory_parts[k];
    if (memory_parts[k] > memory_parts[largest]) largest = k;
  }
  const double available = static_cast<double>(gg::available_memory());
  if (memory > available)
    throw gg::RuntimeError("the run needs about " + gg::size_text(memory) + " of memory (" + count_text(counts[largest]) +
                           what[largest] + "), but " + gg::size_text(available) + " are available; " + why[largest] +
                           ", run where there is more memory, or give --no-resource-check to try anyway");
  // The snapshots wait in scratch_dir in double precision until the output, built there too, is
  // written from them: both are on the disk at the end.
  const double frame = particles * (cfg.dim * 8.0 * (cfg.velocities ? 2 : 1) + effects.frame_bytes);
  const double disk = frames * frame * (cfg.float_snapshots ? 1.5 : 2.0);
  const double free = static_cast<double>(gg::free_disk_space(scratch_dir));
  if (disk > free)
    throw gg::RuntimeError("the run's " + count_text(frames) + " snapshots need about " + gg::size_text(disk) + " on disk in '" +
                           scratch_dir + "' (kept there in double precision until the output is written, then the "
                           "output), but " + gg::size_text(free) + " are free there; take fewer snapshots, write -o "
                           "where there is more space, or give --no-resource-check to try anyway");
}

}  // namespace ggsim
