#pragma once
// A scene: everything gg-sim needs to know, validated (docs/DESIGN.md "Command lines").
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "ggsim/skin.hpp"

namespace ggsim {

// The moment of inertia of a uniform disk (2D) or sphere (3D), in units of m sigma^2 / 4.
inline double default_inertia(int dim) { return dim == 3 ? 0.4 : 0.5; }

struct SimConfig {
  int dim = 2;
  // Any two of N, L, rho (0 = not given); resolve() fills in the third.
  std::uint64_t N = 0;
  double L = 0;
  double rho = 0;
  bool rho_given = false;  // resolve(): whether the density was given (else it follows from N and the box)
  double e = 1;         // coefficient of restitution
  double delta = 0;     // velocity cutoff (0 = off)
  double tc = 0;        // TC-model time (0 = off)
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
  bool unwrapped = false;       // store the periodic image of every particle with the snapshots
  bool pressure = false;        // record the pressure (collisional virial)
  bool float_snapshots = false; // store snapshots in single precision
  // The ballistic aggregation model: touching particles merge (aggregation.hpp); no restitution.
  bool aggregate = false;
  // A driven gas (docs/PHYSICS.md "Driven gas"): "white-noise" (effects/white_noise_drive.hpp), or empty for none.
  std::string drive;
  double drive_strength = 0;  // XI: d<v^2>/dt = 2 d XI^2 per particle
  double drive_rate = 0;      // kicks per particle per unit time; 0: default_drive_rate()
  bool driven() const { return !drive.empty(); }
  // Rough particles (docs/PHYSICS.md "Rough particles"): --beta, the tangential restitution in
  // [-1, 1]; unset for smooth ones. q of the moment of inertia I = q m sigma^2 / 4 (resolve():
  // default_inertia(dim)); the rotational temperature of the start (unset: no rotation).
  std::optional<double> beta;
  std::optional<double> inertia;
  std::optional<double> T0_rot;
  bool rough() const { return beta.has_value(); }
  // Viscoelastic particles (effects/viscoelastic_restitution.hpp): K = A alpha^(2/5) of the
  // dissipative Hertz law, e = epsilon(K |n.v_ij|^(1/5)) instead of --e; 0: none.
  double viscoelastic = 0;
  // Walls across the last axis at distance walls_height (0: none), their restitution, a thermal
  // bottom wall's temperature (0: not thermal), a vibrated bottom wall's amplitude and frequency, and
  // gravity along the last axis (effects/walls.hpp, docs/PHYSICS.md "Walls and gravity").
  double walls_height = 0, wall_e = 1, wall_T = 0, wall_amplitude = 0, wall_frequency = 0, gravity = 0;
  // A mixture or a polydisperse gas (mixture.hpp; docs/DESIGN.md "Mixtures"), as given: radii per
  // species or "uniform:LO:HI", masses per species (or one), number fractions per species.
  std::string radii, masses, fractions;
  bool mixture() const { return !radii.empty() || !masses.empty(); }
  std::optional<double> skin;   // shell diameter beyond contact, sigma units (speed only); resolve(): default_skin(dim)
  std::string output;
  std::string author;            // /h5md/author (empty: $GG_AUTHOR, else $USER); not in the fingerprint
  std::string checkpoint;        // checkpoint file (default: OUTPUT.checkpoint.h5)
  double checkpoint_every = 0;   // wall seconds between checkpoints (0 = only on SIGINT/SIGTERM)
  std::string resume;            // continue from this checkpoint
  // --continue: a start from a file (--init) that keeps its clock and collision count (the time
  // and step of its last frame) and its velocities, so that a finished run goes on to a later t_max.
  bool continue_clock = false;
  bool resource_check = true;    // refuse a run the machine has not the memory or disk for

  // Whether the start is read from a file (--init FILE.h5).
  bool starts_from_file() const { return init != "random" && init != "lattice"; }
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
