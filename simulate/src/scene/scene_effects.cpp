#include "scene_effects.hpp"

#include <charconv>
#include <cstdlib>
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
}  // namespace

const std::vector<const SceneEffect*>& scene_effects() {
  static const std::vector<const SceneEffect*> list = scenes_of(Registry{});
  return list;
}

void SceneEffect::fingerprint(const SimConfig& c, std::ostream& s) const {
  if (!used(c)) return;
  for (const SceneKey& key : keys()) {
    s << " " << key.name << "=";
    std::visit([&s](const auto& value) { s << value; }, key.get(c));
  }
}

void SceneEffect::write_parameters(gg::H5Output& out, const SimConfig& c) const {
  const bool on = used(c);
  for (const SceneKey& key : keys())
    if (key.written == Written::kAlways || (key.written == Written::kWhenUsed && on))
      std::visit([&](const auto& value) { out.attr("/parameters", key.name, value); }, key.get(c));
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
