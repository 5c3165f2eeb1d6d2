#pragma once
// The collisional virial for the pressure (gg-sim --pressure): the sum of r_ij . Delta p_i over
// the collisions since the recorder last took it (docs/PHYSICS.md "Pressure"). A checkpoint saves
// the part not yet taken as "virial".
#include <vector>

#include "ggsim/effects/effect_state.hpp"

namespace ggsim {

class PressureVirial {
 public:
  template <class Parameters>
  PressureVirial(const Parameters&, const EffectStart& s) {
    if (s.records)
      if (const auto saved = s.records->take_real("virial", 1); !saved.empty()) sum_ = saved[0];
  }

  void add_virial(double w) { sum_ += w; }
  // The sum since the last call.
  double take() {
    const double s = sum_;
    sum_ = 0;
    return s;
  }
  void save(const EffectSink& out) const { out.real("virial", {sum_}); }

 private:
  double sum_ = 0;
};

}  // namespace ggsim
