#include "scene_effects.hpp"

#include <charconv>
#include <cstdlib>

#include "gg/errors.hpp"

namespace ggsim {

const std::vector<const SceneEffect*>& scene_effects() {
  static const std::vector<const SceneEffect*> list{&cutoff_scene(),  &tc_scene(),    &pressure_scene(),
                                                     &unwrapped_scene(), &drive_scene(), &rough_scene(),
                                                     &mixture_scene(),   &viscoelastic_scene(), &walls_scene()};
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
