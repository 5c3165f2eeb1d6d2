#include "ggsim/run.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <memory>
#include <optional>
#include <string>

#include "gg/errors.hpp"
#include "gg/h5file.hpp"
#include "gg/progress.hpp"
#include "gg/provenance.hpp"
#include "gg/trajectory.hpp"
#include "ggsim/checkpoint.hpp"
#include "ggsim/engine.hpp"
#include "ggsim/initial_state.hpp"
#include "ggsim/recorder.hpp"
#include "ggsim/resources.hpp"
#include "ggsim/restart_frame.hpp"

namespace ggsim {

namespace {

template <int D>
struct State {
  gg::Box<D> box;
  std::vector<Vec<D>> r, v;
  // --unwrapped: the periodic image each particle starts in (a start from a file that holds one:
  // its last frame's; empty: image 0).
  std::vector<Image<D>> image;
  double t0 = 0;             // the clock at the start (--continue: the file's last frame)
  std::uint64_t step0 = 0;   // and the collisions so far
};

// The file a run starts from (--init FILE.h5), open for the whole run: its provenance goes into
// the output's /parameters/provenance/inputs/0, as every tool's inputs do (docs/DESIGN.md).
struct InitFile {
  std::unique_ptr<gg::H5Input> in;
  // Whether it holds velocities; unknown for a resumed run whose start file is gone.
  std::optional<bool> has_velocities;
};

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

// Positions and velocities from the last frame of an H5MD file: its velocities as they are, or
// scaled to T0 if the scene names one; drawn at T0 if the file has none.
template <int D>
State<D> state_from_file(const gg::H5Input& in, const SimConfig& cfg, Random& rng) {
  if (in.exists(kFrames) && !in.shape(kFrames).empty() && in.shape(kFrames)[0] == 0)
    throw gg::RuntimeError("--init " + cfg.init + " has no snapshots (0 frames) to start from; give an H5MD file with "
                           "at least one snapshot (e.g. a gg-sim output with --snapshots)");
  if (in.exists("/particles/all/mass"))
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
  if (cfg.unwrapped && !s.image.empty()) {
    st.image.resize(s.n_particles);
    for (std::size_t i = 0; i < s.n_particles; ++i)
      for (int k = 0; k < D; ++k) st.image[i][k] = static_cast<std::int32_t>(s.image[i * D + k]);
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
    if (cfg.T0_given) set_temperature<D>(st.v, cfg.T0);
  } else {
    st.v = maxwellian_velocities<D>(s.n_particles, cfg.T0, rng);
  }
  // A start with overlapping disks has no meaning for hard spheres: refuse it.
  CellGrid<D> cells(st.box, 1.0, st.r.size());
  for (std::size_t i = 0; i < st.r.size(); ++i) {
    cells.for_each_near(cells.encode(st.r[i]), [&](std::uint32_t j, const auto&) {
      Vec<D> d;
      for (int k = 0; k < D; ++k) d[k] = st.box.min_image(st.r[i][k] - st.r[j][k], k);
      const double d2 = dot<D>(d, d);
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
          " diameters apart); " +
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
  std::array<double, D> edges;
  edges.fill(cfg.L);
  st.box = gg::Box<D>(edges);
  st.r = cfg.init == "random" ? random_positions<D>(st.box, cfg.N, rng) : lattice_positions<D>(st.box, cfg.N);
  st.v = maxwellian_velocities<D>(cfg.N, cfg.T0, rng);
  return st;
}

struct NoObserver {
  double next_time() const { return kNever; }
  template <class E> void observe(E&, double) {}
  template <class E> bool poll(const E&) { return g_stop_requested != 0; }
};

// Elastic run for `per_particle` collisions per particle, then back to T = T0 at t = 0 (and, with
// --unwrapped, in image 0: the displacements count from t = 0).
template <int D>
void equilibrate(State<D>& st, const SimConfig& cfg) {
  EngineParameters par;
  par.skin = cfg.skin;
  Engine<D, Effects<false, false, false>> eng(st.box, st.r, st.v, par);
  NoObserver none;
  const auto budget = static_cast<std::uint64_t>(std::llround(cfg.equilibrate * static_cast<double>(st.r.size()) / 2));
  const StopReason why = eng.run(kNever, budget, none);
  if (why == StopReason::kInterrupted) throw gg::RuntimeError("interrupted during equilibration; nothing written");
  eng.for_each_particle(eng.now(), [&](std::uint32_t i, const Vec<D>& r, const Vec<D>& v) {
    st.r[i] = r;
    st.v[i] = v;
  });
  st.image.clear();
  set_temperature<D>(st.v, cfg.T0);
}

// How a run ended, as /parameters/stop_reason records it: an interrupted or collapsed run's output
// holds everything up to then, and says so.
const char* stop_reason_name(StopReason why) {
  switch (why) {
    case StopReason::kTimeReached: return "t_max";
    case StopReason::kCollisionBudget: return "max_collisions";
    case StopReason::kInterrupted: return "interrupted";
    case StopReason::kCollapse: return "collapse";
    case StopReason::kNothingLeft: return "no_events";
    case StopReason::kOneLeft: return "one_particle_left";
    case StopReason::kOutgrewBox: return "outgrew_box";
  }
  return "unknown";
}

// An aggregating run's own outputs (docs/DESIGN.md "Aggregates"): N(t) and the mean mass
// N0 / N(t) as observables, masses and radii per snapshot as H5MD time-dependent elements beside
// the positions (one row per start particle; 0 for one merged into another).
void write_aggregates(gg::H5Output& out, const Recorder& rec) {
  gg::write_observable(out, "number_of_particles", rec.particles());
  gg::write_observable(out, "mean_mass", rec.mean_mass(), "m");
  const SnapshotStore& snaps = rec.snapshots();
  const gg::Snapshots& index = snaps.index();
  const auto element = [&](const std::string& name, const gg::FrameReader& frames, const std::string& unit) {
    const std::string group = "/particles/all/" + name;
    out.write(group + "/step", index.step);
    out.write(group + "/time", index.time);
    out.attr(group + "/time", "unit", gg::kUnitTime);
    out.write_rows(group + "/value", {index.frames(), index.n_particles}, frames);
    out.attr(group + "/value", "unit", unit);
  };
  element("mass", snaps.masses(), "m");
  element("radius", snaps.radii(), gg::kUnitLength);
}

void write_output(const SimConfig& cfg, const std::vector<std::string>& argv, const Recorder& rec,
                  const InitFile& init, StopReason why) {
  gg::H5Output out(cfg.output);
  const SnapshotStore& snaps = rec.snapshots();
  gg::Snapshots index = snaps.index();  // box, times and steps (the frames stay in the store)
  index.author = cfg.author;
  gg::write_snapshots(out, index, snaps.positions(), snaps.velocities(), snaps.images(), "gg-sim", cfg.float_snapshots);
  if (cfg.float_snapshots) write_restart_frame(out, snaps);
  gg::write_observable(out, "kinetic_energy", rec.energy(), gg::kUnitEnergy);
  gg::write_observable(out, "collisions_per_particle", rec.collisions());
  if (cfg.pressure) gg::write_observable(out, "pressure", rec.pressure(), gg::pressure_unit(cfg.dim));
  if (cfg.aggregate) write_aggregates(out, rec);
  // Every scene value, so a file says how it was made (docs/DESIGN.md /parameters).
  out.create_group("/parameters");
  out.attr("/parameters", "dim", static_cast<std::int64_t>(cfg.dim));
  out.attr("/parameters", "N", static_cast<std::int64_t>(index.n_particles));
  out.attr("/parameters", "L", index.edges[0]);
  // The density of the run as it is (with --init FILE it comes from the file, not from the flags).
  double volume = 1;
  for (double L : index.edges) volume *= L;
  out.attr("/parameters", "rho", static_cast<double>(index.n_particles) / volume);
  out.attr("/parameters", "e", cfg.e);
  out.attr("/parameters", "delta", cfg.delta);
  out.attr("/parameters", "tc", cfg.tc);
  // The temperature the run started at: a start from a file that kept the file's velocities has
  // the file's (2 E(0) / d; the first sample is at t = 0). If a resumed run's start file is gone,
  // 2 E(0) / d is right either way (drawn velocities have T0 up to round-off).
  const bool kept_file_temperature = init.has_velocities.value_or(true) && !cfg.T0_given && cfg.equilibrate == 0;
  out.attr("/parameters", "T0", kept_file_temperature ? 2 * rec.energy().value.front() / cfg.dim : cfg.T0);
  out.attr("/parameters", "seed", static_cast<std::int64_t>(cfg.seed));
  out.attr("/parameters", "init", cfg.init);
  out.attr("/parameters", "equilibrate", cfg.equilibrate);
  out.attr("/parameters", "t_max", cfg.t_max);
  // The clock at the start: 0, or the file's with --continue (the first sample is at it).
  out.attr("/parameters", "t_start", rec.energy().time.empty() ? 0.0 : rec.energy().time.front());
  out.attr("/parameters", "continue", static_cast<std::int64_t>(cfg.continue_clock));
  // No budget is infinite, as an unset t_max is (not 2^64 - 1 rounded to 1.8e19).
  const bool budget = cfg.max_collisions != std::numeric_limits<std::uint64_t>::max();
  out.attr("/parameters", "max_collisions",
           budget ? static_cast<double>(cfg.max_collisions) : std::numeric_limits<double>::infinity());
  out.attr("/parameters", "samples_per_decade", cfg.samples_per_decade);
  out.attr("/parameters", "sample_from", cfg.sample_from);
  out.attr("/parameters", "snapshots", cfg.snapshots);
  out.attr("/parameters", "snapshots_per_decade", cfg.snapshots_per_decade);
  out.attr("/parameters", "snapshots_from", cfg.snapshots_from);
  out.attr("/parameters", "velocities", static_cast<std::int64_t>(cfg.velocities));
  out.attr("/parameters", "pressure", static_cast<std::int64_t>(cfg.pressure));
  out.attr("/parameters", "skin", cfg.skin.value_or(default_skin(cfg.dim)));
  if (cfg.aggregate) out.attr("/parameters", "aggregate", std::int64_t{1});
  out.attr("/parameters", "stop_reason", std::string(stop_reason_name(why)));
  std::vector<const gg::H5Input*> inputs;
  if (init.in) inputs.push_back(init.in.get());
  gg::write_provenance(out, gg::Provenance{"gg-sim", argv, cfg.seed}, inputs);
  out.commit();
}

// How to go on from the checkpoint: it holds the scene, so only the output is needed.
std::string resume_command(const SimConfig& cfg, const std::vector<std::string>& argv) {
  return (argv.empty() ? std::string("gg-sim") : argv[0]) + " --resume " + cfg.checkpoint_path() + " -o " + cfg.output;
}

std::string stalled_start_message(const SimConfig& cfg, double t) {
  char when[96];
  std::snprintf(when, sizeof when, "the clock stopped at t = %.6g%s", t, cfg.e == 1 ? " with e = 1" : ", at the start");
  const std::string what = std::string(when) + ", which no inelastic collapse does: disks are in contact";
  if (cfg.starts_from_file())
    return what + " in the start read from " + cfg.init + "; start from a frame whose disks are apart (nothing written)";
  return what + " in gg-sim's own " + cfg.init + " start, a bug in gg-sim: please report it with this command "
         "(nothing written); meanwhile try another --seed or --init";
}

// Runs the engine from `st` (a fresh start) or from the checkpoint cfg.resume (st == nullptr),
// checkpointing every cfg.checkpoint_every seconds and on SIGINT/SIGTERM.
template <int D, class Fx>
int simulate(const SimConfig& cfg, State<D>* st, const InitFile& init, const std::vector<std::string>& argv,
             bool show_progress) {
  EngineParameters par;
  par.rule = {cfg.e, cfg.delta, cfg.tc};
  par.skin = cfg.skin;
  const double t_start = st ? st->t0 : 0;
  par.t0 = t_start;
  par.collisions0 = st ? st->step0 : 0;
  gg::Box<D> box;
  std::unique_ptr<Engine<D, Fx>> eng;
  if (st) {
    box = st->box;
    eng = std::make_unique<Engine<D, Fx>>(box, st->r, st->v, par, st->image);
    // The engine holds the start now; a run's memory is the engine's alone.
    std::vector<Vec<D>>().swap(st->r);
    std::vector<Vec<D>>().swap(st->v);
    std::vector<Image<D>>().swap(st->image);
  } else {
    eng = std::make_unique<Engine<D, Fx>>(box, read_checkpoint<D>(cfg, &box), par);
  }
  gg::Progress progress(show_progress, "gg-sim");
  std::vector<double> edges(box.L.begin(), box.L.end());
  Recorder rec(cfg, eng->size(), D, edges, show_progress ? &progress : nullptr, t_start);
  if (!st) restore_recorder(cfg, rec);
  StopReason why;
  for (;;) {
    why = eng->run(cfg.t_max, cfg.max_collisions, rec);
    if (why != StopReason::kInterrupted || g_stop_requested) break;
    write_checkpoint<D>(cfg, box, eng->view(), rec);  // a periodic checkpoint was due
    rec.checkpoint_written();
  }
  // Elastic disks cannot collapse, nor can a gas before its first free flight: a stall then means
  // disks in contact at the start, colliding again and again at one instant.
  if (why == StopReason::kCollapse && (cfg.e == 1 || (st && eng->now() == t_start)))
    throw gg::RuntimeError(stalled_start_message(cfg, eng->now()));
  const bool keep_checkpoint = why == StopReason::kInterrupted && !cfg.checkpoint_path().empty();
  if (keep_checkpoint) write_checkpoint<D>(cfg, box, eng->view(), rec);
  rec.finish(*eng);
  write_output(cfg, argv, rec, init, why);
  const std::string where = cfg.output == "-" ? "the output" : cfg.output;
  switch (why) {
    case StopReason::kOneLeft:
      std::fprintf(stderr, "gg-sim: note: every particle has merged into one at t = %.6g; the run ends there (%s is "
                   "complete)\n", eng->now(), where.c_str());
      return 0;
    case StopReason::kOutgrewBox:
      std::fprintf(stderr,
                   "gg-sim: error: at t = %.6g a particle grew too large for the box (every edge must exceed two "
                   "of its diameters and a shell); %s holds everything recorded up to then; give a larger --L "
                   "(or --N) for later times\n", eng->now(), where.c_str());
      return gg::kExitRuntime;
    case StopReason::kCollapse:
      std::fprintf(stderr,
                   "gg-sim: error: inelastic collapse at t = %.17g after %.6g collisions per particle: the clock "
                   "stopped advancing; rerun with a collision cutoff (--delta 1e-4, or --tc 1e-4); %s holds "
                   "everything recorded up to then\n",
                   eng->now(), 2.0 * static_cast<double>(eng->collisions()) / static_cast<double>(eng->size()),
                   where.c_str());
      return gg::kExitRuntime;
    case StopReason::kInterrupted:
      if (keep_checkpoint)
        std::fprintf(stderr, "gg-sim: interrupted at t = %.6g; %s holds everything recorded so far; resume with: %s\n",
                     eng->now(), where.c_str(), resume_command(cfg, argv).c_str());
      else
        std::fprintf(stderr, "gg-sim: interrupted at t = %.6g; %s holds everything recorded so far (no checkpoint: give --checkpoint FILE to be able to resume)\n",
                     eng->now(), where.c_str());
      return gg::kExitRuntime;
    default:
      if (!cfg.checkpoint_path().empty()) std::remove(cfg.checkpoint_path().c_str());  // the output is complete
      return 0;
  }
}

// The scene's runtime choices become template arguments here, once, outside the event loop: a
// scene without cutoff, t_c, pressure or images runs an engine compiled without them, with no
// branch per collision or per move for an effect it does not use.
template <int D, bool Images>
int dispatch_effects(const SimConfig& cfg, State<D>* st, const InitFile& init, const std::vector<std::string>& argv,
                     bool show_progress) {
  const bool cut = cfg.delta > 0, tc = cfg.tc > 0, vir = cfg.pressure;
  const int key = (cut ? 4 : 0) + (tc ? 2 : 0) + (vir ? 1 : 0);
  switch (key) {
    case 0: return simulate<D, Effects<false, false, false, Images>>(cfg, st, init, argv, show_progress);
    case 1: return simulate<D, Effects<false, false, true, Images>>(cfg, st, init, argv, show_progress);
    case 2: return simulate<D, Effects<false, true, false, Images>>(cfg, st, init, argv, show_progress);
    case 3: return simulate<D, Effects<false, true, true, Images>>(cfg, st, init, argv, show_progress);
    case 4: return simulate<D, Effects<true, false, false, Images>>(cfg, st, init, argv, show_progress);
    case 5: return simulate<D, Effects<true, false, true, Images>>(cfg, st, init, argv, show_progress);
    case 6: return simulate<D, Effects<true, true, false, Images>>(cfg, st, init, argv, show_progress);
    default: return simulate<D, Effects<true, true, true, Images>>(cfg, st, init, argv, show_progress);
  }
}

template <int D>
int dispatch(const SimConfig& cfg, State<D>* st, const InitFile& init, const std::vector<std::string>& argv,
             bool show_progress) {
  // Aggregation excludes the other effects (SimConfig::resolve).
  if (cfg.aggregate) return simulate<D, Aggregation>(cfg, st, init, argv, show_progress);
  if (cfg.unwrapped) return dispatch_effects<D, true>(cfg, st, init, argv, show_progress);
  return dispatch_effects<D, false>(cfg, st, init, argv, show_progress);
}

template <int D>
int run_in(const SimConfig& cfg, const std::vector<std::string>& argv, bool show_progress) {
  const InitFile init = open_init_file(cfg);
  const std::string scratch = gg::scratch_dir_for_output(cfg.output);
  if (!cfg.resume.empty()) {
    require_resources(cfg, checkpoint_particles(cfg.resume), scratch);
    return dispatch<D>(cfg, nullptr, init, argv, show_progress);
  }
  // A file's particles are counted once it has been read and checked (a damaged file may claim any
  // number); the scene's before anything is built.
  if (!cfg.starts_from_file()) require_resources(cfg, cfg.N, scratch);
  Random rng(cfg.seed);
  State<D> st = initial_state<D>(cfg, init, rng);
  if (cfg.starts_from_file()) require_resources(cfg, st.r.size(), scratch);
  if (cfg.equilibrate > 0) equilibrate<D>(st, cfg);
  return dispatch<D>(cfg, &st, init, argv, show_progress);
}

}  // namespace

int run(const SimConfig& cfg, const std::vector<std::string>& argv, bool show_progress) {
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
  if (!cfg.resume.empty()) require_same_scene(cfg.resume, checkpoint_scene(cfg.resume), cfg);
  if (!cfg.resume.empty() && checkpoint_dimension(cfg.resume) != cfg.dim)
    throw gg::UsageError("--resume " + cfg.resume + " holds a run in another dimension than --dim " + std::to_string(cfg.dim));
  switch (cfg.dim) {
    case 1: return run_in<1>(cfg, argv, show_progress);
    case 2: return run_in<2>(cfg, argv, show_progress);
    default: return run_in<3>(cfg, argv, show_progress);
  }
}

}  // namespace ggsim
