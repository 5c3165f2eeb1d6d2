#pragma once
// The boundary: what the box does at its edges (docs/DESIGN.md "Boundary and motion law"). The
// engine asks it to fold a position into the box and for the separation of a pair; the cell grid's
// own codes wrap periodically (cell_grid.hpp). The boundary a scene runs is its variant's
// (EngineVariant::Boundary, effects/effect_set.hpp), fixed at compile time:
//   PeriodicBoundary  periodic on every axis: gg::Box itself, so that it costs what the box costs;
//   ShearedBoundary   Lees-Edwards sliding-brick images across the gradient axis (uniform shear
//                     flow, docs/PHYSICS.md "Uniform shear flow").
// Walls are not a boundary but events of the particles that meet them (effects/walls.hpp).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <type_traits>

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
  // The whole box lengths the images above have slid by at time t: a L_y t = offset(t) + that L_x.
  std::int64_t whole_slides(double t) const {
    return std::llround((jump * t - offset(t)) * this->inv_L[kFlow]);
  }

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

  // Moves (r, v) at time t to its image n along the gradient axis (x wrapped into the box). With
  // `image` (a particle's count of the box edges it has crossed, effects/image_counts.hpp) the
  // count follows, so that unwrapped() stays where it was.
  template <class Image = std::nullptr_t>
  void to_image(Vec<D>& r, Vec<D>& v, int n, double t, Image image = nullptr) const {
    if (n == 0) return;
    r[kGradient] += n * this->L[kGradient];
    std::int64_t folds;
    r[kFlow] = this->wrap(r[kFlow] + n * offset(t), kFlow, folds);
    v[kFlow] += n * jump;
    if constexpr (!std::is_same_v<Image, std::nullptr_t>) {
      (*image)[kGradient] -= n;
      (*image)[kFlow] += static_cast<std::int32_t>(n * whole_slides(t) + folds);
    }
  }

  // Folds (r, v) at time t into the box along the gradient axis, from less than an edge outside.
  template <class Image = std::nullptr_t>
  void fold(Vec<D>& r, Vec<D>& v, double t, Image image = nullptr) const {
    to_image(r, v, (r[kGradient] < 0) - (r[kGradient] >= this->L[kGradient]), t, image);
  }

  // Where a particle at r in the box with image count n is at time t in the unbounded sheared
  // space: image n of the sliding brick, r + n_x L_x x^ + n_y (L_y y^ + a L_y t x^) + n_z L_z z^.
  // Its velocity there is v + n_y a L_y x^, so a particle that crosses no other moves on a straight
  // line through the images (docs/DESIGN.md "Files": the `image` of a sheared run).
  template <class Image>
  Vec<D> unwrapped(Vec<D> r, const Image& n, double t) const {
    for (int k = 0; k < D; ++k) r[k] += n[k] * this->L[k];
    r[kFlow] += n[kGradient] * jump * t;
    return r;
  }

  // The velocity less the mean flow at height y.
  Vec<D> peculiar(Vec<D> v, double y) const {
    v[kFlow] -= rate * (y - 0.5 * this->L[kGradient]);
    return v;
  }

  double rate, jump;  // a, and a L_y: the speed of the images above relative to the box
};

}  // namespace ggsim
