#include "run_output.hpp"

#include <cstdio>
#include <string>
#include <vector>

#include "gg/errors.hpp"
#include "gg/h5file.hpp"
#include "gg/provenance.hpp"
#include "gg/trajectory.hpp"
#include "ggsim/scene_effect.hpp"
#include "ggsim/restart_frame.hpp"

namespace ggsim {

namespace {

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

// A time-dependent H5MD element /particles/all/NAME beside the positions, at the snapshots' times:
// `components` values per particle ([T][N] for one).
void write_element(gg::H5Output& out, const gg::Snapshots& index, const std::string& name,
                   const gg::FrameReader& frames, std::size_t components, const std::string& unit) {
  const std::string group = "/particles/all/" + name;
  out.write(group + "/step", index.step);
  out.write(group + "/time", index.time);
  out.attr(group + "/time", "unit", gg::kUnitTime);
  std::vector<std::size_t> shape{index.frames(), index.n_particles};
  if (components > 1) shape.push_back(components);
  out.write_rows(group + "/value", shape, frames);
  out.attr(group + "/value", "unit", unit);
}

// The snapshots' more fields (each effect's: docs/DESIGN.md "Files") as H5MD time-dependent elements
// beside the positions, one row per start particle.
void write_more_fields(gg::H5Output& out, const SnapshotStore& snaps) {
  for (std::size_t m = 0; m < snaps.more_fields().size(); ++m) {
    const FrameField& f = snaps.more_fields()[m];
    write_element(out, snaps.index(), f.name, snaps.more(m), f.components, f.unit);
  }
}

// How to go on from the checkpoint: it holds the scene, so only the output is needed.
std::string resume_command(const SimConfig& cfg, const std::vector<std::string>& argv) {
  return (argv.empty() ? std::string("gg-sim") : argv[0]) + " --resume " + cfg.checkpoint_path() + " -o " + cfg.output;
}

}  // namespace

void write_output(const SimConfig& cfg, const std::vector<std::string>& argv, const Recorder& rec,
                  const InitFile& init, StopReason why, const RunPieces& pieces) {
  gg::H5Output out(cfg.output);
  const SnapshotStore& snaps = rec.snapshots();
  gg::Snapshots index = snaps.index();  // box, times and steps (the frames stay in the store)
  index.author = cfg.author;
  index.periodic.assign(index.edges.size(), true);
  for (const SceneEffect* effect : scene_effects()) effect->close_axes(cfg, index.periodic);
  for (double k : rec.fixed("species")) index.species.push_back(static_cast<std::int64_t>(k));
  gg::write_snapshots(out, index, snaps.positions(), snaps.velocities(), snaps.images(), "gg-sim", cfg.float_snapshots);
  if (cfg.float_snapshots) write_restart_frame(out, snaps);
  gg::write_observable(out, "kinetic_energy", rec.energy(), gg::kUnitEnergy);
  gg::write_observable(out, "collisions_per_particle", rec.collisions());
  write_more_fields(out, snaps);
  for (const auto& [name, o] : rec.effect_observables()) gg::write_observable(out, name, o.series, o.unit, o.width);
  // Every scene value, so a file says how it was made (docs/DESIGN.md /parameters): the scene's own
  // keys (scene_effect.hpp base_scene_keys()), the run's size, density, temperature and clock at its
  // start, then each effect's.
  out.create_group("/parameters");
  write_keys(out, base_scene_keys(), cfg, true);
  // The particles, box and density of the run as it is (with --init FILE they come from the file, not
  // from the flags).
  out.attr("/parameters", "N", static_cast<std::int64_t>(index.n_particles));
  out.attr("/parameters", "L", index.edges[0]);
  double volume = 1;
  for (double L : index.edges) volume *= L;
  out.attr("/parameters", "rho", static_cast<double>(index.n_particles) / volume);
  // The temperature the run started at: a start from a file that kept the file's velocities has
  // the file's (2 E(0) / d; the first sample is at t = 0). If a resumed run's start file is gone,
  // 2 E(0) / d is right either way (drawn velocities have T0 up to round-off).
  const bool kept_file_temperature = init.has_velocities.value_or(true) && !cfg.T0_given && cfg.equilibrate == 0;
  out.attr("/parameters", "T0", kept_file_temperature ? 2 * rec.energy().value.front() / cfg.dim : cfg.T0);
  // The clock at the start: 0, or the file's with --continue (the first sample is at it).
  out.attr("/parameters", "t_start", rec.energy().time.empty() ? 0.0 : rec.energy().time.front());
  const SceneSize size{static_cast<double>(index.n_particles), volume};
  for (const SceneEffect* effect : scene_effects()) {
    effect->write_results(out, cfg, rec, size);
    effect->write_parameters(out, cfg);
  }
  out.attr("/parameters", "stop_reason", std::string(stop_reason_name(why)));
  std::vector<const gg::H5Input*> inputs;
  if (init.in) inputs.push_back(init.in.get());
  gg::write_provenance(out, gg::Provenance{"gg-sim", argv, cfg.seed}, inputs);
  pieces.write(out, "/parameters/provenance/pieces");
  out.commit();
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

int report_end(const SimConfig& cfg, const std::vector<std::string>& argv, StopReason why, double now,
               double collisions_per_particle, bool keep_checkpoint) {
  const std::string where = cfg.output == "-" ? "the output" : cfg.output;
  switch (why) {
    case StopReason::kOneLeft:
      std::fprintf(stderr, "gg-sim: note: every particle has merged into one at t = %.6g; the run ends there (%s is "
                   "complete)\n", now, where.c_str());
      return 0;
    case StopReason::kOutgrewBox:
      std::fprintf(stderr,
                   "gg-sim: error: at t = %.6g a particle grew too large for the box (every edge must exceed two "
                   "of its diameters and a shell); %s holds everything recorded up to then; give a larger --L "
                   "(or --N) for later times\n", now, where.c_str());
      return gg::kExitRuntime;
    case StopReason::kCollapse: {
      std::string cutoffs;  // the scene parts' that stop a collapse
      for (const SceneEffect* effect : scene_effects())
        if (const std::string c = effect->collapse_cutoff(); !c.empty()) cutoffs += (cutoffs.empty() ? "" : ", or ") + c;
      std::fprintf(stderr,
                   "gg-sim: error: inelastic collapse at t = %.17g after %.6g collisions per particle: the clock "
                   "stopped advancing; rerun with a collision cutoff (%s); %s holds everything recorded up to then\n",
                   now, collisions_per_particle, cutoffs.c_str(), where.c_str());
      return gg::kExitRuntime;
    }
    case StopReason::kInterrupted:
      if (keep_checkpoint)
        std::fprintf(stderr, "gg-sim: interrupted at t = %.6g; %s holds everything recorded so far; resume with: %s\n",
                     now, where.c_str(), resume_command(cfg, argv).c_str());
      else
        std::fprintf(stderr, "gg-sim: interrupted at t = %.6g; %s holds everything recorded so far (no checkpoint: give --checkpoint FILE to be able to resume)\n",
                     now, where.c_str());
      return gg::kExitRuntime;
    default:
      if (!cfg.checkpoint_path().empty()) std::remove(cfg.checkpoint_path().c_str());  // the output is complete
      return 0;
  }
}

}  // namespace ggsim
