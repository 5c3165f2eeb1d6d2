#pragma once
// The observer of a run: samples E(t) and collisions per particle on a log-spaced time grid, and
// snapshots at the scene's times. The effects the scene uses add their observables (the pressure,
// the rotational energy of rough particles, the energy the drive put in: observables()) and their
// per-particle fields of a snapshot (angular velocities, the masses and radii of a mixture or of
// aggregates: frame_fields(), effects/effect_set.hpp), and at the end of the run their values fixed
// in time (a mixture's species: fixed_values()); so does the engine's contact policy (aggregates'
// N(t) and mean mass, contact/aggregate.hpp). It reads the engine and never changes it, so what is
// recorded cannot perturb the trajectory.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "gg/h5file.hpp"
#include "gg/progress.hpp"
#include "gg/trajectory.hpp"
#include "ggsim/config.hpp"
#include "ggsim/effects/effect_state.hpp"
#include "ggsim/snapshot_store.hpp"
#include "ggsim/stop_request.hpp"

namespace ggsim {

// Times `start` (if include_start), then 10^(k / per_decade) for every integer k with
// from <= 10^(k/per_decade) < t_max and 10^(k/per_decade) > start, then t_max itself if finite.
// With t_max infinite the grid continues on demand. A fresh run starts at 0; one that continues a
// file's clock (--continue) at the time of its last frame.
class LogTimes {
 public:
  LogTimes(double per_decade, double from, double t_max, bool include_start, double start = 0);
  double next() const { return next_; }
  void pop();
  // After restore() of a grid that was made for the end `old_t_max`: the end is t_max (larger)
  // now, so the grid goes on past the old end instead of stopping there.
  void extend_from(double old_t_max);
  // Position on the grid, for checkpoints.
  std::vector<double> state() const { return {static_cast<double>(k_), next_, at_end_ ? 1.0 : 0.0}; }
  void restore(const std::vector<double>& s) { k_ = static_cast<long>(s.at(0)), next_ = s.at(1), at_end_ = s.at(2) != 0; }

 private:
  double per_decade_, t_max_;
  long k_;
  double next_;
  bool at_end_ = false;
};

class Recorder {
 public:
  // `t_start`: the clock at the start (0, or the time of the file's last frame with --continue);
  // `effect_fields`: the effects' per-particle fields of a snapshot (EffectSet::frame_fields()).
  Recorder(const SimConfig& cfg, std::size_t n, int dim, const std::vector<double>& edges,
           gg::Progress* progress, double t_start = 0, const std::vector<FrameField>& effect_fields = {});

  double next_time() const { return std::min(samples_.next(), next_snapshot()); }

  template <class Engine>
  void observe(Engine& eng, double t) {
    if (samples_.next() <= t) {
      record_sample(eng, t);
      samples_.pop();
    }
    if (next_snapshot() <= t) {
      record_snapshot(eng, t);
      if (snapshot_grid_) snapshot_grid_->pop();
      ++snapshot_index_;
    }
  }

  // Called every 65536 events: progress line; true to pause the run for a stop request or a
  // due checkpoint (checkpoint_due() tells which).
  template <class Engine>
  bool poll(const Engine& eng) {
    if (progress_) report(eng.now(), eng.collisions());
    return stop_requested() || checkpoint_due();
  }
  bool checkpoint_due() const;
  void checkpoint_written();

  // Everything recorded and the position on the time grids (checkpoints).
  void save(gg::H5Output& out, const std::string& group) const;
  // `t_max_written`: the --t-max of the run that saved it (a resumed run may go further).
  void restore(const gg::H5Input& in, const std::string& group, double t_max_written);

  // Final state of the run: a last sample at the stop time if it is past the last one, and the
  // effects' values fixed in time, each at its particle's number in the start.
  template <class Engine>
  void finish(Engine& eng) {
    if (series_.time.empty() || eng.now() > series_.time.back()) record_sample(eng, eng.now());
    eng.effects().fixed_values([&](const std::string& name, const std::vector<double>& values) {
      std::vector<double>& to = fixed_[name];
      to.assign(values.size(), 0.0);
      for (std::uint32_t i = 0; i < values.size(); ++i) to[eng.label(i)] = values[i];
    });
  }

  const gg::TimeSeries& energy() const { return energy_; }
  const gg::TimeSeries& collisions() const { return series_; }
  // An effect's observable: its H5MD unit, its samples and the values of each (1, or an array's).
  struct EffectObservable {
    std::string unit;
    gg::TimeSeries series;
    std::size_t width = 1;
  };
  // By name (the output's /observables/NAME).
  const std::map<std::string, EffectObservable>& effect_observables() const { return effect_observables_; }
  // An effect's values fixed in time by the number in the start (fixed_values()), after finish();
  // empty if no effect has them.
  const std::vector<double>& fixed(const std::string& name) const {
    static const std::vector<double> kNone;
    const auto it = fixed_.find(name);
    return it == fixed_.end() ? kNone : it->second;
  }
  const SnapshotStore& snapshots() const { return snaps_; }

 private:
  double next_snapshot() const;
  void report(double t, std::uint64_t collisions);

  template <class Engine>
  void record_sample(Engine& eng, double t) {
    const auto n = static_cast<double>(eng.size());
    const double E = eng.kinetic_energy(t);
    const auto step = static_cast<std::int64_t>(eng.collisions());
    energy_.step.push_back(step);
    energy_.time.push_back(t);
    energy_.value.push_back(E);
    series_.step.push_back(step);
    series_.time.push_back(t);
    series_.value.push_back(2.0 * static_cast<double>(eng.collisions()) / n);
    const Sample at{.t = t, .kinetic_energy = E, .n = n, .volume = volume_, .dim = dim_,
                    .velocity_tensor = [&eng, t] { return eng.velocity_tensor(t); },
                    .squared_speeds = [&eng, t] { return eng.squared_speeds(t); }};
    const ObservableSink sink([&](const std::string& name, const std::string& unit, const std::vector<double>& values) {
      EffectObservable& o = effect_observables_[name];
      o.unit = unit;
      o.width = values.size();
      o.series.step.push_back(step);
      o.series.time.push_back(t);
      o.series.value.insert(o.series.value.end(), values.begin(), values.end());
    });
    eng.observables(sink, at);
  }

  // The frame is gathered here and goes to disk at once: between snapshots the run holds none.
  template <class Engine>
  void record_snapshot(Engine& eng, double t) {
    // The engine visits its particles in its own order; each is written at its number in the start.
    const auto d = static_cast<std::size_t>(dim_);
    std::vector<double> position(eng.size() * d), velocity(velocities_wanted_ ? eng.size() * d : 0);
    eng.for_each_particle(t, [&](std::uint32_t i, const auto& x, const auto& v) {
      std::copy(x.begin(), x.end(), position.data() + i * d);
      if (velocities_wanted_) std::copy(v.begin(), v.end(), velocity.data() + i * d);
    });
    std::vector<double> image(images_wanted_ ? eng.size() * d : 0);
    if (images_wanted_)
      eng.for_each_image(t, [&](std::uint32_t i, const auto& a) { std::copy(a.begin(), a.end(), image.data() + i * d); });
    // The more fields by particle number: a number the engine no longer holds (a part of an
    // aggregate) keeps 0.
    const std::vector<FrameField>& fields = snaps_.more_fields();
    std::vector<std::vector<double>> more(fields.size());
    for (std::size_t m = 0; m < fields.size(); ++m) more[m].assign(eng.size() * fields[m].components, 0.0);
    eng.effects().frame_values([&](const std::string& name, const std::vector<double>& values) {
      const auto kept = std::find_if(fields.begin(), fields.end(), [&](const FrameField& f) { return f.name == name; });
      if (kept == fields.end()) return;  // one kept only with the velocities
      const std::size_t c = kept->components;
      double* to = more[static_cast<std::size_t>(kept - fields.begin())].data();
      for (std::uint32_t i = 0; i < values.size() / c; ++i) std::copy_n(values.data() + i * c, c, to + eng.label(i) * c);
    });
    if constexpr (Engine::Contact::kMerges) {
      // Every start particle keeps its row (docs/DESIGN.md "Aggregates"): a start particle merged
      // into another has mass and radius 0 (the sizes effect's fields) and the position and velocity
      // of the particle it is part of.
      for (std::uint32_t i = 0; i < eng.size(); ++i) {
        const std::uint32_t a = eng.contact().aggregate_of(i);
        if (a == i) continue;
        std::copy_n(position.data() + a * d, d, position.data() + i * d);
        if (velocities_wanted_) std::copy_n(velocity.data() + a * d, d, velocity.data() + i * d);
      }
    }
    FrameValues values{.position = position.data(), .velocity = velocity.data(), .image = image.data()};
    for (const std::vector<double>& m : more) values.more.push_back(m.data());
    snaps_.append(t, static_cast<std::int64_t>(eng.collisions()), values);
  }

  LogTimes samples_;
  std::optional<LogTimes> snapshot_grid_;
  std::vector<double> snapshot_list_;
  std::size_t snapshot_index_ = 0;
  bool velocities_wanted_, images_wanted_;
  int dim_;
  double volume_, t_max_;
  std::uint64_t max_collisions_;
  gg::TimeSeries energy_, series_;
  std::map<std::string, EffectObservable> effect_observables_;
  SnapshotStore snaps_;
  gg::Progress* progress_;
  double checkpoint_every_;
  std::chrono::steady_clock::time_point last_checkpoint_ = std::chrono::steady_clock::now();
  std::map<std::string, std::vector<double>> fixed_;  // fixed_values() by the number in the start
};

}  // namespace ggsim
