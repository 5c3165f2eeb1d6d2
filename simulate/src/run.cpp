#include "ggsim/run.hpp"

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <utility>

#include "engine_variant_list.hpp"  // generated: EngineVariants<D>::kKeys
#include "gg/errors.hpp"
#include "gg/h5file.hpp"
#include "gg/trajectory.hpp"
#include "ggsim/cell_grid.hpp"
#include "ggsim/checkpoint.hpp"
#include "ggsim/engine_variants.hpp"
#include "ggsim/initial_state.hpp"
#include "ggsim/resources.hpp"
#include "ggsim/restart_frame.hpp"
#include "ggsim/scene_effect.hpp"
#include "simulate.hpp"
#include "start.hpp"

namespace ggsim {

namespace {

const std::string kFrames = "/particles/all/position/value";

// Opens --init FILE for a fresh run; for a resumed one (whose start is in the checkpoint) only if
// it is still there, for its provenance.
InitFile open_init_file(const SimConfig& cfg) {
  InitFile f;
  if (!cfg.starts_from_file()) {
    f.has_velocities = false;
    return f;
  }
  if (!cfg.resume.empty() && (cfg.init == "-" || !std::filesystem::exists(cfg.init))) return f;
  f.in = std::make_unique<gg::H5Input>(cfg.init);
  f.has_velocities = f.in->exists("/particles/all/velocity/value");
  return f;
}

// The sizes of a fresh start's n particles, if an effect gives them (its scene part's start_sizes).
Sizes start_sizes(const SimConfig& cfg, const StartFile& file, std::size_t n, Random& rng) {
  for (const SceneEffect* effect : scene_effects())
    if (Sizes sizes = effect->start_sizes(cfg, file, n, rng); !sizes.empty()) return sizes;
  return {};
}

// The effects' arrays at a fresh start (their scene parts' start_state), after the positions and
// velocities.
template <int D>
void start_effects(const SimConfig& cfg, const StartFile& file, State<D>& st, Random& rng) {
  for (const SceneEffect* effect : scene_effects()) effect->start_state(cfg, file, st.r.size(), rng, st.effects);
}

// Positions and velocities from the last frame of an H5MD file: its velocities as they are, or
// scaled to T0 if the scene names one; drawn at T0 if the file has none. The effects may take
// their sizes (a mixture's output) and their arrays from it.
template <int D>
State<D> state_from_file(const gg::H5Input& in, const SimConfig& cfg, Random& rng) {
  if (in.exists(kFrames) && !in.shape(kFrames).empty() && in.shape(kFrames)[0] == 0)
    throw gg::RuntimeError("--init " + cfg.init + " has no snapshots (0 frames) to start from; give an H5MD file with "
                           "at least one snapshot (e.g. a gg-sim output with --snapshots)");
  gg::Snapshots s = gg::read_snapshots(in, {-1});
  if (s.n_particles == 0) throw gg::RuntimeError("--init " + cfg.init + " holds no particles; give a file with at least one");
  if (s.dim != D)
    throw gg::UsageError("--init " + cfg.init + " holds " + std::to_string(s.dim) + "D positions but --dim is " +
                         std::to_string(D));
  const bool exact = use_restart_frame(in, s);
  State<D> st;
  std::array<double, D> edges;
  for (int k = 0; k < D; ++k) edges[k] = s.edges[k];
  st.box = gg::Box<D>(edges);
  st.r.resize(s.n_particles);
  for (std::size_t i = 0; i < s.n_particles; ++i)
    for (int k = 0; k < D; ++k) st.r[i][k] = s.position[i * D + k];
  st.sizes = start_sizes(cfg, {&in, &s}, s.n_particles, rng);
  const bool sized = !st.sizes.empty();
  if (cfg.continue_clock) {
    if (s.velocity.empty())
      throw gg::UsageError("--continue goes on with the velocities of " + cfg.init + ", which has none; write the "
                           "run to continue with --velocities, or drop --continue to start a new clock");
    st.t0 = s.time.at(0);
    st.step0 = static_cast<std::uint64_t>(std::max<std::int64_t>(s.step.at(0), 0));
    if (!cfg.snapshots.empty() && cfg.snapshots.front() < st.t0)
      throw gg::UsageError("--snapshots time " + std::to_string(cfg.snapshots.front()) + " lies before t = " +
                           std::to_string(st.t0) + ", where --continue starts (the last frame of " + cfg.init +
                           "); give later times");
    if (!(cfg.t_max > st.t0))
      throw gg::UsageError("--t-max " + std::to_string(cfg.t_max) + " is not after t = " + std::to_string(st.t0) +
                           ", where --continue starts (the last frame of " + cfg.init + "); give a later --t-max");
    if (cfg.max_collisions <= st.step0)
      throw gg::UsageError("--max-collisions " + std::to_string(cfg.max_collisions) + " is not more than the " +
                           std::to_string(st.step0) + " collisions " + cfg.init + " has had (--continue counts on)");
  }
  if (!s.velocity.empty()) {
    st.v.resize(s.n_particles);
    for (std::size_t i = 0; i < s.n_particles; ++i)
      for (int k = 0; k < D; ++k) st.v[i][k] = s.velocity[i * D + k];
    if (cfg.T0_given) sized ? set_temperature<D>(st.v, cfg.T0, st.sizes.mass) : set_temperature<D>(st.v, cfg.T0);
  } else {
    st.v = sized ? maxwellian_velocities<D>(st.sizes.mass, cfg.T0, rng)
                   : maxwellian_velocities<D>(s.n_particles, cfg.T0, rng);
  }
  // A start with overlapping disks has no meaning for hard spheres: refuse it. Contact is at
  // R_i + R_j (1 without sizes), found in cells of the largest diameter.
  const auto contact = [&](std::size_t i, std::size_t j) {
    return sized ? st.sizes.radius[i] + st.sizes.radius[j] : 1.0;
  };
  CellGrid<D> cells(st.box, sized ? 2 * *std::max_element(st.sizes.radius.begin(), st.sizes.radius.end()) : 1.0,
                    st.r.size());
  for (std::size_t i = 0; i < st.r.size(); ++i) {
    cells.for_each_near(cells.encode(st.r[i]), [&](std::uint32_t j, const auto&) {
      Vec<D> d;
      for (int k = 0; k < D; ++k) d[k] = st.box.min_image(st.r[i][k] - st.r[j][k], k);
      const double d2 = dot<D>(d, d) / (contact(i, j) * contact(i, j));  // in contact distances
      if (d2 >= 1.0 - kOverlapTolerance) return;
      const double gap = std::sqrt(d2);
      const auto in_float = [](const Vec<D>& x) {
        for (int k = 0; k < D; ++k)
          if (static_cast<double>(static_cast<float>(x[k])) != x[k]) return false;
        return true;
      };
      // Single-precision positions (--float-snapshots, in an output without a /restart copy of its
      // last frame) round touching disks into each other by up to ~1e-5 diameters.
      const bool rounding = !exact && gap > 1.0 - 1e-4 && in_float(st.r[i]) && in_float(st.r[j]);
      char apart[32];
      std::snprintf(apart, sizeof apart, "%.9g", gap);
      throw gg::RuntimeError(
          "--init " + cfg.init + ": particles " + std::to_string(j) + " and " + std::to_string(i) + " overlap (" + apart +
          (sized ? " contact distances apart); " : " diameters apart); ") +
          (rounding ? "that is the rounding of single-precision positions (--float-snapshots); an output written "
                      "with --float-snapshots keeps its last frame in double (/restart) to start from: rerun the run "
                      "that wrote this one, or use one written without --float-snapshots"
                    : "a hard-sphere start needs every pair at least one diameter apart"));
    });
    cells.insert(static_cast<std::uint32_t>(i), st.r[i]);
  }
  start_effects(cfg, {&in, &s}, st, rng);
  return st;
}

template <int D>
State<D> initial_state(const SimConfig& cfg, const InitFile& file, Random& rng) {
  if (file.in) return state_from_file<D>(*file.in, cfg, rng);
  State<D> st;
  // The cube of edge L, unless an effect shapes the box or where the particles go (walls).
  StartShape shape{std::vector<double>(D, cfg.L), std::vector<double>(D, cfg.L), std::vector<double>(D, 0.0)};
  for (const SceneEffect* effect : scene_effects()) effect->shape_start(cfg, shape);
  std::array<double, D> edges, region_edges;
  std::copy(shape.edges.begin(), shape.edges.end(), edges.begin());
  std::copy(shape.region.begin(), shape.region.end(), region_edges.begin());
  st.box = gg::Box<D>(edges);
  const gg::Box<D> region(region_edges);
  // Sizes (an effect's, drawn first), then positions, then velocities from the one generator.
  st.sizes = start_sizes(cfg, {}, cfg.N, rng);
  if (!st.sizes.empty())
    st.r = random_positions<D>(region, cfg.N, rng, &st.sizes);
  else
    st.r = cfg.init == "random" ? random_positions<D>(region, cfg.N, rng) : lattice_positions<D>(region, cfg.N);
  for (Vec<D>& x : st.r)
    for (int k = 0; k < D; ++k) x[k] += shape.offset[k];
  st.v = st.sizes.empty() ? maxwellian_velocities<D>(cfg.N, cfg.T0, rng) : maxwellian_velocities<D>(st.sizes.mass, cfg.T0, rng);
  if constexpr (D >= 2)
    if (shape.shear != 0)
      for (std::size_t i = 0; i < st.v.size(); ++i) st.v[i][0] += shape.shear * (st.r[i][1] - 0.5 * edges[1]);
  start_effects(cfg, {}, st, rng);
  return st;
}

// The scene's effects become template arguments here, once, outside the event loop: the scene
// runs the compiled variant with the fewest effects that holds all of its own (engine_variants.hpp),
// each compiled in a translation unit of its own, so no collision or move branches on an effect
// the scene does not use.
template <int D>
using SimulateVariant = int(const SimConfig&, State<D>*, SavedRun*, const InitFile&, const std::vector<std::string>&,
                           bool);

template <int D, std::size_t... K>
constexpr std::array<SimulateVariant<D>*, sizeof...(K)> variant_table(std::index_sequence<K...>) {
  return {&simulate<D, EngineVariant<EngineVariants<D>::kKeys[K]>>...};
}

template <int D>
int dispatch(const SimConfig& cfg, State<D>* st, SavedRun* saved, const InitFile& init,
             const std::vector<std::string>& argv, bool show_progress) {
  static constexpr auto kTable = variant_table<D>(std::make_index_sequence<EngineVariants<D>::kKeys.size()>());
  // A resumed run holds the effects of the engine that wrote its checkpoint, which took their state.
  const unsigned wanted = st ? wanted_effects(cfg, !st->sizes.empty()) : wanted_effects(cfg) | saved->effects();
  return kTable[choose_variant(wanted, EngineVariants<D>::kKeys)](cfg, st, saved, init, argv, show_progress);
}

template <int D>
int run_in(const SimConfig& cfg, SavedRun* saved, const std::vector<std::string>& argv, bool show_progress) {
  const InitFile init = open_init_file(cfg);
  const std::string scratch = gg::scratch_dir_for_output(cfg.output);
  if (saved) {
    require_resources(cfg, saved->particles(), scratch);
    return dispatch<D>(cfg, nullptr, saved, init, argv, show_progress);
  }
  // A file's particles are counted once it has been read and checked (a damaged file may claim any
  // number); the scene's before anything is built.
  if (!cfg.starts_from_file()) require_resources(cfg, cfg.N, scratch);
  Random rng(cfg.seed);
  State<D> st = initial_state<D>(cfg, init, rng);
  if (cfg.starts_from_file()) require_resources(cfg, st.r.size(), scratch);
  if (cfg.equilibrate > 0) equilibrate<D>(st, cfg);
  return dispatch<D>(cfg, &st, nullptr, init, argv, show_progress);
}

}  // namespace

int run(const SimConfig& cfg, const std::vector<std::string>& argv, bool show_progress, SavedRun* saved) {
  std::vector<std::string> read;
  if (cfg.starts_from_file()) read.push_back(cfg.init);
  if (!cfg.resume.empty()) read.push_back(cfg.resume);
  gg::require_output_is_not_an_input(cfg.output, read);
  // The checkpoint is rewritten during the run and removed at its end: it may be the one resumed
  // from, but neither the output nor the start (neither of which need exist yet).
  const std::string checkpoint = cfg.checkpoint_path();
  const bool over_output = gg::same_file(checkpoint, cfg.output);
  if (over_output || (cfg.starts_from_file() && gg::same_file(checkpoint, cfg.init)))
    throw gg::UsageError("--checkpoint " + checkpoint + " names the " + (over_output ? "output" : "--init file") +
                         ", which the run's checkpoints would overwrite; choose another --checkpoint");
  // A file already there (an interrupted run's checkpoint, or any other) would be overwritten and, at
  // the end, removed: only the run that resumes from it may take its place.
  const std::string resumed_from = saved ? saved->path() : cfg.resume;
  std::error_code ec;
  if (!checkpoint.empty() && std::filesystem::exists(checkpoint, ec) &&
      (resumed_from.empty() || !gg::same_file(checkpoint, resumed_from)))
    throw gg::UsageError("'" + checkpoint + "' exists (an interrupted run's checkpoint?), which this run would overwrite and " +
                         "remove; resume it with --resume " + checkpoint + ", or remove it, or give another --checkpoint");
  // Before any work, what the end of the run needs: somewhere to write its output and checkpoints.
  gg::require_writable_output(cfg.output, "-o");
  if (!checkpoint.empty()) gg::require_writable_output(checkpoint, "--checkpoint");
  std::unique_ptr<SavedRun> opened;
  if (!cfg.resume.empty() && !saved) saved = (opened = std::make_unique<SavedRun>(cfg.resume, cfg.allow_other_build)).get();
  if (saved) require_same_scene(saved->path(), saved->scene(), cfg);
  if (saved && saved->dimension() != cfg.dim)
    throw gg::UsageError("--resume " + saved->path() + " holds a run in another dimension than --dim " + std::to_string(cfg.dim));
  switch (cfg.dim) {
    case 1: return run_in<1>(cfg, saved, argv, show_progress);
    case 2: return run_in<2>(cfg, saved, argv, show_progress);
    default: return run_in<3>(cfg, saved, argv, show_progress);
  }
}

}  // namespace ggsim

