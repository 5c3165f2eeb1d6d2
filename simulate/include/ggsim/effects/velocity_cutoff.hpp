#pragma once
// The velocity cutoff (gg-sim --delta): a collision whose normal relative speed is below delta is
// elastic (McNamara 1993; Ben-Naim et al., paper section II), which keeps a cooling gas from
// collapsing. A collision part only: no state, nothing written.
#include <cmath>
#include <cstdint>

#include "ggsim/effects/effect_state.hpp"

namespace ggsim {

class VelocityCutoff {
 public:
  template <class Parameters>
  VelocityCutoff(const Parameters& par, const EffectStart&) : delta_(par.rule.delta) {}

  // |n.v_ij| < delta: elastic. At the threshold itself the collision is inelastic.
  void restitution(double& e, double vn, std::uint32_t, std::uint32_t, double) const {
    if (std::abs(vn) < delta_) e = 1;
  }

 private:
  double delta_;
};

}  // namespace ggsim
