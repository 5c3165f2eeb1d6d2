#pragma once
// How many times each particle has crossed each periodic boundary (gg-sim --unwrapped): the H5MD
// `image` of docs/DESIGN.md "Files", with which position + image x edges is the unwrapped position
// (H5MD 1.1, "Particles group"). The engine folds positions into the box through its effects
// (EffectSet::wrap_near); this effect counts the folds. A start from a file that has images, and
// a checkpoint, give them as "image".
#include <array>
#include <cstdint>
#include <vector>

#include "gg/box.hpp"
#include "ggsim/effects/effect_parameters.hpp"
#include "ggsim/effects/effect_state.hpp"
#include "ggsim/effects/hooks.hpp"
#include "ggsim/effects/registry_entry.hpp"
#include "ggsim/permutation.hpp"

namespace ggsim {

// Whether a scene keeps the images with its snapshots (src/scene/switch_scenes.cpp; the recorder
// asks): an engine with the effect counts the folds either way.
struct ImageParameters {
  bool on = false;
};

template <int D>
using Image = std::array<std::int32_t, D>;

template <int D>
class ImageCounts {
 public:
  static constexpr Hooks kHooks = hook::folds | hook::permute | hook::save;

  template <class Parameters>
  ImageCounts(const Parameters&, const EffectStart& s) : count_(s.n, Image<D>{}) {
    if (!s.records) return;
    const std::vector<std::int64_t> saved = s.records->take_integer("image", s.n * D);
    for (std::size_t i = 0; i < saved.size(); ++i) count_[i / D][i % D] = static_cast<std::int32_t>(saved[i]);
  }

  // Coordinate k of particle i wrapped into the box from x, less than one edge outside [0, L)
  // (the engine's advance), or anywhere (a start), and the fold counted.
  double wrap_near(std::uint32_t i, int k, double x, const gg::Box<D>& box) {
    count_[i][k] += static_cast<std::int32_t>(x >= box.L[k]) - static_cast<std::int32_t>(x < 0);
    return box.wrap_near(x, k);
  }
  double wrap(std::uint32_t i, int k, double x, const gg::Box<D>& box) {
    std::int64_t folds;
    const double y = box.wrap(x, k, folds);
    count_[i][k] += static_cast<std::int32_t>(folds);
    return y;
  }
  Image<D> image(std::uint32_t i) const { return count_[i]; }
  Image<D>* count(std::uint32_t i) { return &count_[i]; }

  template <class Rank>
  void permute(const Rank& rank) { permute_by_rank(count_, rank); }
  void save(const EffectSink& out) const {
    std::vector<std::int64_t> a;
    a.reserve(count_.size() * D);
    for (const Image<D>& c : count_) a.insert(a.end(), c.begin(), c.end());
    out.integer("image", a);
  }

 private:
  std::vector<Image<D>> count_;
};

// Its entry in the registry (effects/registry.hpp, registry_entry.hpp).
struct ImagesEffect {
  static constexpr std::string_view kName = "images";
  template <int D>
  using Unit = ImageCounts<D>;
  static const SceneEffect& scene();  // src/scene/switch_scenes.cpp (--unwrapped)
};

}  // namespace ggsim
