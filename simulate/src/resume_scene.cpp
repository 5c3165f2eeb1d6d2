#include "ggsim/resume_scene.hpp"

#include <algorithm>
#include <charconv>
#include <cstdlib>
#include <limits>
#include <map>
#include <sstream>

#include "gg/errors.hpp"
#include "scene/scene_effects.hpp"

namespace ggsim {
namespace {

std::uint64_t count(const std::string& s) { return std::strtoull(s.c_str(), nullptr, 10); }

// Every key a fingerprint holds, with its option and how its text goes back into a SimConfig: the
// scene's own keys and each effect's (scene_effect.hpp).
std::map<std::string, SceneKey> all_keys() {
  std::map<std::string, SceneKey> k;
  for (SceneKey& key : base_scene_keys()) k.emplace(key.name, std::move(key));
  for (const SceneEffect* effect : scene_effects())
    for (SceneKey& key : effect->keys()) k.emplace(key.name, std::move(key));
  return k;
}
const std::map<std::string, SceneKey>& keys() {
  static const std::map<std::string, SceneKey> k = all_keys();
  return k;
}

// A key's value, or the value a fingerprint leaves out (one that omits a key at its default still
// compares equal).
std::string value_or_default(const SceneValues& scene, const std::string& key) {
  for (const auto& [k, v] : scene)
    if (k == key) return v;
  const auto it = keys().find(key);
  return it == keys().end() ? "" : it->second.absent;
}

// A value as a person writes it: numbers in their shortest exact form (0.8, not 0.80000000000000004).
std::string readable(const std::string& value) {
  std::string out;
  std::stringstream in(value);
  std::string item;
  while (std::getline(in, item, ',')) {
    if (item.empty()) continue;
    char* end = nullptr;
    const double x = std::strtod(item.c_str(), &end);
    if (end && *end == '\0') {
      char text[32];
      const auto r = std::to_chars(text, text + sizeof text, x);
      item.assign(text, r.ptr);
    }
    out += (out.empty() ? "" : ",") + item;
  }
  return out.empty() ? "(none)" : out;
}

}  // namespace

SceneValues parse_scene(const std::string& fingerprint, const std::string& source) {
  // Pairs are separated by spaces; a space inside a value (an --init path) continues that value.
  SceneValues scene;
  std::stringstream in(fingerprint);
  std::string token;
  while (in >> token) {
    const auto eq = token.find('=');
    if (eq != std::string::npos && keys().count(token.substr(0, eq))) {
      scene.emplace_back(token.substr(0, eq), token.substr(eq + 1));
    } else if (!scene.empty()) {
      scene.back().second += " " + token;
    } else {
      throw gg::UsageError(source + " holds a scene this gg-sim does not know ('" + token +
                           "'); resume it with the gg-sim that wrote it");
    }
  }
  if (scene.empty() || scene.front().first != "dim")
    throw gg::UsageError(source + " holds no scene; resume it with the gg-sim that wrote it");
  return scene;
}

std::string scene_value(const SceneValues& scene, const std::string& key) { return value_or_default(scene, key); }

void adopt_scene(SimConfig& cfg, const SceneValues& stored, const std::set<std::string>& given, bool* n_given,
                 bool* l_given) {
  for (const auto& [key, value] : stored) {
    const SceneKey& k = keys().at(key);
    if (k.set && !given.count(k.flag)) k.set(cfg, value);
  }
  if (!cfg.starts_from_file() && !given.count("N") && !given.count("L") && !given.count("rho")) {
    cfg.N = count(value_or_default(stored, "N"));
    cfg.L = number(value_or_default(stored, "L"));
    *n_given = *l_given = true;
  }
}

void require_same_scene(const std::string& checkpoint, const SceneValues& stored, const SimConfig& cfg) {
  const SceneValues now = parse_scene(cfg.fingerprint(), "this scene");
  std::vector<std::string> names;  // the keys of both, in order
  for (const SceneValues* scene : {&stored, &now})
    for (const auto& [k, v] : *scene)
      if (std::find(names.begin(), names.end(), k) == names.end()) names.push_back(k);
  for (const std::string& key : names) {
    const std::string there = value_or_default(stored, key), here = value_or_default(now, key);
    if (there == here) continue;
    const std::string flag = std::string("--") + keys().at(key).flag;
    if (key == "t_max" && number(here) > number(there)) continue;  // the run goes on further
    if (key == "max_collisions" && count(here) > count(there)) continue;
    if (key == "max_collisions" && count(there) == std::numeric_limits<std::uint64_t>::max())
      throw gg::UsageError("--resume " + checkpoint + ": " + flag + " " + readable(here) + " sets a limit the run was "
                           "started without; a resumed run may go further, not less far: drop " + flag);
    if (key == "t_max" || key == "max_collisions")
      throw gg::UsageError("--resume " + checkpoint + ": " + flag + " " + readable(here) + " is less than the " +
                           readable(there) + " the run was started with; a resumed run may go further, not less far");
    throw gg::UsageError("--resume " + checkpoint + " was written by another scene: " + key + " = " + readable(there) +
                         " there, " + readable(here) + " here (" + flag + "); drop " + flag +
                         " to continue the checkpoint's scene, or remove the checkpoint to start over");
  }
}

}  // namespace ggsim
