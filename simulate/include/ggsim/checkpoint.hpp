#pragma once
// Checkpoints: the full state of a run (engine, recorder, scene) in one HDF5 file, written
// atomically and sealed with a checksum, from which --resume continues bit for bit. Every reader
// below checks the seal first: a damaged checkpoint is refused, never resumed into another run.
#include <memory>
#include <string>

#include "gg/box.hpp"
#include "gg/h5file.hpp"
#include "ggsim/config.hpp"
#include "ggsim/engine.hpp"
#include "ggsim/recorder.hpp"
#include "ggsim/resume_scene.hpp"
#include "ggsim/run_pieces.hpp"

namespace ggsim {

// `effects`: the key of the effects the engine holds (effects/effect_set.hpp, kBit), which the
// checkpoint names so that a resume holds them too.
template <int D>
void write_checkpoint(const SimConfig& cfg, const gg::Box<D>& box, const EngineView<D>& eng, const Recorder& rec,
                      const RunPieces& pieces, unsigned effects);

// A checkpoint opened for --resume: read once, its seal, format and build checked when it is opened
// (gg::RuntimeError for a damaged file, gg::UsageError for another format, or for another build of
// gg-sim unless `allow_other_build`, run_pieces.hpp), its scene read, then read part by part
// and closed when the run has taken what it needs (close(): a run rewrites its checkpoint, and an
// open handle would keep the old file's disk space).
class SavedRun {
 public:
  explicit SavedRun(const std::string& path, bool allow_other_build = false);
  ~SavedRun();
  const std::string& path() const { return path_; }
  // The scene it was written by (the run's own is compared with it once, run.cpp).
  const SceneValues& scene() const { return scene_; }
  int dimension() const { return dimension_; }
  // The pieces of the run so far, and whether this build differs from the one that wrote them.
  const RunPieces& pieces() const { return pieces_; }
  bool other_build() const { return other_build_; }
  std::size_t particles() const { return particles_; }
  // The engine state and the box.
  template <int D>
  EngineState<D> engine_state(gg::Box<D>* box) const;
  // The key of the effects the engine that wrote it held (0 for a checkpoint of format 10, which
  // does not name them: a resume holds those of its scene): a resume's engine holds them too, so
  // that each takes its state back whether the scene names it or not (a start from a mixture's output).
  unsigned effects() const { return effects_; }
  // Throws gg::RuntimeError if an engine built from it left saved state `left` untaken (an
  // effect of the run that wrote it is missing).
  void require_taken(const EffectRecords& left) const;
  // Puts the recorder back where the run left it.
  void restore(Recorder& rec) const;
  void close();

 private:
  const gg::H5Input& file() const;
  std::string path_;
  std::unique_ptr<gg::H5Input> in_;
  SceneValues scene_;
  int dimension_ = 0;
  std::size_t particles_ = 0;
  RunPieces pieces_;
  bool other_build_ = false;
  unsigned effects_ = 0;
  bool lists_effects_ = false;  // its format names the effects
};

}  // namespace ggsim
