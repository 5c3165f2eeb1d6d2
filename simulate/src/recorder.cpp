#include "ggsim/recorder.hpp"

#include <algorithm>
#include <cstdio>

#include "gg/errors.hpp"
#include "ggsim/effects/image_counts.hpp"

namespace ggsim {

LogTimes::LogTimes(double per_decade, double from, double t_max, bool include_start, double start)
    : per_decade_(per_decade), t_max_(t_max) {
  k_ = static_cast<long>(std::ceil(std::log10(from) * per_decade_ - 1e-9));
  if (start > 0) {  // the grid goes on after the start
    k_ = std::max(k_, static_cast<long>(std::floor(std::log10(start) * per_decade_)));
    while (std::pow(10.0, k_ / per_decade_) <= start) ++k_;
  }
  next_ = include_start ? start : std::pow(10.0, k_ / per_decade_);
  if (!include_start && !(next_ < t_max_)) next_ = t_max_, at_end_ = true;
}

void LogTimes::pop() {
  if (at_end_) {
    next_ = std::numeric_limits<double>::infinity();
    return;
  }
  // k_ is the grid time after the start until that time has been taken.
  const double grid = std::pow(10.0, k_ / per_decade_);
  const double candidate = next_ < grid ? grid : std::pow(10.0, ++k_ / per_decade_);
  if (candidate < t_max_) {
    next_ = candidate;
  } else {
    next_ = t_max_;  // infinite t_max: never reached
    at_end_ = true;
  }
}

void LogTimes::extend_from(double old_t_max) {
  if (!at_end_ || !(t_max_ > old_t_max)) return;
  // Stopped at the old end: k_ is the first grid time at or past it, not taken.
  if (next_ != old_t_max) return;  // the old end was taken already: nothing to go on from
  const double grid = std::pow(10.0, k_ / per_decade_);
  at_end_ = !(grid < t_max_);
  next_ = at_end_ ? t_max_ : grid;
}

namespace {

// What the snapshots keep: the effects' fields, those that go with the velocities only if the
// velocities do.
SnapshotFields snapshot_fields(const SimConfig& cfg, const std::vector<FrameField>& effect_fields) {
  SnapshotFields kept{.velocities = cfg.velocities, .images = cfg.effects.get<ImageParameters>().on};
  for (const FrameField& f : effect_fields)
    if (!f.with_velocities || cfg.velocities) kept.more.push_back(f);
  return kept;
}

}  // namespace

Recorder::Recorder(const SimConfig& cfg, std::size_t n, int dim, const std::vector<double>& edges,
                   gg::Progress* progress, double t_start, const std::vector<FrameField>& effect_fields)
    : samples_(cfg.samples_per_decade, cfg.sample_from, cfg.t_max, true, t_start),
      velocities_wanted_(cfg.velocities),
      images_wanted_(cfg.effects.get<ImageParameters>().on),
      dim_(dim),
      t_max_(cfg.t_max),
      max_collisions_(cfg.max_collisions),
      snaps_(cfg.output, n, dim, edges, snapshot_fields(cfg, effect_fields)),
      progress_(progress),
      checkpoint_every_(cfg.checkpoint_every) {
  volume_ = 1;
  for (double L : edges) volume_ *= L;
  if (cfg.snapshots_per_decade > 0)
    snapshot_grid_.emplace(cfg.snapshots_per_decade, cfg.snapshots_from, cfg.t_max, false, t_start);
  snapshot_list_ = cfg.snapshots;  // increasing (SimConfig::resolve), none before the start (run.cpp)
}

double Recorder::next_snapshot() const {
  if (snapshot_grid_) return snapshot_grid_->next();
  return snapshot_index_ < snapshot_list_.size() ? snapshot_list_[snapshot_index_]
                                                  : std::numeric_limits<double>::infinity();
}

void Recorder::report(double t, std::uint64_t collisions) {
  // The run stops at whichever limit comes first (t / infinity = 0; no budget is 2^64 collisions).
  const double fraction = std::max(t / t_max_, static_cast<double>(collisions) / static_cast<double>(max_collisions_));
  char detail[96];
  std::snprintf(detail, sizeof detail, "t = %.4g, %.3g collisions", t, static_cast<double>(collisions));
  progress_->update(fraction, detail);
}

}  // namespace ggsim

namespace ggsim {

bool Recorder::checkpoint_due() const {
  if (checkpoint_every_ <= 0) return false;
  const std::chrono::duration<double> since = std::chrono::steady_clock::now() - last_checkpoint_;
  return since.count() >= checkpoint_every_;
}

void Recorder::checkpoint_written() { last_checkpoint_ = std::chrono::steady_clock::now(); }

namespace {
void save_series(gg::H5Output& out, const std::string& g, const gg::TimeSeries& ts) {
  out.write(g + "/step", ts.step);
  out.write(g + "/time", ts.time);
  out.write(g + "/value", ts.value);
}
gg::TimeSeries load_series(const gg::H5Input& in, const std::string& g) {
  gg::TimeSeries ts;
  ts.step = in.read_int(g + "/step");
  ts.time = in.read(g + "/time").data;
  ts.value = in.read(g + "/value").data;
  return ts;
}
}  // namespace

void Recorder::save(gg::H5Output& out, const std::string& group) const {
  save_series(out, group + "/energy", energy_);
  save_series(out, group + "/collisions", series_);
  for (const auto& [name, o] : effect_observables_) {
    save_series(out, group + "/effect_observables/" + name, o.series);
    out.attr(group + "/effect_observables/" + name, "unit", o.unit);
  }
  // The frames one at a time from the store, [T][N][d] as in the output.
  const gg::Snapshots& index = snaps_.index();
  out.write(group + "/snapshots/time", index.time);
  out.write(group + "/snapshots/step", index.step);
  const std::vector<std::size_t> shape{index.frames(), index.n_particles, static_cast<std::size_t>(index.dim)};
  out.write_rows(group + "/snapshots/position", shape, snaps_.positions());
  if (velocities_wanted_) out.write_rows(group + "/snapshots/velocity", shape, snaps_.velocities());
  if (images_wanted_) out.write_rows(group + "/snapshots/image", shape, snaps_.images());
  const std::vector<FrameField>& more = snaps_.more_fields();
  for (std::size_t m = 0; m < more.size(); ++m)
    out.write_rows(group + "/snapshots/" + more[m].name, {index.frames(), index.n_particles, more[m].components},
                   snaps_.more(m));
  out.write(group + "/samples_grid", samples_.state());
  out.write(group + "/snapshot_grid", snapshot_grid_ ? snapshot_grid_->state() : std::vector<double>{});
  out.write_scalar(group + "/snapshot_index", static_cast<std::int64_t>(snapshot_index_));
}

void Recorder::restore(const gg::H5Input& in, const std::string& group, double t_max_written) {
  energy_ = load_series(in, group + "/energy");
  series_ = load_series(in, group + "/collisions");
  if (in.exists(group + "/effect_observables"))
    for (const std::string& name : in.members(group + "/effect_observables")) {
      const std::string g = group + "/effect_observables/" + name;
      EffectObservable& o = effect_observables_[name];
      o = {in.attr_string(g, "unit").value_or(""), load_series(in, g)};
      o.width = o.series.time.empty() ? 1 : o.series.value.size() / o.series.time.size();
    }
  const std::vector<double> time = in.read(group + "/snapshots/time").data;
  const std::vector<std::int64_t> step = in.read_int(group + "/snapshots/step");
  const std::size_t n = snaps_.index().n_particles;
  const std::size_t values = n * static_cast<std::size_t>(dim_);
  const std::vector<FrameField>& more = snaps_.more_fields();
  const auto damaged = [&](std::size_t k) {
    return gg::RuntimeError(in.path() + ": snapshot " + std::to_string(k) + " in " + group +
                            " has the wrong size; the checkpoint is damaged");
  };
  for (std::size_t k = 0; k < time.size(); ++k) {  // a frame at a time, as the store keeps them
    const std::vector<double> position = in.read_rows(group + "/snapshots/position", {k}).data;
    const std::vector<double> velocity =
        velocities_wanted_ ? in.read_rows(group + "/snapshots/velocity", {k}).data : std::vector<double>();
    const std::vector<double> image =
        images_wanted_ ? in.read_rows(group + "/snapshots/image", {k}).data : std::vector<double>();
    if (position.size() != values || velocity.size() != (velocities_wanted_ ? values : 0) ||
        image.size() != (images_wanted_ ? values : 0))
      throw damaged(k);
    std::vector<std::vector<double>> fields;
    FrameValues frame{.position = position.data(), .velocity = velocity.data(), .image = image.data()};
    for (const FrameField& f : more) {
      fields.push_back(in.read_rows(group + "/snapshots/" + f.name, {k}).data);
      if (fields.back().size() != n * f.components) throw damaged(k);
    }
    for (const std::vector<double>& f : fields) frame.more.push_back(f.data());
    snaps_.append(time[k], step.at(k), frame);
  }
  samples_.restore(in.read(group + "/samples_grid").data);
  samples_.extend_from(t_max_written);
  if (snapshot_grid_) {
    snapshot_grid_->restore(in.read(group + "/snapshot_grid").data);
    snapshot_grid_->extend_from(t_max_written);
  }
  snapshot_index_ = static_cast<std::size_t>(in.read_int(group + "/snapshot_index").at(0));
}

}  // namespace ggsim
