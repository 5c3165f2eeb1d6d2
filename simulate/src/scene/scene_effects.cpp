#include "scene_effects.hpp"

#include <charconv>
#include <cstdlib>
#include <type_traits>
#include <variant>

#include "gg/errors.hpp"
#include "gg/h5file.hpp"
#include "ggsim/effects/registry.hpp"

namespace ggsim {

namespace {
template <class... E>
std::vector<const SceneEffect*> scenes_of(EffectList<E...>) {
  return {&E::scene()...};
}

// Whether a fingerprint holds the key (SceneKey::when), when its scene part is `used`.
bool in_fingerprint(const SceneKey& key, const SimConfig& c, bool used) { return used && (!key.when || key.when(c)); }
}  // namespace

const std::vector<const SceneEffect*>& scene_effects() {
  static const std::vector<const SceneEffect*> list = scenes_of(Registry{});
  return list;
}

void fingerprint_keys(std::ostream& s, const std::vector<SceneKey>& keys, const SimConfig& c, bool used) {
  for (const SceneKey& key : keys) {
    if (!in_fingerprint(key, c, used)) continue;
    s << " " << key.name << "=";
    std::visit(
        [&s](const auto& value) {
          if constexpr (std::is_same_v<std::decay_t<decltype(value)>, std::vector<double>>)
            for (double x : value) s << x << ",";
          else
            s << value;
        },
        key.get(c));
  }
}

void write_keys(gg::H5Output& out, const std::vector<SceneKey>& keys, const SimConfig& c, bool used) {
  for (const SceneKey& key : keys) {
    if (key.written == Written::kNever || (key.written == Written::kWhenUsed && !in_fingerprint(key, c, used))) continue;
    std::visit(
        [&](const auto& value) {
          if constexpr (std::is_same_v<std::decay_t<decltype(value)>, std::uint64_t>)
            out.attr("/parameters", key.name, static_cast<std::int64_t>(value));
          else
            out.attr("/parameters", key.name, value);
        },
        key.written_as ? key.written_as(c) : key.get(c));
  }
}

void SceneEffect::fingerprint(const SimConfig& c, std::ostream& s) const { fingerprint_keys(s, keys(), c, used(c)); }

void SceneEffect::write_parameters(gg::H5Output& out, const SimConfig& c) const {
  write_keys(out, keys(), c, used(c));
}

void require(bool ok, const std::string& message) {
  if (!ok) throw gg::UsageError(message);
}

std::string str(double x) {
  char text[32];
  return std::string(text, std::to_chars(text, text + sizeof text, x).ptr);
}

double number(const std::string& s) { return std::strtod(s.c_str(), nullptr); }

}  // namespace ggsim
