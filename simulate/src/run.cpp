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
#include "ggsim/effects/rough_particles.hpp"
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
const std::string kSpinFrames = "/particles/all/angular_velocity/value";

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

// Whether a file is the output of a mixture (gg-sim --radii, --masses: docs/DESIGN.md "Mixtures").
bool holds_mixture(const gg::H5Input& in) { return in.exists("/observables/temperature_species"); }

// The sizes of a mixture's output at its last frame, and the species of its n particles.
Sizes sizes_from_file(const gg::H5Input& in, std::size_t n, const std::string& path) {
  Sizes s;
  const std::size_t last = in.shape("/particles/all/mass/value").at(0) - 1;
  s.radius = in.read_rows("/particles/all/radius/value", {last}).data;
  s.mass = in.read_rows("/particles/all/mass/value", {last}).data;
  for (std::int64_t x : in.read_int("/particles/all/species")) s.species.push_back(static_cast<std::uint32_t>(x));
  bool valid = s.radius.size() == n && s.mass.size() == n && s.species.size() == n;
  for (std::size_t i = 0; valid && i < n; ++i) {
    valid = s.radius[i] > 0 && s.mass[i] > 0 && std::isfinite(s.radius[i]) && std::isfinite(s.mass[i]);
    s.species_count = std::max(s.species_count, s.species[i] + 1);
  }
  if (!valid)
    throw gg::RuntimeError("--init " + path + ": /particles/all/radius, mass or species do not give every particle a "
                           "positive radius and mass; give an output of gg-sim --radii or --masses");
  return s;
}

// Positions and velocities from the last frame of an H5MD file: its velocities as they are, or
// scaled to T0 if the scene names one; drawn at T0 if the file has none. A mixture's output also
// gives its sizes.
template <int D>
State<D> state_from_file(const gg::H5Input& in, const SimConfig& cfg, Random& rng) {
  if (in.exists(kFrames) && !in.shape(kFrames).empty() && in.shape(kFrames)[0] == 0)
    throw gg::RuntimeError("--init " + cfg.init + " has no snapshots (0 frames) to start from; give an H5MD file with "
                           "at least one snapshot (e.g. a gg-sim output with --snapshots)");
  const bool mixture = holds_mixture(in);
  if (mixture && cfg.equilibrate > 0)
    throw gg::UsageError("--init " + cfg.init + " holds a mixture; --equilibrate runs equal particles; drop it");
  if (in.exists("/particles/all/mass") && !mixture)
    throw gg::UsageError("--init " + cfg.init + " holds aggregates of an --aggregate run (/particles/all/mass); gg-sim "
                         "starts only from particles of unit mass and diameter");
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
  if (mixture) st.sizes = sizes_from_file(in, s.n_particles, cfg.init);
  if (cfg.unwrapped && !s.image.empty()) {
    std::vector<std::int64_t>& image = st.effects.integer["image"];
    for (double x : s.image) image.push_back(static_cast<std::int64_t>(x));
  }
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
    if (cfg.T0_given) mixture ? set_temperature<D>(st.v, cfg.T0, st.sizes.mass) : set_temperature<D>(st.v, cfg.T0);
  } else {
    st.v = mixture ? maxwellian_velocities<D>(st.sizes.mass, cfg.T0, rng)
                   : maxwellian_velocities<D>(s.n_particles, cfg.T0, rng);
  }
  // A start with overlapping disks has no meaning for hard spheres: refuse it. Contact is at
  // R_i + R_j (1 without a mixture), found in cells of the largest diameter.
  const auto contact = [&](std::size_t i, std::size_t j) {
    return mixture ? st.sizes.radius[i] + st.sizes.radius[j] : 1.0;
  };
  CellGrid<D> cells(st.box, mixture ? 2 * *std::max_element(st.sizes.radius.begin(), st.sizes.radius.end()) : 1.0,
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
          (mixture ? " contact distances apart); " : " diameters apart); ") +
          (rounding ? "that is the rounding of single-precision positions (--float-snapshots); an output written "
                      "with --float-snapshots keeps its last frame in double (/restart) to start from: rerun the run "
                      "that wrote this one, or use one written without --float-snapshots"
                    : "a hard-sphere start needs every pair at least one diameter apart"));
    });
    cells.insert(static_cast<std::uint32_t>(i), st.r[i]);
  }
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
  if (cfg.mixture()) {  // sizes, then positions, then velocities from the one generator
    st.sizes = draw_sizes(MixtureSpec::parse(cfg.radii, cfg.masses, cfg.fractions), cfg.N, D, rng);
    st.r = random_positions<D>(region, cfg.N, rng, &st.sizes);
  } else {
    st.r = cfg.init == "random" ? random_positions<D>(region, cfg.N, rng) : lattice_positions<D>(region, cfg.N);
  }
  for (Vec<D>& x : st.r)
    for (int k = 0; k < D; ++k) x[k] += shape.offset[k];
  st.v = cfg.mixture() ? maxwellian_velocities<D>(st.sizes.mass, cfg.T0, rng) : maxwellian_velocities<D>(cfg.N, cfg.T0, rng);
  return st;
}

// The angular velocities of rough particles at the start: a Maxwellian at --T0-rot (I <w_k^2> =
// T0_rot for each of the rotational degrees of freedom, one in 2D, three in 3D) drawn after the
// positions and velocities, else those of the last frame of --init FILE if it has them, else 0.
template <int D>
std::vector<Spin<D>> initial_spins(const SimConfig& cfg, const InitFile& file, std::size_t n, Random& rng) {
  std::vector<Spin<D>> spin(n, Spin<D>{});
  if (cfg.T0_rot) {
    const double sd = std::sqrt(*cfg.T0_rot / moment_of_inertia(*cfg.inertia));
    for (Spin<D>& w : spin) {
      if constexpr (D == 3) for (double& c : w) c = sd * rng.normal();
      else w = sd * rng.normal();
    }
  } else if (file.in && file.in->exists(kSpinFrames)) {
    const auto shape = file.in->shape(kSpinFrames);
    if (shape.size() < 2 || shape[1] != n || (shape.size() > 2 ? shape[2] : 1) != kSpinComponents<D>)
      throw gg::RuntimeError("--init " + cfg.init + ": " + kSpinFrames + " does not hold " + std::to_string(kSpinComponents<D>) +
                             " angular velocity components for each of its " + std::to_string(n) + " particles");
    const std::vector<double> w = file.in->read_rows(kSpinFrames, {shape[0] - 1}).data;
    for (std::size_t i = 0; i < n; ++i) {
      if constexpr (D == 3) for (int k = 0; k < 3; ++k) spin[i][k] = w[i * 3 + k];
      else spin[i] = w[i];
    }
  }
  return spin;
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
  return {&simulate<D, Effects<EngineVariants<D>::kKeys[K]>>...};
}

// A mixture read from --init FILE (or from the checkpoint of such a run) is one too.
template <int D>
int dispatch(const SimConfig& cfg, State<D>* st, SavedRun* saved, const InitFile& init,
             const std::vector<std::string>& argv, bool show_progress) {
  static constexpr auto kTable = variant_table<D>(std::make_index_sequence<EngineVariants<D>::kKeys.size()>());
  const bool mixture = st ? !st->sizes.empty() : saved->has_sizes();
  const unsigned wanted = wanted_effects(cfg) | (mixture ? kMixtureBit : 0u);
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
  if (cfg.rough()) st.effects.real["spin"] = flatten_spins<D>(initial_spins<D>(cfg, init, st.r.size(), rng));
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
  // Before any work, what the end of the run needs: somewhere to write its output and checkpoints.
  gg::require_writable_output(cfg.output, "-o");
  if (!checkpoint.empty()) gg::require_writable_output(checkpoint, "--checkpoint");
  std::unique_ptr<SavedRun> opened;
  if (!cfg.resume.empty() && !saved) saved = (opened = std::make_unique<SavedRun>(cfg.resume)).get();
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

