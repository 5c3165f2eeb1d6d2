#pragma once
// Random numbers reproducible on every platform: std::mt19937_64's output sequence is fixed by
// the standard, but the standard distributions are not, so the conversions are written here.
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>

namespace ggsim {

class Random {
 public:
  explicit Random(std::uint64_t seed) : engine_(seed) {}
  // Uniform in [0, 1) with 53 random bits.
  double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
  // Standard normal by the Box-Muller transform.
  double normal() {
    if (has_spare_) {
      has_spare_ = false;
      return spare_;
    }
    double u = uniform();
    while (u == 0) u = uniform();
    const double rad = std::sqrt(-2 * std::log(u));
    const double ang = 2 * std::numbers::pi * uniform();
    spare_ = rad * std::sin(ang);
    has_spare_ = true;
    return rad * std::cos(ang);
  }

 private:
  std::mt19937_64 engine_;
  double spare_ = 0;
  bool has_spare_ = false;
};

}  // namespace ggsim
