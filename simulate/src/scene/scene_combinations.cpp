// Which effects a scene may use together: each scene part declares the effects it cannot be
// combined with (SceneEffect::exclusions()), and this one check refuses a scene against all the
// declarations, with the reason its declaration gives (docs/DESIGN.md "Where an effect lives").
#include <bit>

#include "scene_effects.hpp"

namespace ggsim {

unsigned used_effects(const SimConfig& c) {
  const std::vector<const SceneEffect*>& parts = scene_effects();
  unsigned used = 0;
  for (std::size_t k = 0; k < parts.size(); ++k)
    if (parts[k]->used(c)) used |= 1u << k;
  return used;
}

std::string combination_refusal(unsigned used) {
  const std::vector<const SceneEffect*>& parts = scene_effects();
  used &= (1u << parts.size()) - 1;
  for (std::size_t k = 0; k < parts.size(); ++k) {
    const unsigned self = 1u << k;
    if ((used & self) == 0) continue;
    for (const Exclusion& x : parts[k]->exclusions()) {
      const unsigned clash = x.effects & used & ~self;
      if (clash == 0) continue;
      return parts[k]->option() + " cannot be combined with " + parts[std::countr_zero(clash)]->option() + " (" +
             x.why + "; drop one of them)";
    }
  }
  return {};
}

void check_combinations(const SimConfig& c) {
  const std::string refusal = combination_refusal(used_effects(c));
  require(refusal.empty(), refusal);
}

}  // namespace ggsim
