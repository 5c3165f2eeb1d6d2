#include "scene_effects.hpp"

#include <charconv>
#include <cstdlib>

#include "gg/errors.hpp"
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

void require(bool ok, const std::string& message) {
  if (!ok) throw gg::UsageError(message);
}

std::string str(double x) {
  char text[32];
  return std::string(text, std::to_chars(text, text + sizeof text, x).ptr);
}

double number(const std::string& s) { return std::strtod(s.c_str(), nullptr); }

}  // namespace ggsim
