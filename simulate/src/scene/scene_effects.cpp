#include "scene_effects.hpp"

#include <charconv>
#include <cstdlib>

#include "gg/errors.hpp"

namespace ggsim {

// Each defined in its scene part's file.
const SceneEffect& aggregation_scene();
const SceneEffect& cutoff_scene();
const SceneEffect& tc_scene();
const SceneEffect& pressure_scene();
const SceneEffect& unwrapped_scene();
const SceneEffect& drive_scene();
const SceneEffect& rough_scene();
const SceneEffect& mixture_scene();
const SceneEffect& viscoelastic_scene();
const SceneEffect& walls_scene();
const SceneEffect& shear_scene();

// The one list of the scene parts.
const std::vector<const SceneEffect*>& scene_effects() {
  static const std::vector<const SceneEffect*> list{&aggregation_scene(), &cutoff_scene(),  &tc_scene(),
                                                     &pressure_scene(),    &unwrapped_scene(), &drive_scene(),
                                                     &rough_scene(),       &mixture_scene(),   &viscoelastic_scene(),
                                                     &walls_scene(),       &shear_scene()};
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
