#pragma once
// How many times each particle has crossed each periodic boundary (gg-sim --unwrapped): the H5MD
// `image` of docs/DESIGN.md "Files", with which position + image x edges is the unwrapped position
// (H5MD 1.1, "Particles group"). The count is kept only by an engine compiled with it (Effects'
// kImages): without it this holds nothing and every call compiles to nothing, so a run that does
// not ask for images runs the same instructions as before.
#include <array>
#include <cstdint>
#include <vector>

#include "gg/box.hpp"

namespace ggsim {

template <int D>
using Image = std::array<std::int32_t, D>;

template <int D, bool On>
class ImageCounts {
 public:
  // Every particle in the image `start[i]` (empty: image 0).
  void reset(std::size_t n, const std::vector<Image<D>>& start = {}) {
    if constexpr (On) count_ = start.empty() ? std::vector<Image<D>>(n, Image<D>{}) : start;
    else (void)n, (void)start;
  }
  // Coordinate k of particle i wrapped into the box from x, less than one edge outside [0, L)
  // (the engine's advance), or anywhere (a start), and the fold counted.
  double wrap_near(std::uint32_t i, int k, double x, const gg::Box<D>& box) {
    if constexpr (On) count_[i][k] += static_cast<std::int32_t>(x >= box.L[k]) - static_cast<std::int32_t>(x < 0);
    else (void)i;
    return box.wrap_near(x, k);
  }
  double wrap(std::uint32_t i, int k, double x, const gg::Box<D>& box) {
    if constexpr (On) {
      std::int64_t folds;
      const double y = box.wrap(x, k, folds);
      count_[i][k] += static_cast<std::int32_t>(folds);
      return y;
    } else {
      return (void)i, box.wrap(x, k);
    }
  }
  // Particle i's image, 0 without counts.
  Image<D> at(std::uint32_t i) const {
    if constexpr (On) return count_[i];
    else return (void)i, Image<D>{};
  }
  // The per-particle array, in the engine's numbering (checkpoints; renumbering).
  std::vector<Image<D>>& all() { return count_; }
  const std::vector<Image<D>>& all() const { return count_; }

 private:
  std::vector<Image<D>> count_;
};

}  // namespace ggsim
