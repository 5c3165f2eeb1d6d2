#pragma once
// Lees-Edwards boundary conditions (boundary.hpp): the sliding-brick images of uniform shear flow
// (docs/PHYSICS.md "Uniform shear flow"), and the search of a particle's collisions through the
// sliding edge, which the periodic cells cannot do (as DynamO keeps its sheared cell search,
// globals/cellsShearing, beside its LEBC boundary).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <type_traits>
#include <vector>

#include "gg/box.hpp"
#include "gg/errors.hpp"
#include "ggsim/boundary/boundary.hpp"
#include "ggsim/cell_grid.hpp"
#include "ggsim/motion/position.hpp"
#include "ggsim/particles.hpp"
#include "ggsim/prediction.hpp"

namespace ggsim {

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
struct ShearedBoundary : gg::Box<D>, WithoutEdgeEvents<D> {
  static_assert(D >= 2, "a shear needs a flow axis and a gradient axis");
  static constexpr int kFlow = 0, kGradient = 1;

  // `par`: the engine's parameters, whose effects' store (effects/effect_parameters.hpp) holds the
  // shear's; the rate is all of its state (`start`: nothing for it).
  template <class Parameters, class Start>
  ShearedBoundary(const gg::Box<D>& box, const Parameters& par, const Start&)
      : gg::Box<D>(box),
        rate(par.rule.effects.template get<ShearParameters>().rate),
        jump(rate * box.L[kGradient]) {}

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

  // --- what the engine asks (boundary.hpp) ---

  // A particle is folded across the gradient axis only when it gets a new shell: its shell centre
  // is in the frame of its record until then.
  static constexpr bool folds_when_advancing(int k) { return k != kGradient; }
  // b's image that touches a (positions at time t, each within a shell diameter of the box).
  template <class Image>
  void to_touching_image(const Vec<D>& a, Vec<D>& rb, Vec<D>& vb, double t, Image image) const {
    to_image(rb, vb, image_of(a, rb), t, image);
  }
  Vec<D> separation(const Vec<D>& a, const Vec<D>& b) const { return nearest_separation<D>(*this, a, b); }
  Vec<D> peculiar(const Vec<D>& v, const Vec<D>& r) const { return peculiar(v, r[kGradient]); }
  // A shell whose centre would lie across the sliding edge is centred on its particle instead.
  bool may_centre_shell_at(const Vec<D>& x) const { return x[kGradient] >= 0 && x[kGradient] < this->L[kGradient]; }

  // A search within `reach` (centre to centre): the rows at the sliding edge must not be the same,
  // and a particle there searches again before its partners' images across the edge slide by more
  // than kSlideCells cell widths along x (stay()).
  template <class Grid>
  void prepare_search(const Grid& grid, double reach) {
    if (grid.cells_along(kGradient) < 3 || grid.cells_along(kFlow) < 3)
      throw gg::UsageError("a sheared box needs edges of at least 3 cells (" + std::to_string(3 * grid.min_cell_width()) +
                           " diameters) along x and y; raise --N or --L");
    const double slide = kSlideCells * grid.min_cell_width(), speed = std::abs(jump);
    edge_stay_ = speed > 0 ? slide / speed : kNever;
    across_reach_ = reach + slide;
    reach2_ = reach * reach;
  }
  // A particle whose shell is in a row at the sliding edge searches again at least every
  // kSlideCells cell widths / (a L_y): until then the images of its partners across the edge slide
  // by at most that much along x (search_near_edges()).
  template <class Grid>
  double stay(const Grid& grid, const typename Grid::Code& centre, double t) const {
    if (grid.in_sheared_row(centre)) return std::min(t, edge_stay_);
    return t;
  }

  // The search of particle i (at now) near the edges: through the sliding edge its neighbours are
  // the particles of the row across it within reach along the other axes whose images along x are
  // within reach now or come within it before i searches again (their images slide by at most
  // kSlideCells cells meanwhile, stay()); each such pair is tried at its three nearest images along
  // x. Keeps the earliest in i's pending event (contact2(i, j): the pair's squared contact distance).
  template <class Particles, class Grid, class Motion, class Contact2>
  bool search_near_edges(std::uint32_t i, Particles& p, Grid& grid, const Motion& motion, double now,
                         const Contact2& contact2) {
    using Code = typename Grid::Code;
    Particle<D>& q = p[i];
    PendingEvent& ev = q.next;
    const Code centre = grid.code(i);
    // Where the images of the row across the edge that lie nearest i are, along x: the row below's
    // images above are shifted by the offset, the row above's images below by minus it.
    Vec<D> c = grid.decode(centre);
    const int image = c[kGradient] > 0.5 * this->L[kGradient] ? 1 : -1;
    c[kFlow] = this->wrap(c[kFlow] - image * offset(now), kFlow);
    const Code across_centre = grid.encode(c);
    near_.clear();
    grid.hide_for_search(i);
    grid.for_each_near_sheared(
        centre, c[kFlow] - across_reach_, 2 * across_reach_,
        [&](typename Grid::Slot s, const Code& cj) {
          if (grid.distance2(centre, cj) <= reach2_) near_.push_back(s);
        },
        [&](typename Grid::Slot s, const Code& cj) {
          if (grid.distance2_across(centre, cj) <= reach2_ && grid.distance_along_0(across_centre, cj) <= across_reach_)
            near_.push_back(s);
        });
    grid.unhide(i);
    for (const typename Grid::Slot s : near_) {
      const std::uint32_t j = Grid::particle(s);
      const Particle<D>& o = p[j];
      const Vec<D> rj = position_after<D>(motion, o, now - o.t), vj = velocity_after<D>(motion, o, now - o.t);
      Vec<D> v;
      for (int k = 0; k < D; ++k) v[k] = q.v[k] - vj[k];
      const int n = image_of(q.r, rj);
      Vec<D> r = separation(q.r, rj, n, now);
      v[kFlow] -= n * jump;
      double t = time_to_contact<D>(r, v, contact2(i, j));
      if (n != 0)
        for (const int m : {-1, 1}) {
          Vec<D> rm = r;
          rm[kFlow] += m * this->L[kFlow];
          t = std::min(t, time_to_contact<D>(rm, v, contact2(i, j)));
        }
      if (now + t < ev.collision_time) ev.collision_time = now + t, ev.partner = j;
    }
    if (ev.partner != PendingEvent::kNone) ev.partner_collisions = p[ev.partner].collisions;
    return true;
  }

  double rate, jump;  // a, and a L_y: the speed of the images above relative to the box

 private:
  static constexpr double kSlideCells = 2;
  // The longest a particle at the sliding edge goes between searches, how far along x a search
  // there looks across the edge, the squared reach, and the particles it finds within reach.
  double edge_stay_ = kNever, across_reach_ = 0, reach2_ = 0;
  std::vector<std::uint32_t> near_;
};

}  // namespace ggsim
