#pragma once
// Checkpoints: the full state of a run (engine, recorder, scene) in one HDF5 file, written
// atomically and sealed with a checksum, from which --resume continues bit for bit. Every reader
// below checks the seal first: a damaged checkpoint is refused, never resumed into another run.
#include <string>

#include "gg/box.hpp"
#include "ggsim/config.hpp"
#include "ggsim/engine.hpp"
#include "ggsim/recorder.hpp"
#include "ggsim/resume_scene.hpp"

namespace ggsim {

template <int D>
void write_checkpoint(const SimConfig& cfg, const gg::Box<D>& box, const EngineView<D>& eng, const Recorder& rec);

// Reads the checkpoint cfg.resume, written by the same scene (else gg::UsageError naming the key
// that differs; --t-max and --max-collisions may have grown): the engine state and the box.
template <int D>
EngineState<D> read_checkpoint(const SimConfig& cfg, gg::Box<D>* box);

// A mixture's sizes by particle number, as the checkpoint cfg.resume holds them (empty without
// a mixture), and whether it holds them.
Sizes read_checkpoint_sizes(const SimConfig& cfg);
bool checkpoint_has_sizes(const std::string& path);

// Puts the recorder back where the checkpoint cfg.resume left it.
void restore_recorder(const SimConfig& cfg, Recorder& rec);

// The dimension a checkpoint was written for (to pick the engine before reading it).
int checkpoint_dimension(const std::string& path);

// The scene a checkpoint was written by (for `--resume CK` without the original command).
SceneValues checkpoint_scene(const std::string& path);

// How many particles its run has (for the memory check before resuming).
std::size_t checkpoint_particles(const std::string& path);

}  // namespace ggsim
