// A unit of effects compiled by hook_check_test.cmake, which expects each HOOK_CASE but 0 to stop
// the build with the message naming its hook (effects/hooks.hpp): 0 declares and answers
// restitution rightly, 1 misspells it, 2 takes e by value (the restitution would be lost), 3
// answers it without declaring it (it would never be asked); 4 mistypes a size.
#include <cstdint>

#include "ggsim/effects/effect_set.hpp"

namespace {

struct Unit {
  static constexpr ggsim::Hooks kHooks = HOOK_CASE == 3 ? 0 : ggsim::hook::restitution;
  template <class Parameters>
  Unit(const Parameters&, const ggsim::EffectStart&) {}
#if HOOK_CASE == 1
  void restitutoin(double& e, double, std::uint32_t, std::uint32_t, double) { e = 1; }
#elif HOOK_CASE == 2
  void restitution(double e, double, std::uint32_t, std::uint32_t, double) { e = 1; }
#else
  void restitution(double& e, double, std::uint32_t, std::uint32_t, double) { e = 1; }
#endif
};

// 4 declares sizes whose mass is a float (the impulses would be weighed in single precision).
struct Sizes {
  static constexpr ggsim::Hooks kHooks = HOOK_CASE == 4 ? ggsim::hook::sizes : 0;
  template <class Parameters>
  Sizes(const Parameters&, const ggsim::EffectStart&) {}
#if HOOK_CASE == 4
  float mass(std::uint32_t) const { return 1; }
  double radius(std::uint32_t) const { return 0.5; }
  double radius_cap() const { return 0.5; }
  void set_size(std::uint32_t, double, double) {}
  void set_radius_cap(double) {}
#endif
};

static_assert(sizeof(ggsim::EffectSet<2, Unit, Sizes>) > 0);

}  // namespace

int main() {}
