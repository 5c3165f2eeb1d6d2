#pragma once
// The definition of simulate<D, Fx> (simulate.hpp), included only by the translation units that
// compile the engine variants (one each, generated from simulate/variant.cpp.in).
#include <memory>
#include <string>
#include <vector>

#include "gg/errors.hpp"
#include "gg/progress.hpp"
#include "ggsim/checkpoint.hpp"
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
  // A fresh start's sizes by particle number (a mixture's), which the engine's sizes effect keeps
  // in its own order (a resumed run's are in its checkpoint). Aggregates start as particles of
  // radius 1/2 and mass 1 whose sizes then grow, given as a mixture's are so that the sizes effect
  // writes them with the snapshots.
  if (st) {
    par.radius = std::move(st->sizes.radius), par.mass = std::move(st->sizes.mass);
    par.species = std::move(st->sizes.species), par.species_count = st->sizes.species_count;
  }
  if constexpr (Engine<D, Fx>::Contact::kMerges)
    if (st) par.radius.assign(st->r.size(), 0.5), par.mass.assign(st->r.size(), 1.0);
  if (st) {
    box = st->box;
    SceneSize size{.n = static_cast<double>(st->r.size()), .volume = 1};
    for (double L : box.L) size.volume *= L;
    for (const SceneEffect* effect : scene_effects()) effect->start_parameters(cfg, size, par.rule.effects);
    eng = std::make_unique<Engine<D, Fx>>(box, st->r, st->v, par, std::move(st->effects));
    // The engine holds the start now; a run's memory is the engine's alone.
    std::vector<Vec<D>>().swap(st->r);
    std::vector<Vec<D>>().swap(st->v);
  } else {
    eng = std::make_unique<Engine<D, Fx>>(box, saved->engine_state<D>(&box), par);
  }
  std::vector<double>().swap(par.radius);  // the engine holds the sizes now
  std::vector<double>().swap(par.mass);
  std::vector<std::uint32_t>().swap(par.species);
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
    write_checkpoint<D>(cfg, box, eng->view(), rec, pieces);
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
