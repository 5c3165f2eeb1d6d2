#pragma once
// A checkpoint holds the scene of its run (SimConfig::fingerprint(), key=value pairs), so that
// `gg-sim --resume CK -o OUT` continues it without the original command: every scene value the
// command does not give is taken from there, and every one it gives must agree with it, but for
// --t-max and --max-collisions, which may extend the run.
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "ggsim/config.hpp"

namespace ggsim {

// key -> value, in the order of the fingerprint.
using SceneValues = std::vector<std::pair<std::string, std::string>>;

// Throws gg::UsageError naming `source` if the text is not a fingerprint of a known scene.
SceneValues parse_scene(const std::string& fingerprint, const std::string& source);

// Takes every value of `stored` whose option is not among `given` (long option names without the
// dashes, e.g. "t-max", as the command line or the scene file gave them) into `cfg`; N and L only
// for a start without a file and when none of N, L, rho is given (then *n_given and *l_given are set).
void adopt_scene(SimConfig& cfg, const SceneValues& stored, const std::set<std::string>& given, bool* n_given,
                 bool* l_given);

// Throws gg::UsageError naming the first scene key whose value in `cfg` (resolved) differs from the
// checkpoint's, with both values; --t-max and --max-collisions may be larger than stored.
void require_same_scene(const std::string& checkpoint, const SceneValues& stored, const SimConfig& cfg);

// The value of `key` in `scene` ("" if absent).
std::string scene_value(const SceneValues& scene, const std::string& key);

}  // namespace ggsim
