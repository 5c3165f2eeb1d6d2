#pragma once
// The random numbers of an effect that draws during a run (the drive's kicks, a thermal wall's
// velocities): SplitMix64 (Steele, Lea & Flood, OOPSLA 2014), one 64-bit word of state, so that a
// checkpoint keeps all of it in one integer and a resumed run draws what the uninterrupted one would.
#include <cstdint>

namespace ggsim {

struct SplitMix64 {
  std::uint64_t state = 0;

  std::uint64_t bits() {
    std::uint64_t z = state += 0x9e3779b97f4a7c15ull;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }
  double uniform() { return static_cast<double>(bits() >> 11) * 0x1.0p-53; }  // [0, 1)
  // Uniform in [0, m) for m < 2^32 (Lemire's multiply-shift on 32 random bits; the bias, m / 2^32,
  // is below 0.07 for the engine's most particles, 2^28, and 1e-5 for N = 4e4).
  std::uint32_t below(std::size_t m) { return static_cast<std::uint32_t>(((bits() >> 32) * m) >> 32); }
};

}  // namespace ggsim
