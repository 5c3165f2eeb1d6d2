#pragma once
// What a run starts from: the state run.cpp builds (drawn, or read from --init FILE) and hands to
// the engine variant the scene runs (simulate.hpp).
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "gg/box.hpp"
#include "gg/h5file.hpp"
#include "ggsim/config.hpp"
#include "ggsim/effects/effect_state.hpp"
#include "ggsim/mixture.hpp"
#include "ggsim/prediction.hpp"

namespace ggsim {

template <int D>
struct State {
  gg::Box<D> box;
  std::vector<Vec<D>> r, v;
  // What the effects start from: with --unwrapped the periodic image of each particle ("image",
  // a start from a file that holds one: its last frame's; absent: image 0); for rough particles
  // the angular velocities ("spin"; absent: none rotates).
  EffectRecords effects;
  Sizes sizes;               // a mixture's (--radii, --masses), by particle number; empty: none
  double t0 = 0;             // the clock at the start (--continue: the file's last frame)
  std::uint64_t step0 = 0;   // and the collisions so far
};

// The file a run starts from (--init FILE.h5), open for the whole run: its provenance goes into
// the output's /parameters/provenance/inputs/0, as every tool's inputs do (docs/DESIGN.md).
struct InitFile {
  std::unique_ptr<gg::H5Input> in;
  // Whether it holds velocities; unknown for a resumed run whose start file is gone.
  std::optional<bool> has_velocities;
};

// Elastic run of cfg.equilibrate collisions per particle, then back to T = T0 at t = 0 (and, with
// --unwrapped, in image 0: the displacements count from t = 0). equilibrate.cpp.
template <int D>
void equilibrate(State<D>& st, const SimConfig& cfg);

}  // namespace ggsim
