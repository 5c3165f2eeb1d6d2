// The keys of a scene that no effect owns (scene_effect.hpp base_scene_keys()): one table, in the order
// of the fingerprint, from which SimConfig::fingerprint(), the keys a --resume reads back
// (resume_scene.cpp) and the output's /parameters (run_output.cpp) all follow, as an effect's do from
// its scene part. Their options and checks are gg-sim's own (gg_sim_main.cpp, SimConfig::resolve()).
#include <limits>

#include "scene_effects.hpp"

namespace ggsim {

std::vector<SceneKey> base_scene_keys() {
  // A --resume sets N and L itself (adopt_scene(): for a start without a file, and only when none of
  // --N, --L, --rho is given). /parameters has the run's N, L and T0 (write_output(): with --init FILE
  // the file's particles, box and temperature).
  SceneKey n = scene_key("N", &SimConfig::N, "", Written::kNever), l = scene_key("L", &SimConfig::L, "", Written::kNever);
  n.set = l.set = nullptr;
  // Whether T0 was named changes only a start from a file (scaled or kept velocities), so only the
  // fingerprint of such a start has it; --T0 names it.
  SceneKey t0_given = scene_key("T0_given", &SimConfig::T0_given, "0", Written::kNever);
  t0_given.flag = "T0";
  t0_given.when = [](const SimConfig& c) { return c.starts_from_file(); };
  // No budget is infinite in /parameters, as an unset t_max is (not 2^64 - 1 rounded to 1.8e19).
  SceneKey budget = scene_key("max_collisions", &SimConfig::max_collisions);
  budget.written_as = [](const SimConfig& c) {
    return SceneValue(c.max_collisions == std::numeric_limits<std::uint64_t>::max()
                          ? std::numeric_limits<double>::infinity()
                          : static_cast<double>(c.max_collisions));
  };
  // A fingerprint has --continue only when it is given (one without it reads back as 0); /parameters
  // always.
  SceneKey go_on = scene_key("continue", &SimConfig::continue_clock, "0", Written::kAlways);
  go_on.when = [](const SimConfig& c) { return c.continue_clock; };
  return {scene_key("dim", &SimConfig::dim),
          n,
          l,
          scene_key("e", &SimConfig::e),
          scene_key("T0", &SimConfig::T0, "", Written::kNever),
          scene_key("seed", &SimConfig::seed),
          scene_key("init", &SimConfig::init),
          scene_key("equilibrate", &SimConfig::equilibrate),
          scene_key("t_max", &SimConfig::t_max),
          budget,
          scene_key("samples_per_decade", &SimConfig::samples_per_decade),
          scene_key("sample_from", &SimConfig::sample_from),
          scene_key("snapshots", &SimConfig::snapshots),
          t0_given,
          scene_key("snapshots_per_decade", &SimConfig::snapshots_per_decade),
          scene_key("snapshots_from", &SimConfig::snapshots_from),
          scene_key("velocities", &SimConfig::velocities),
          // The snapshots' type says it in the output.
          scene_key("float_snapshots", &SimConfig::float_snapshots, "", Written::kNever),
          scene_key("skin", &SimConfig::skin, [](const SimConfig& c) { return default_skin(c.dim); }),
          go_on};
}

}  // namespace ggsim
