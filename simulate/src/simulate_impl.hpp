#pragma once
// The definition of simulate<D, Fx> (simulate.hpp), included only by the translation units that
// compile the engine variants (one each, generated from simulate/variant.cpp.in).
#include <memory>
#include <string>
#include <vector>

#include "gg/errors.hpp"
#include "gg/progress.hpp"
#include "ggsim/checkpoint.hpp"
#include "ggsim/effects/particle_sizes.hpp"
#include "ggsim/engine.hpp"
#include "ggsim/recorder.hpp"
#include "ggsim/scene_effect.hpp"
#include "ggsim/stop_request.hpp"
#include "run_output.hpp"
#include "simulate.hpp"

namespace ggsim {

template <int D, class Fx>
int simulate(const SimConfig& cfg, State<D>* st, SavedRun* saved, const InitFile& init,
             const std::vector<std::string>& argv, bool show_progress) {
  EngineParameters par;
  par.rule = {cfg.e, cfg.effects};
  par.skin = cfg.skin;
  const double t_start = st ? st->t0 : 0;
  par.t0 = t_start;
  par.collisions0 = st ? st->step0 : 0;
  gg::Box<D> box;
  std::unique_ptr<Engine<D, Fx>> eng;
  if (st) {
    box = st->box;
    SceneSize size{.n = static_cast<double>(st->r.size()), .volume = 1};
    for (double L : box.L) size.volume *= L;
    for (const SceneEffect* effect : scene_effects()) effect->start_parameters(cfg, size, par.rule.effects);
    // The start's sizes (a mixture's, by particle number) are the sizes effect's start arrays.
    ParticleSizes::add_start(std::move(st->sizes), st->effects);
    eng = std::make_unique<Engine<D, Fx>>(box, st->r, st->v, par, std::move(st->effects));
    // The engine holds the start now; a run's memory is the engine's alone.
    std::vector<Vec<D>>().swap(st->r);
    std::vector<Vec<D>>().swap(st->v);
  } else {
    EngineState<D> state = saved->engine_state<D>(&box);
    eng = std::make_unique<Engine<D, Fx>>(box, std::move(state), par);
    // Each effect took its own arrays out of state.effects; every saved array belongs to an effect
    // this engine holds, and one left over is state this run would lose (a checkpoint of format 10,
    // which does not name its effects, of a run whose effects its scene does not name: a start from
    // a mixture's output).
    saved->require_taken(state.effects);
  }
  gg::Progress progress(show_progress, "gg-sim");
  std::vector<double> edges(box.L.begin(), box.L.end());
  Recorder rec(cfg, eng->size(), D, edges, show_progress ? &progress : nullptr, t_start, eng->effects().frame_fields());
  RunPieces pieces = saved ? saved->pieces() : RunPieces{};
  pieces.start(eng->now(), argv, saved && saved->other_build());
  if (!st) {
    saved->restore(rec);
    saved->close();
  }
  const auto checkpoint = [&] {
    pieces.end_at(eng->now());
    write_checkpoint<D>(cfg, box, eng->view(), rec, pieces, Fx::kKey);
  };
  StopReason why;
  for (;;) {
    why = eng->run(cfg.t_max, cfg.max_collisions, rec);
    if (why != StopReason::kInterrupted || g_stop_requested) break;
    checkpoint();  // a periodic checkpoint was due
    rec.checkpoint_written();
  }
  // Elastic disks cannot collapse, nor can a gas before its first free flight: a stall then means
  // disks in contact at the start, colliding again and again at one instant.
  if (why == StopReason::kCollapse && (cfg.e == 1 || (st && eng->now() == t_start)))
    throw gg::RuntimeError(stalled_start_message(cfg, eng->now()));
  const bool keep_checkpoint = why == StopReason::kInterrupted && !cfg.checkpoint_path().empty();
  if (keep_checkpoint) checkpoint();
  rec.finish(*eng);
  pieces.end_at(eng->now());
  write_output(cfg, argv, rec, init, why, pieces);
  return report_end(cfg, argv, why, eng->now(),
                    2.0 * static_cast<double>(eng->collisions()) / static_cast<double>(eng->size()), keep_checkpoint);
}

}  // namespace ggsim
