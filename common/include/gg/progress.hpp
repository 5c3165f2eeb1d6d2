#pragma once
// Progress line on stderr for long runs ("\r" updates at most a few times per second), with an
// estimate of the time left from the run's recent rate (RemainingTime).
#include <chrono>
#include <string>

#include "gg/remaining_time.hpp"

namespace gg {

class Progress {
 public:
  Progress(bool enabled, std::string label);
  ~Progress();  // ends the line if anything was printed
  // fraction in [0,1]; `detail` is appended (e.g. "t = 12.5, 3.1e6 collisions").
  void update(double fraction, const std::string& detail = {});

 private:
  bool enabled_;
  std::string label_;
  bool printed_ = false;
  std::size_t width_ = 0;  // length of the last line, to blank it out when the next is shorter
  std::chrono::steady_clock::time_point last_{};
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  RemainingTime left_;
};

}  // namespace gg
