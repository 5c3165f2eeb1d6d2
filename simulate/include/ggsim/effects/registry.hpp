#pragma once
// The effects an engine may compile in: the one list of them (docs/DESIGN.md "Where an effect
// lives"). An effect is registered by its header here and its entry in the list (registry_entry.hpp);
// the engine variants, the scene's options, checks, keys and outputs, which effects a scene may
// combine (each entry's scene part declares those it cannot be combined with), the checkpoint and
// the choice of variant all follow from the list. Its order is the order in which a collision asks the
// effects (a restitution law first, so that a cutoff or the TC model may still make a collision
// elastic) and in which a scene's parts are asked (the options of gg-sim --help).
#include <concepts>
#include <string_view>

#include "ggsim/contact/aggregate.hpp"
#include "ggsim/effects/hooks.hpp"
#include "ggsim/effects/image_counts.hpp"
#include "ggsim/effects/impact_speed_restitution.hpp"
#include "ggsim/effects/particle_sizes.hpp"
#include "ggsim/effects/pressure_virial.hpp"
#include "ggsim/effects/rough_particles.hpp"
#include "ggsim/effects/shear_stress.hpp"
#include "ggsim/effects/tc_model.hpp"
#include "ggsim/effects/velocity_cutoff.hpp"
#include "ggsim/effects/viscoelastic_restitution.hpp"
#include "ggsim/effects/walls.hpp"
#include "ggsim/effects/white_noise_drive.hpp"

namespace ggsim {

template <class... Entries>
struct EffectList {};

using Registry = EffectList<ViscoelasticEffect,
                            ImpactSpeedEffect,
                            CutoffEffect,
                            TcEffect,
                            RoughEffect,
                            VirialEffect,
                            ImagesEffect,
                            DrivenEffect,
                            WallsEffect,
                            ShearEffect,
                            MixtureEffect,
                            AggregateEffect>;

// What an entry is (registry_entry.hpp): a word, a unit that declares its hooks, a scene part.
template <class E>
concept RegistryEntry = requires {
  { E::kName } -> std::convertible_to<std::string_view>;
  { E::scene() } -> std::same_as<const SceneEffect&>;
  requires EffectUnit<typename E::template Unit<2>>;
};
template <class E>
consteval bool entry_checked() {
  static_assert(RegistryEntry<E>, "a registry entry needs kName, a Unit<D> with kHooks and scene() (registry_entry.hpp)");
  return true;
}
template <class... E>
consteval bool entries_checked(EffectList<E...>) {
  return (entry_checked<E>() && ...);
}
static_assert(entries_checked(Registry{}));

}  // namespace ggsim
