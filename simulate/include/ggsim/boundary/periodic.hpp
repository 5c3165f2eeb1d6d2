#pragma once
// The periodic box (boundary.hpp): every axis periodic, every question of the engine answered by
// the box itself or by nothing, so that the calls compile away.
#include <cstddef>

#include "gg/box.hpp"
#include "ggsim/boundary/boundary.hpp"
#include "ggsim/particles.hpp"

namespace ggsim {

template <int D>
struct PeriodicBoundary : gg::Box<D>, WithoutEdgeEvents<D> {
  PeriodicBoundary() = default;
  template <class Parameters, class Start>
  PeriodicBoundary(const gg::Box<D>& box, const Parameters&, const Start&) : gg::Box<D>(box) {}
  explicit PeriodicBoundary(const gg::Box<D>& box) : gg::Box<D>(box) {}

  static constexpr bool folds_when_advancing(int) { return true; }
  template <class Image = std::nullptr_t>
  void fold(Vec<D>&, Vec<D>&, double, Image = nullptr) const {}
  template <class Image>
  void to_touching_image(const Vec<D>&, Vec<D>&, Vec<D>&, double, Image) const {}
  Vec<D> separation(const Vec<D>& a, const Vec<D>& b) const { return nearest_separation<D>(*this, a, b); }
  Vec<D> peculiar(const Vec<D>& v, const Vec<D>&) const { return v; }
  static constexpr bool may_centre_shell_at(const Vec<D>&) { return true; }
  template <class Grid>
  void prepare_search(const Grid&, double) {}
  template <class Grid>
  double stay(const Grid&, const typename Grid::Code&, double t) const {
    return t;
  }
  template <class... Engine>
  static constexpr bool search_near_edges(Engine&&...) {
    return false;
  }
};

}  // namespace ggsim
