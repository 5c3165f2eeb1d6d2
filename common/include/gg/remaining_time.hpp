#pragma once
// An estimate of the time left from a run's own recent rate: the fraction done per wall-clock
// second over the last minute (a cooling gas speeds up in simulated time as it cools, so the rate
// since the start would mislead), extrapolated to fraction 1.
#include <deque>
#include <optional>
#include <string>
#include <utility>

namespace gg {

class RemainingTime {
 public:
  static constexpr double kWindowSeconds = 60;
  static constexpr double kMinSpanSeconds = 1;  // no estimate from less than a second of progress

  // `seconds`: wall-clock time of the observation (any origin, not decreasing); `fraction` in [0, 1].
  void add(double seconds, double fraction);
  // Seconds left, or nullopt when the fraction has not moved over at least kMinSpanSeconds.
  std::optional<double> seconds_left() const;

 private:
  std::deque<std::pair<double, double>> samples_;  // (seconds, fraction), oldest first
};

// "about 45 s left", "about 3 min 20 s left", "about 2 h 5 min left".
std::string describe_time_left(double seconds);

}  // namespace gg
