#pragma once
// Exact event times for ballistic motion between events (no time step).
#include <array>
#include <cmath>
#include <limits>

namespace ggsim {

inline constexpr double kNever = std::numeric_limits<double>::infinity();

template <int D>
using Vec = std::array<double, D>;

template <int D>
inline double dot(const Vec<D>& a, const Vec<D>& b) {
  double s = 0;
  for (int k = 0; k < D; ++k) s += a[k] * b[k];
  return s;
}

// Below this v^2 the quadratics' coefficients underflow (speeds near 1e-160 arise at the end of
// an inelastic collapse); velocities are then scaled by the exact power of two kSpeedUp and the
// time scaled back, so predictions stay exact instead of degenerating to 0 or garbage.
inline constexpr double kTinySpeed2 = 0x1p-900;
inline constexpr double kSpeedUp = 0x1p400;

template <int D>
inline Vec<D> sped_up(const Vec<D>& v) {
  Vec<D> u;
  for (int k = 0; k < D; ++k) u[k] = v[k] * kSpeedUp;
  return u;
}

// Time until two disks of contact distance sigma (sigma^2 = sigma2) touch, given their relative
// position r and relative velocity v at the same instant; kNever if they never do.
// Bannerman et al., Comput. Part. Mech. 1, 191 (2014): a pair already overlapping by round-off
// collides now if approaching and never if receding, so round-off can neither lose a collision
// nor create a spurious one.
template <int D>
inline double time_to_contact(const Vec<D>& r, const Vec<D>& v, double sigma2) {
  const double b = dot<D>(r, v);
  if (b >= 0) return kNever;  // moving apart (or sliding): cheap rejection, no square root
  const double c = dot<D>(r, r) - sigma2;
  if (c <= 0) return 0;  // touching or overlapping by round-off, and approaching
  const double a = dot<D>(v, v);
  if (a < kTinySpeed2) return time_to_contact<D>(r, sped_up<D>(v), sigma2) * kSpeedUp;
  const double disc = b * b - a * c;
  if (disc < 0) return kNever;  // passes by
  // Smaller root of a t^2 + 2 b t + c = 0 written without cancellation:
  // t = (-b - sqrt(disc)) / a = c / (-b + sqrt(disc)).
  return c / (-b + std::sqrt(disc));
}

// The same, from the pair's three invariants b = r.v, c = r.r - sigma^2 and a = v.v, which the
// engine accumulates in one pass over the coordinates (no temporaries in memory). For
// a < kTinySpeed2 the caller must use the vector form, which can rescale v.
inline double time_to_contact(double b, double c, double a) {
  if (b >= 0) return kNever;
  if (c <= 0) return 0;
  const double disc = b * b - a * c;
  if (disc < 0) return kNever;
  return c / (-b + std::sqrt(disc));
}

// Time until a particle at offset r from its shell centre, moving with v, reaches distance
// `radius` from the centre (r inside the shell, so the larger root is the exit).
template <int D>
inline double time_to_leave(const Vec<D>& r, const Vec<D>& v, double radius) {
  const double a = dot<D>(v, v);
  if (a == 0) {
    bool at_rest = true;
    for (int k = 0; k < D; ++k) at_rest = at_rest && v[k] == 0;
    if (at_rest) return kNever;
  }
  if (a < kTinySpeed2) return time_to_leave<D>(r, sped_up<D>(v), radius) * kSpeedUp;
  const double b = dot<D>(r, v);
  const double c = dot<D>(r, r) - radius * radius;  // <= 0 inside
  if (c >= 0) return 0;
  const double disc = b * b - a * c;  // >= b^2 since c < 0
  // Larger root (-b + sqrt(disc)) / a, written without cancellation for b > 0.
  return b <= 0 ? (-b + std::sqrt(disc)) / a : -c / (b + std::sqrt(disc));
}

}  // namespace ggsim
