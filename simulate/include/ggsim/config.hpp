#pragma once
// A scene: everything gg-sim needs to know, validated (docs/DESIGN.md "Command lines").
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "ggsim/effects/effect_parameters.hpp"
#include "ggsim/skin.hpp"

namespace ggsim {

struct SimConfig {
  int dim = 2;
  // Any two of N, L, rho (0 = not given); resolve() fills in the third.
  std::uint64_t N = 0;
  double L = 0;
  double rho = 0;
  bool rho_given = false;  // resolve(): whether the density was given (else it follows from N and the box)
  double e = 1;         // coefficient of restitution
  double T0 = 1;        // initial temperature
  // Whether the scene names T0: a start from a file with velocities keeps its temperature unless
  // it does (then the velocities are scaled to T0).
  bool T0_given = false;
  std::uint64_t seed = 1;
  std::string init = "random";  // random | lattice | FILE.h5
  double equilibrate = 0;       // elastic collisions per particle before t = 0
  double t_max = std::numeric_limits<double>::infinity();
  bool t_max_given = false;     // an explicit --t-max inf is no time limit, not a forgotten one
  std::uint64_t max_collisions = std::numeric_limits<std::uint64_t>::max();
  double samples_per_decade = 20;
  double sample_from = 0.01;    // first log-spaced sample time (t = 0 is always sampled)
  std::vector<double> snapshots;     // explicit snapshot times
  double snapshots_per_decade = 0;   // or log-spaced snapshots from snapshots_from
  double snapshots_from = 1;
  bool velocities = false;      // store velocities with the snapshots
  bool float_snapshots = false; // store snapshots in single precision
  // The ballistic aggregation model: touching particles merge (contact/aggregate.hpp); no restitution.
  bool aggregate = false;
  // Each effect's parameters, which its scene part (scene_effect.hpp) declares, checks and
  // fingerprints, and its class in effects/ reads.
  EffectParameters effects;
  std::optional<double> skin;   // shell diameter beyond contact, sigma units (speed only); resolve(): default_skin(dim)
  std::string output;
  std::string author;            // /h5md/author (empty: $GG_AUTHOR, else $USER); not in the fingerprint
  std::string checkpoint;        // checkpoint file (default: OUTPUT.checkpoint.h5)
  double checkpoint_every = 0;   // wall seconds between checkpoints (0 = only on SIGINT/SIGTERM)
  std::string resume;            // continue from this checkpoint
  bool allow_other_build = false;  // resume a checkpoint another build of gg-sim wrote (recorded)
  // --continue: a start from a file (--init) that keeps its clock and collision count (the time
  // and step of its last frame) and its velocities, so that a finished run goes on to a later t_max.
  bool continue_clock = false;
  bool resource_check = true;    // refuse a run the machine has not the memory or disk for

  // Whether the start is read from a file (--init FILE.h5).
  bool starts_from_file() const { return init != "random" && init != "lattice"; }
  // Whether the run records snapshots (the flags that shape them mean nothing without).
  bool takes_snapshots() const { return !snapshots.empty() || snapshots_per_decade > 0; }
  // Refuses a flag that shapes the snapshots (`what` it does) in a run that takes none, where it
  // would do nothing.
  void require_snapshots_for(bool given, const std::string& flag, const std::string& what) const;
  // Every value that shapes the trajectory or what is recorded, as text: a checkpoint is only
  // resumed by the scene that wrote it.
  std::string fingerprint() const;
  // Where checkpoints go: --checkpoint, else next to the output (none for a run to stdout).
  std::string checkpoint_path() const;

  // Checks ranges and N/L/rho consistency; fills the missing one of N, L, rho.
  // Throws gg::UsageError naming the flag and the fix. (Whether --e is given is main's to check:
  // a resumed run takes it from its checkpoint.)
  void resolve(bool n_given, bool l_given, bool rho_given);
};

}  // namespace ggsim
