#pragma once
// The boundary: what the box does at its edges (docs/DESIGN.md "Boundary and motion law"). The
// engine asks it to fold a position into the box (wrap from anywhere, wrap_near from less than an
// edge outside) and for the separation of a pair (min_image, min_image_near); the cell grid's own
// codes wrap the same way (cell_grid.hpp). The boundary a scene runs is its variant's
// (Effects::Boundary), fixed at compile time. Periodic on every axis is gg::Box itself; a sheared
// boundary (Lees-Edwards) would shift the images of the sheared axis in time and change a
// velocity that crosses it, and a wall would reflect instead of folding.
#include "gg/box.hpp"

namespace ggsim {

template <int D>
using PeriodicBoundary = gg::Box<D>;

}  // namespace ggsim
