// gg-sim: event-driven molecular dynamics of inelastic hard spheres (3D), disks (2D) and rods (1D).
// Thin main: CLI11 -> validated SimConfig -> ggsim::run -> exit status.
#include <csignal>
#include <memory>
#include <set>
#include <string>

#include "gg/cli.hpp"
#include "gg/errors.hpp"
#include "ggsim/checkpoint.hpp"
#include "ggsim/cli_scene_options.hpp"
#include "ggsim/run.hpp"
#include "ggsim/scene_effect.hpp"
#include "ggsim/stop_request.hpp"

int main(int argc, char** argv) {
  return gg::guarded_main("gg-sim", [&] {
    ggsim::SimConfig c;
    CLI::App app{"gg-sim: event-driven MD of inelastic hard spheres (--dim 3), disks (--dim 2) or rods (--dim 1) in a periodic box.\n"
                 "Units: diameter = mass = k_B = 1; T = <v_x^2>; E = kinetic energy per particle.",
                 "gg-sim"};
    gg::CommonFlags common;
    gg::add_common_flags(app, common);
    app.set_config("--scene", "", "Scene file (INI/TOML); every key is also a flag, and flags override it");
    app.add_option("--dim", c.dim, "Dimension, 1 (rods), 2 (disks) or 3 (spheres)")->capture_default_str();
    auto* n = app.add_option("--N", c.N, "Number of particles (give two of --N, --L, --rho)")
                  ->transform(gg::whole_number());
    auto* l = app.add_option("--L", c.L, "Box edge in diameters");
    auto* rho = app.add_option("--rho", c.rho, "Number density N/L^d (packing fraction: pi rho/4 in 2D, pi rho/6 in 3D)");
    // Required (docs/DESIGN.md): a forgotten --e would silently run an elastic gas. (Checked below: a
    // resumed run has it in its checkpoint.)
    auto* e = app.add_option("--e", c.e, "Coefficient of restitution, 0 <= e <= 1 (1: elastic); required");
    auto* t0 = app.add_option("--T0", c.T0, "Initial temperature (a start from a file with velocities keeps its "
                              "own unless --T0 is given)")->capture_default_str();
    app.add_option("--seed", c.seed, "Random seed (same scene and seed give bit-identical output)")
        ->transform(gg::whole_number())
        ->capture_default_str();
    app.add_option("--init", c.init, "Start: random (random sequential addition), lattice, or FILE.h5 (last frame)")
        ->capture_default_str();
    app.add_option("--equilibrate", c.equilibrate, "Elastic collisions per particle before t = 0 (then T reset to T0)")
        ->capture_default_str();
    auto* t_max = app.add_option("--t-max", c.t_max, "Stop at this simulated time (inf: no limit, with --max-collisions)");
    app.add_option("--max-collisions", c.max_collisions, "Stop after this many collisions (e.g. 4e6)")
      ->transform(gg::whole_number());
    app.add_option("--samples-per-decade", c.samples_per_decade, "E(t) and collision samples per decade of time")
        ->capture_default_str();
    app.add_option("--sample-from", c.sample_from, "First log-spaced sample time (t = 0 is always sampled)")
        ->capture_default_str();
    gg::add_list_option(app, "--snapshots", c.snapshots, "Snapshot times t1,t2,...");
    app.add_option("--snapshots-per-decade", c.snapshots_per_decade, "Log-spaced snapshots (0 = none)")
        ->capture_default_str();
    app.add_option("--snapshots-from", c.snapshots_from, "First log-spaced snapshot time")->capture_default_str();
    app.add_flag("--velocities", c.velocities, "Store velocities with the snapshots");
    ggsim::CliSceneOptions effect_options(app);
    for (const ggsim::SceneEffect* effect : ggsim::scene_effects()) effect->add_options(effect_options, c);
    app.add_flag("--float-snapshots", c.float_snapshots, "Store snapshots in single precision (half the disk)");
    app.add_option("--skin", c.skin,
                   "Shell skin in diameters (default 0.7 in 1D and 2D, 0.3 in 3D): speed only (the dynamics is exact "
                   "for any skin; round-off, and with it a chaotic trajectory, may differ); at least ~100 L/2^32 "
                   "sqrt(dim), the step of the shell centres");
    app.add_option("--checkpoint", c.checkpoint, "Checkpoint file (default: OUTPUT.checkpoint.h5; written on "
                   "SIGINT/SIGTERM and every --checkpoint-every seconds, removed when the run completes)");
    app.add_option("--checkpoint-every", c.checkpoint_every, "Wall-clock seconds between checkpoints (0 = only when "
                   "interrupted)")->capture_default_str();
    app.add_option("--resume", c.resume, "Continue from this checkpoint: its scene is stored in it, so no other flag "
                   "but -o is needed; flags given must agree with it, but --t-max and --max-collisions may extend the run");
    app.add_flag("--allow-other-build", c.allow_other_build, "With --resume: go on from a checkpoint that another "
                 "build of gg-sim wrote (refused otherwise: a run's pieces should share one build); the output's "
                 "/parameters/provenance/pieces records it");
    app.add_flag("--continue", c.continue_clock, "With --init FILE: go on from its last frame keeping its clock, "
                 "collision count and velocities (a finished run continued to a later --t-max)");
    bool no_resource_check = false;
    app.add_flag("--no-resource-check", no_resource_check, "Run even if the memory or disk space the run needs "
                 "(estimated before it starts) is more than the machine has");
    app.add_option("-o,--output", c.output, "Output H5MD file, or - for stdout")->required();
    app.add_option("--author", c.author, "Author named in the output's /h5md/author (default: $GG_AUTHOR, else $USER)");
    if (const int status = gg::parse_cli(app, argc, argv); status >= 0) return status;
    c.T0_given = t0->count() > 0;
    c.t_max_given = t_max->count() > 0;
    c.resource_check = !no_resource_check;
    bool n_given = n->count() > 0, l_given = l->count() > 0;
    std::string instead_of_e;  // the first scene part that stands in for --e, and why
    for (const ggsim::SceneEffect* effect : ggsim::scene_effects())
      if (instead_of_e.empty()) instead_of_e = effect->replaces_restitution(c);
    std::unique_ptr<ggsim::SavedRun> saved;  // read once: its scene here, the rest by the run
    if (!c.resume.empty()) {
      saved = std::make_unique<ggsim::SavedRun>(c.resume, c.allow_other_build);
      std::set<std::string> given;  // as the command line and the scene file gave them
      for (const CLI::Option* opt : app.get_options())
        if (opt->count() > 0 && !opt->get_lnames().empty()) given.insert(opt->get_lnames().front());
      ggsim::adopt_scene(c, saved->scene(), given, &n_given, &l_given);
    } else if (!instead_of_e.empty() && e->count() > 0) {
      throw gg::UsageError("--e has no meaning with " + instead_of_e + "; drop it");
    } else if (e->count() == 0 && instead_of_e.empty()) {
      throw gg::UsageError("--e is required: the coefficient of restitution (1 for an elastic gas)");
    }
    c.resolve(n_given, l_given, rho->count() > 0);
    std::signal(SIGINT, ggsim::request_stop);
    std::signal(SIGTERM, ggsim::request_stop);
    return ggsim::run(c, gg::argv_strings(argc, argv), common.show_progress(), saved.get());
  }, "--samples-per-decade, the snapshots or --N");
}
