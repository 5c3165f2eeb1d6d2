#include "gg/remaining_time.hpp"

#include <cmath>

namespace gg {

void RemainingTime::add(double seconds, double fraction) {
  samples_.emplace_back(seconds, fraction);
  // Keep one sample at or before the window's start, so the span is a whole minute once there is one.
  while (samples_.size() > 2 && samples_[1].first <= seconds - kWindowSeconds) samples_.pop_front();
}

std::optional<double> RemainingTime::seconds_left() const {
  if (samples_.size() < 2) return std::nullopt;
  const auto& [t0, f0] = samples_.front();
  const auto& [t1, f1] = samples_.back();
  if (t1 - t0 < kMinSpanSeconds || !(f1 > f0)) return std::nullopt;
  return (1 - f1) * (t1 - t0) / (f1 - f0);
}

std::string describe_time_left(double seconds) {
  const long s = std::lround(std::max(seconds, 0.0));
  std::string text;
  if (s < 60)
    text = std::to_string(s) + " s";
  else if (s < 3600)
    text = std::to_string(s / 60) + " min " + std::to_string(s % 60) + " s";
  else
    text = std::to_string(s / 3600) + " h " + std::to_string(s % 3600 / 60) + " min";
  return "about " + text + " left";
}

}  // namespace gg
