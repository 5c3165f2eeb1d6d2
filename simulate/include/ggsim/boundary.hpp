#pragma once
// The boundary: what the box does at its edges (docs/DESIGN.md "Boundary and motion law"). The
// engine asks it to fold a position into the box and for the separation of a pair; the cell grid's
// own codes wrap periodically (cell_grid.hpp). The boundary a scene runs is its variant's
// (Effects::Boundary), fixed at compile time:
//   PeriodicBoundary  periodic on every axis: gg::Box itself, so that it costs what the box costs;
//   ShearedBoundary   Lees-Edwards sliding-brick images across the gradient axis (uniform shear
//                     flow, docs/PHYSICS.md "Uniform shear flow").
// Walls are not a boundary but events of the particles that meet them (effects/walls.hpp).
#include <cmath>

#include "gg/box.hpp"
#include "ggsim/effects/effect_parameters.hpp"
#include "ggsim/particles.hpp"

namespace ggsim {

template <int D>
struct PeriodicBoundary : gg::Box<D> {
  static constexpr bool kSheared = false;
  PeriodicBoundary() = default;
  template <class Parameters>
  PeriodicBoundary(const gg::Box<D>& box, const Parameters&) : gg::Box<D>(box) {}
  explicit PeriodicBoundary(const gg::Box<D>& box) : gg::Box<D>(box) {}
};

// What a scene asks of the shear (gg-sim --shear-rate); rate 0: no shear.
struct ShearParameters {
  double rate = 0;  // a: the mean flow is u_x = a (y - L_y/2)
};

// Lees-Edwards boundary conditions (Lees & Edwards, J. Phys. C 5, 1921 (1972)): the images of the
// box one edge above along the gradient axis y (axis 1) slide along the flow axis x (axis 0) at the
// speed a L_y, so at time t they are shifted by offset(t) = a L_y t (mod L_x) and move a L_y faster
// along x; the images below the other way. Every other axis is periodic. A particle leaving through
// the top enters at the bottom as its own image there: x less the offset, v_x less a L_y. Its
// peculiar velocity v - a (y - L_y/2) x^ is the same on both sides, so that is what the
// temperature and the pressure tensor read.
template <int D>
struct ShearedBoundary : gg::Box<D> {
  static_assert(D >= 2, "a shear needs a flow axis and a gradient axis");
  static constexpr bool kSheared = true;
  static constexpr int kFlow = 0, kGradient = 1;

  template <class Parameters>
  ShearedBoundary(const gg::Box<D>& box, const Parameters& par)
      : gg::Box<D>(box), rate(effect_parameters<ShearParameters>(par).rate), jump(rate * box.L[kGradient]) {}

  // How far along x the images above are shifted at time t, in [0, L_x) up to rounding.
  double offset(double t) const { return std::fmod(jump * t, this->L[kFlow]); }

  // Which image of b is nearest a across the gradient axis: +1 the one above, -1 below, 0 b itself
  // (positions at one time, each within a shell diameter of the box).
  int image_of(const Vec<D>& a, const Vec<D>& b) const {
    const double dy = a[kGradient] - b[kGradient], half = 0.5 * this->L[kGradient];
    return (dy > half) - (dy < -half);
  }

  // a minus image n of b at time t: the nearest image along x and the other periodic axes.
  Vec<D> separation(const Vec<D>& a, const Vec<D>& b, int n, double t) const {
    Vec<D> d;
    d[kFlow] = this->min_image(a[kFlow] - b[kFlow] - n * offset(t), kFlow);
    d[kGradient] = a[kGradient] - b[kGradient] - n * this->L[kGradient];
    for (int k = 2; k < D; ++k) d[k] = this->min_image_near(a[k] - b[k], k);
    return d;
  }

  // Moves (r, v) at time t to its image n along the gradient axis (x wrapped into the box).
  void to_image(Vec<D>& r, Vec<D>& v, int n, double t) const {
    if (n == 0) return;
    r[kGradient] += n * this->L[kGradient];
    r[kFlow] = this->wrap(r[kFlow] + n * offset(t), kFlow);
    v[kFlow] += n * jump;
  }

  // Folds (r, v) at time t into the box along the gradient axis, from less than an edge outside.
  void fold(Vec<D>& r, Vec<D>& v, double t) const {
    to_image(r, v, (r[kGradient] < 0) - (r[kGradient] >= this->L[kGradient]), t);
  }

  // The velocity less the mean flow at height y.
  Vec<D> peculiar(Vec<D> v, double y) const {
    v[kFlow] -= rate * (y - 0.5 * this->L[kGradient]);
    return v;
  }

  double rate, jump;  // a, and a L_y: the speed of the images above relative to the box
};

}  // namespace ggsim
