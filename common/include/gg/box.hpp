#pragma once
// Periodic box of edge lengths L[0..D-1] (docs/DESIGN.md: one periodic box type, inline wrap).
#include <array>
#include <cmath>
#include <cstdint>

namespace gg {

template <int D>
struct Box {
  std::array<double, D> L{};
  std::array<double, D> inv_L{};

  Box() = default;
  explicit Box(const std::array<double, D>& edges) : L(edges) {
    for (int k = 0; k < D; ++k) inv_L[k] = 1.0 / L[k];
  }
  double volume() const {
    double v = 1;
    for (int k = 0; k < D; ++k) v *= L[k];
    return v;
  }
  // Minimum-image separation component.
  double min_image(double dx, int k) const { return dx - L[k] * std::nearbyint(dx * inv_L[k]); }
  // Minimum image of a separation already within (-L, L), as between two wrapped positions
  // (one fold, no rounding call: the engine's hot path).
  double min_image_near(double dx, int k) const {
    if (dx > 0.5 * L[k]) return dx - L[k];
    if (dx < -0.5 * L[k]) return dx + L[k];
    return dx;
  }
  // Wrap a coordinate less than one box length outside [0, L) (one fold, the engine's hot path;
  // x + L may round to L, which cell lookups treat as the last cell).
  double wrap_near(double x, int k) const {
    if (x < 0) return x + L[k];
    if (x >= L[k]) return x - L[k];
    return x;
  }
  // Wrap a coordinate into [0, L).
  double wrap(double x, int k) const {
    x -= L[k] * std::floor(x * inv_L[k]);
    return x >= L[k] ? x - L[k] : x;  // floor of a value just below 0 can give exactly L
  }
  // The same wrap, and the periodic image a finite x lies in: x = wrap(x, k) + image L up to
  // rounding (the H5MD `image` of docs/DESIGN.md "Files").
  double wrap(double x, int k, std::int64_t& image) const {
    const double n = std::floor(x * inv_L[k]);
    const double y = x - L[k] * n;
    image = static_cast<std::int64_t>(n) + (y >= L[k]);
    return y >= L[k] ? y - L[k] : y;
  }
};

}  // namespace gg
