#pragma once
// The effects an engine may compile in: the one list of them (docs/DESIGN.md "Where an effect
// lives"). An effect is registered by its header here and its entry in the list (registry_entry.hpp);
// the engine variants, the scene's options, checks, keys and outputs, the checkpoint and the
// choice of variant all follow from the list. Its order is the order in which a collision asks the
// effects (a restitution law first, so that a cutoff or the TC model may still make a collision
// elastic) and in which a scene's parts are asked (the options of gg-sim --help).
#include "ggsim/contact/aggregate.hpp"
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

}  // namespace ggsim
