// A unit of effects compiled by hook_check_test.cmake, which expects each HOOK_CASE but 0 to stop
// the build with the message naming its hook (effects/hooks.hpp): 0 declares and answers
// restitution rightly, 1 misspells it, 2 takes e by value (the restitution would be lost), 3
// answers it without declaring it (it would never be asked).
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

static_assert(sizeof(ggsim::EffectSet<2, Unit>) > 0);

}  // namespace

int main() {}
