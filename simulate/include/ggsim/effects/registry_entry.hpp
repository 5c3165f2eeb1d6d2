#pragma once
// What an effect's entry in the registry (registry.hpp) is: a small struct, beside the effect's
// class in its header, that names the pieces of the effect (docs/DESIGN.md "Where an effect lives"):
//
//   static constexpr std::string_view kName   its word in an engine variant's name ("tc" in
//                                             "tc+virial"; simulate/CMakeLists.txt)
//   template <int D> using Unit               the class the engine holds in its EffectSet
//                                             (effect_set.hpp), which reads its parameters
//   static const SceneEffect& scene()         its part of a scene (scene_effect.hpp), defined in
//                                             its file of src/scene/: its options, its keys (one
//                                             table) and the effects it cannot be combined with
//                                             (exclusions(), checked in one place for every scene)
//
// and, only for an effect that changes the engine itself rather than adding to it:
//
//   using Motion                              how particles move between events (motion/)
//   template <int D> using Boundary           what the box is (boundary/boundary.hpp)
//   template <int D, class Engine> using Contact
//                                             what a touching pair does (contact/)
//
// An effect with one of these three is exact: a scene runs a variant that has it exactly when it
// asks for it (engine_variants.hpp), since it changes trajectories even when its values are unused.
#include <string_view>

namespace ggsim {

class SceneEffect;

}  // namespace ggsim
