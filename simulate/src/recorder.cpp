#include "ggsim/recorder.hpp"

#include <cstdio>

namespace ggsim {

volatile std::sig_atomic_t g_stop_requested = 0;

LogTimes::LogTimes(double per_decade, double from, double t_max, bool include_zero)
    : per_decade_(per_decade), t_max_(t_max) {
  k_ = static_cast<long>(std::ceil(std::log10(from) * per_decade_ - 1e-9));
  next_ = include_zero ? 0.0 : std::pow(10.0, k_ / per_decade_);
  if (!include_zero && !(next_ < t_max_)) next_ = t_max_, at_end_ = true;
}

void LogTimes::pop() {
  if (at_end_) {
    next_ = std::numeric_limits<double>::infinity();
    return;
  }
  const double candidate = next_ == 0 ? std::pow(10.0, k_ / per_decade_) : std::pow(10.0, ++k_ / per_decade_);
  if (candidate < t_max_) {
    next_ = candidate;
  } else {
    next_ = t_max_;  // infinite t_max: never reached
    at_end_ = true;
  }
}

Recorder::Recorder(const SimConfig& cfg, std::size_t n, int dim, const std::vector<double>& edges,
                   gg::Progress* progress)
    : samples_(cfg.samples_per_decade, cfg.sample_from, cfg.t_max, true),
      pressure_wanted_(cfg.pressure),
      velocities_wanted_(cfg.velocities),
      dim_(dim),
      t_max_(cfg.t_max),
      max_collisions_(cfg.max_collisions),
      progress_(progress) {
  volume_ = 1;
  for (double L : edges) volume_ *= L;
  rho_ = static_cast<double>(n) / volume_;
  if (cfg.snapshots_per_decade > 0) snapshot_grid_.emplace(cfg.snapshots_per_decade, cfg.snapshots_from, cfg.t_max, false);
  snapshot_list_ = cfg.snapshots;
  std::sort(snapshot_list_.begin(), snapshot_list_.end());
  snapshot_list_.erase(std::unique(snapshot_list_.begin(), snapshot_list_.end()), snapshot_list_.end());
  snaps_.dim = dim;
  snaps_.edges = edges;
  snaps_.n_particles = n;
}

double Recorder::next_snapshot() const {
  if (snapshot_grid_) return snapshot_grid_->next();
  return snapshot_index_ < snapshot_list_.size() ? snapshot_list_[snapshot_index_]
                                                  : std::numeric_limits<double>::infinity();
}

void Recorder::report(double t, std::uint64_t collisions) {
  double fraction = 0;
  if (std::isfinite(t_max_)) fraction = t / t_max_;
  else fraction = static_cast<double>(collisions) / static_cast<double>(max_collisions_);
  char detail[96];
  std::snprintf(detail, sizeof detail, "t = %.4g, %.3g collisions", t, static_cast<double>(collisions));
  progress_->update(fraction, detail);
}

}  // namespace ggsim
