#pragma once
// An effect's part of a scene (docs/DESIGN.md "Where an effect lives"): its command-line options
// and their values (its parameters, SimConfig::effects), their checks, the effects it cannot be
// combined with, its keys (one table, from which its part of the fingerprint a checkpoint compares
// and resumes from and of the output's /parameters both follow), what it writes beside its
// observables, the axes its box is not periodic along, whether the scene uses it, its start state
// and its share of the run's memory. gg-sim, SimConfig, the start, the resume code and the output
// ask every effect in scene_effects() in turn, so an effect's scene lives in one file of src/scene/,
// which defines its registry entry's scene() (effects/registry_entry.hpp). (The engine's side of an
// effect is its class in effects/, which reads the same parameters.)
#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <functional>
#include <optional>
#include <ostream>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "ggsim/config.hpp"
#include "ggsim/effects/effect_state.hpp"
#include "ggsim/mixture.hpp"
#include "ggsim/random.hpp"

namespace gg {
class H5Input;
class H5Output;
struct Snapshots;
}

namespace ggsim {

class Recorder;

// Where the output's /parameters has a scene key: when the scene uses the effect, in every run (0
// when unused: a cutoff, which the study's scripts read from every output), or not at all (the
// output has it elsewhere, or the value the run derived from it: write_results()).
enum class Written { kWhenUsed, kAlways, kNever };

// A value of a scene key: a number, a switch (1 or 0), a count, a text or a list of numbers.
using SceneValue = std::variant<double, std::int64_t, std::uint64_t, std::string, std::vector<double>>;

// A scene key: its name in a fingerprint and in /parameters, the option that sets it (long name
// without the dashes), how its fingerprint text goes back into a SimConfig, the text a fingerprint
// leaves out (the value of a scene without it), its value and where /parameters has it; whether the
// scene has it beside its part being used (null: always); its value in /parameters where that is
// not its fingerprint's (null: get's). A scene part's keys are one table (SceneEffect::keys(), and
// base_scene_keys() for the keys no effect owns), made with scene_key().
struct SceneKey {
  std::string name;
  std::string flag;
  std::function<void(SimConfig&, const std::string&)> set;
  std::string absent = "";
  std::function<SceneValue(const SimConfig&)> get = nullptr;
  Written written = Written::kWhenUsed;
  std::function<bool(const SimConfig&)> when = nullptr;
  std::function<SceneValue(const SimConfig&)> written_as = nullptr;
};

namespace scene_detail {
// Where a key's value lives: an effect's parameters P in SimConfig::effects, or the SimConfig itself.
template <class P>
const P& part(const SimConfig& c) {
  if constexpr (std::is_same_v<P, SimConfig>) return c;
  else return c.effects.get<P>();
}
template <class P>
P& part(SimConfig& c) {
  if constexpr (std::is_same_v<P, SimConfig>) return c;
  else return c.effects.set<P>();
}
inline std::string flag_of(std::string name) {
  for (char& ch : name)
    if (ch == '_') ch = '-';
  return name;
}
// The numbers of a fingerprint's list, "10,50," (each followed by a comma).
inline std::vector<double> numbers(const std::string& s) {
  std::vector<double> v;
  for (std::size_t at = 0; at < s.size();) {
    const std::size_t end = std::min(s.find(',', at), s.size());
    if (end > at) v.push_back(std::strtod(s.substr(at, end - at).c_str(), nullptr));
    at = end + 1;
  }
  return v;
}
}  // namespace scene_detail

// The key `name` whose value is the member `field` of P (an effect's parameters, or SimConfig): a
// number, a switch (a bool, written 1 or 0), a whole number, a text or a list of numbers. Its option
// is the name with '-' for '_' (wall_e: --wall-e).
template <class P, class T>
SceneKey scene_key(const std::string& name, T P::*field, std::string absent = "", Written written = Written::kWhenUsed) {
  SceneKey k{name, scene_detail::flag_of(name), nullptr, std::move(absent), nullptr, written};
  if constexpr (std::is_same_v<T, bool>) {
    k.get = [field](const SimConfig& c) { return SceneValue(std::int64_t{scene_detail::part<P>(c).*field}); };
    k.set = [field](SimConfig& c, const std::string& s) { scene_detail::part<P>(c).*field = s == "1"; };
  } else if constexpr (std::is_same_v<T, double>) {
    k.get = [field](const SimConfig& c) { return SceneValue(scene_detail::part<P>(c).*field); };
    k.set = [field](SimConfig& c, const std::string& s) { scene_detail::part<P>(c).*field = std::strtod(s.c_str(), nullptr); };
  } else if constexpr (std::is_integral_v<T>) {
    using Whole = std::conditional_t<std::is_signed_v<T>, std::int64_t, std::uint64_t>;
    k.get = [field](const SimConfig& c) { return SceneValue(static_cast<Whole>(scene_detail::part<P>(c).*field)); };
    k.set = [field](SimConfig& c, const std::string& s) {
      scene_detail::part<P>(c).*field = static_cast<T>(std::strtoull(s.c_str(), nullptr, 10));
    };
  } else if constexpr (std::is_same_v<T, std::vector<double>>) {
    k.get = [field](const SimConfig& c) { return SceneValue(scene_detail::part<P>(c).*field); };
    k.set = [field](SimConfig& c, const std::string& s) { scene_detail::part<P>(c).*field = scene_detail::numbers(s); };
  } else {
    static_assert(std::is_same_v<T, std::string>, "a scene key holds a number, a switch, a whole number, a text or a list");
    k.get = [field](const SimConfig& c) { return SceneValue(scene_detail::part<P>(c).*field); };
    k.set = [field](SimConfig& c, const std::string& s) { scene_detail::part<P>(c).*field = s; };
  }
  return k;
}

// ... an optional number: `fallback` when it is not set (rough particles' inertia: the default of the
// scene's dimension).
template <class P>
SceneKey scene_key(const std::string& name, std::optional<double> P::*field, double (*fallback)(const SimConfig&),
                   std::string absent = "") {
  return {name, scene_detail::flag_of(name),
          [field](SimConfig& c, const std::string& s) { scene_detail::part<P>(c).*field = std::strtod(s.c_str(), nullptr); },
          std::move(absent),
          [field, fallback](const SimConfig& c) {
            const std::optional<double>& x = scene_detail::part<P>(c).*field;
            return SceneValue(x ? *x : fallback(c));
          }};
}

// Effects a scene part cannot be combined with, as bits of the registry (kBit, effects/effect_set.hpp;
// kEveryOtherEffect: all but itself, also those registered later), and why: the reason of the refusal,
// "aggregation merges at contact".
struct Exclusion {
  unsigned effects;
  std::string why;
};
inline constexpr unsigned kEveryOtherEffect = ~0u;

// What the output's /parameters needs beyond the scene: the particles and the box volume.
struct SceneSize {
  double n = 0, volume = 0;
};

// What an effect adds to a run's memory and disk (resources.cpp): bytes per particle in the engine
// and its start, bytes per particle of each snapshot, values per sample of E(t).
struct SceneFootprint {
  double particle_bytes = 0, frame_bytes = 0, sample_values = 0;
};

// The file a fresh start reads (--init FILE), and its last frame; both null for a start of gg-sim's own.
struct StartFile {
  const gg::H5Input* in = nullptr;
  const gg::Snapshots* frame = nullptr;
};

// Where an effect declares its command-line options; gg-sim's CLI11 application stands behind it
// (cli_scene_options.hpp), so that the scene parts do not compile the CLI library.
class SceneOptions {
 public:
  virtual ~SceneOptions() = default;
  virtual void number(const std::string& flag, double& value, const std::string& help) = 0;
  virtual void number(const std::string& flag, std::optional<double>& value, const std::string& help) = 0;
  virtual void text(const std::string& flag, std::string& value, const std::string& help) = 0;
  virtual void flag(const std::string& flag, bool& value, const std::string& help) = 0;
  // A comma-separated list kept as its text: a scene file's "radii = 0.5,0.7" arrives as two items,
  // the command line's as one; both leave "0.5,0.7".
  virtual void list(const std::string& flag, std::string& value, const std::string& help) = 0;
};

// The box of a fresh start and where its particles go: the edges of the engine's box, and the box
// the positions are drawn in (its edges, and an offset added to every position drawn). Both are the
// cube of edge --L unless an effect shapes them. A mean flow u_x = shear (y - L_y/2) may be added
// to the velocities drawn (a sheared box's).
struct StartShape {
  std::vector<double> edges;
  std::vector<double> region;
  std::vector<double> offset;
  double shear = 0;
};

class SceneEffect {
 public:
  virtual ~SceneEffect() = default;
  virtual void add_options(SceneOptions& options, SimConfig& c) const = 0;
  // The option that switches it on, as a refusal names it ("--walls"; "--radii or --masses").
  virtual std::string option() const = 0;
  // The effects it cannot be combined with, and why; check_combinations() refuses a scene that uses
  // it with one of them. The first declaration that matches gives the reason.
  virtual std::vector<Exclusion> exclusions() const { return {}; }
  // Checks the effect's options against the rest of the scene (gg::UsageError naming the flag and
  // the fix) and fills in its defaults; called by SimConfig::resolve().
  virtual void check(SimConfig& c) const = 0;
  // When the scene uses it and it decides every collision's outcome (a restitution law, merging),
  // its flag and why --e then has no meaning, "--FLAG (why)"; else empty.
  virtual std::string replaces_restitution(const SimConfig&) const { return {}; }
  // If the effect is a collision cutoff that stops inelastic collapse, its option with a value to
  // try ("--delta 1e-4"), which the error of a run that collapsed advises; else empty.
  virtual std::string collapse_cutoff() const { return {}; }
  // Shapes the box of a fresh start (walls: a longer box, the particles between the walls; shear: a
  // mean flow).
  virtual void shape_start(const SimConfig&, StartShape&) const {}
  // Clears `periodic` (one flag per axis) along the axes whose edges it closes (walls: the last), so
  // that the output's H5MD box says "none" there.
  virtual void close_axes(const SimConfig&, std::vector<bool>&) const {}
  // Its keys, in the order of its part of the fingerprint and of /parameters: their names, options,
  // values and where /parameters has them.
  virtual std::vector<SceneKey> keys() const = 0;
  // Appends " key=value" for each of its keys the scene has (SimConfig::fingerprint(), fingerprint_keys()).
  void fingerprint(const SimConfig& c, std::ostream& s) const;
  // Writes its keys to the output's /parameters (write_keys()).
  void write_parameters(gg::H5Output& out, const SimConfig& c) const;
  // Writes what the output needs of the effect beyond its observables and keys, if the run had it (a
  // mixture's number of species and packing fraction, from the recorder's fixed values; the rate a
  // drive ran at; the density between walls).
  virtual void write_results(gg::H5Output&, const SimConfig&, const Recorder&, const SceneSize&) const {}
  // Whether the scene uses the effect: its engine variants then hold it (engine_variants.hpp).
  virtual bool used(const SimConfig& c) const = 0;
  // Completes its parameters for the engine of a fresh start, whose size is known now (`p`: the
  // engine's copy of c.effects); a resumed run's effects take what they keep from the checkpoint.
  virtual void start_parameters(const SimConfig&, const SceneSize&, EffectParameters&) const {}
  // The sizes of a fresh start's n particles if the effect gives particles sizes (a mixture), else
  // empty: drawn before anything else from the start's generator, or read from the start's file.
  virtual Sizes start_sizes(const SimConfig&, const StartFile&, std::size_t, Random&) const { return {}; }
  // Its arrays at a fresh start of n particles (effect_state.hpp), drawn from the start's
  // generator after the positions and velocities, or taken from the start's file.
  virtual void start_state(const SimConfig&, const StartFile&, std::size_t, Random&, EffectRecords&) const {}
  virtual SceneFootprint footprint(const SimConfig&) const { return {}; }
};

// The scene parts of the registered effects (effects/registry.hpp), in the registry's order: the
// part of scene_effects()[k] is the effect of bit 1 << k.
const std::vector<const SceneEffect*>& scene_effects();

// The keys of a scene that no effect owns (dim, N, L, e, T0, seed, ..., continue): one table as an
// effect's (scene/base_scene.cpp), the first part of every fingerprint and of every /parameters.
std::vector<SceneKey> base_scene_keys();

// Appends " key=value" for each of `keys` the scene has: when their part is `used`, every one whose
// `when` holds (or has none).
void fingerprint_keys(std::ostream& s, const std::vector<SceneKey>& keys, const SimConfig& c, bool used);
// Writes `keys` to the output's /parameters (Written: kWhenUsed, those fingerprint_keys() appends),
// each as its written_as or get gives it; a whole number as an int64 (as every reader of /parameters
// takes it).
void write_keys(gg::H5Output& out, const std::vector<SceneKey>& keys, const SimConfig& c, bool used);

// The effects (bits) a scene uses: those whose scene part says so.
unsigned used_effects(const SimConfig& c);

// The refusal of the first pair among the effects `used` (bits) that one of the two declares it
// cannot be combined with, in the registry's order of the declaring effect: "--A cannot be combined
// with --B (why; drop one of them)"; empty if there is none.
std::string combination_refusal(unsigned used);

// Throws gg::UsageError(combination_refusal()) for the effects the scene uses; called by
// SimConfig::resolve() before the parts check their own options.
void check_combinations(const SimConfig& c);

}  // namespace ggsim
