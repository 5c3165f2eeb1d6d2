#include "ggsim/config.hpp"

#include <cmath>
#include <sstream>
#include <string>

#include "gg/errors.hpp"
#include "gg/h5file.hpp"
#include "ggsim/particles.hpp"
#include "scene/scene_effects.hpp"

namespace ggsim {

void SimConfig::resolve(bool n_given, bool l_given, bool rho_given) {
  require(dim >= 1 && dim <= 3, "--dim must be 1, 2 or 3 (got " + std::to_string(dim) + ")");
  const int given = int(n_given) + int(l_given) + int(rho_given);
  this->rho_given = rho_given;
  if (starts_from_file())
    require(given == 0, "--init " + init + " fixes N, L and rho from the file; drop --N, --L and --rho");
  else
    require(given == 2, "give exactly two of --N, --L, --rho (got " + std::to_string(given) + ")");
  if (l_given) require(std::isfinite(L) && L > 0, "--L must be a positive number of diameters (got " + str(L) + ")");
  if (rho_given) require(std::isfinite(rho) && rho > 0, "--rho must be positive (got " + str(rho) + ")");
  if (n_given) require(N > 0, "--N must be at least 1");
  if (!n_given && given == 2) N = static_cast<std::uint64_t>(std::llround(rho * std::pow(L, dim)));
  if (!l_given && given == 2) L = std::pow(static_cast<double>(N) / rho, 1.0 / dim);
  if (given == 2) rho = static_cast<double>(N) / std::pow(L, dim);
  if (given == 2) require(N > 0, "--rho x --L^d gives no particle; raise --rho or --L");
  require_engine_holds(N);
  require(std::isfinite(e) && e >= 0 && e <= 1, "--e must lie in [0, 1] (got " + str(e) + ")");
  require(std::isfinite(T0) && T0 > 0, "--T0 must be positive (got " + str(T0) + ")");
  // Beyond this the squared speeds times squared box lengths in the collision predictions overflow a
  // double (docs/DESIGN.md "Conventions of every tool").
  require(T0 >= 1e-100 && T0 <= 1e100, "--T0 " + str(T0) + " lies outside [1e-100, 1e100], where the collision "
                                       "arithmetic overflows; choose units that put T0 nearer 1");
  require(std::isfinite(equilibrate) && equilibrate >= 0, "--equilibrate must be >= 0 collisions per particle");
  require(t_max > 0, "--t-max must be positive (got " + str(t_max) + ")");
  const bool budget = max_collisions != std::numeric_limits<std::uint64_t>::max();
  require(std::isfinite(t_max) || budget || !t_max_given,
          "--t-max inf never ends the run; give a finite --t-max, or --max-collisions to stop after a number of collisions");
  require(std::isfinite(t_max) || budget, "give --t-max or --max-collisions, or the run never ends");
  require(samples_per_decade > 0 && std::isfinite(samples_per_decade), "--samples-per-decade must be positive");
  require(sample_from > 0 && std::isfinite(sample_from), "--sample-from must be positive");
  require(snapshots_per_decade >= 0 && std::isfinite(snapshots_per_decade), "--snapshots-per-decade must be >= 0");
  require(snapshots_from > 0 && std::isfinite(snapshots_from), "--snapshots-from must be positive");
  require(snapshots.empty() || snapshots_per_decade == 0, "give --snapshots or --snapshots-per-decade, not both");
  for (std::size_t k = 1; k < snapshots.size(); ++k)
    require(snapshots[k] > snapshots[k - 1], "--snapshots times must increase, each given once (got " +
                                                 str(snapshots[k - 1]) + " before " + str(snapshots[k]) +
                                                 "); list them in order");
  for (double t : snapshots) {
    require(std::isfinite(t) && t >= 0, "--snapshots times must be finite and >= 0 (got " + str(t) + ")");
    require(t <= t_max, "--snapshots time " + str(t) + " lies beyond --t-max " + str(t_max) +
                            ", so it would never be taken; drop it or raise --t-max");
  }
  require_snapshots_for(velocities, "--velocities", "stores velocities with the snapshots");
  require_snapshots_for(float_snapshots, "--float-snapshots", "shapes the snapshots");
  require(!allow_other_build || !resume.empty(), "--allow-other-build goes with --resume CHECKPOINT; drop it");
  if (!skin) skin = default_skin(dim);
  require(*skin > 0 && std::isfinite(*skin), "--skin must be positive");
  if (continue_clock) {
    require(starts_from_file(), "--continue goes on from a file's last frame; give it with --init FILE.h5");
    require(equilibrate == 0, "--continue keeps the file's clock and velocities; drop --equilibrate");
    require(!T0_given, "--continue keeps the file's velocities and their temperature; drop --T0");
  }
  check_combinations(*this);
  for (const SceneEffect* effect : scene_effects()) effect->check(*this);
  require(!output.empty(), "give an output file with -o FILE.h5 (or -o - for stdout)");
  require(std::isfinite(checkpoint_every) && checkpoint_every >= 0, "--checkpoint-every must be >= 0 seconds");
  require(checkpoint_every == 0 || !checkpoint_path().empty(),
          "--checkpoint-every with -o - (or a device or pipe) needs --checkpoint FILE (there is no output file to put it beside)");
}

void SimConfig::require_snapshots_for(bool given, const std::string& flag, const std::string& what) const {
  require(!given || takes_snapshots(), flag + " " + what + ", and the run takes none; add --snapshots or "
                                       "--snapshots-per-decade, or drop it");
}

std::string SimConfig::checkpoint_path() const {
  if (!checkpoint.empty()) return checkpoint;
  return gg::is_stream_output(output) ? std::string() : output + ".checkpoint.h5";
}

std::string SimConfig::fingerprint() const {
  std::ostringstream s;
  s.precision(17);
  fingerprint_keys(s, base_scene_keys(), *this, true);
  for (const SceneEffect* effect : scene_effects()) effect->fingerprint(*this, s);
  return s.str().substr(1);  // (each key comes with the space before it)
}

}  // namespace ggsim
