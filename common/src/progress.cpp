// "\r<label> 45.2% <detail>, about 3 min 20 s left" on stderr, redrawn at most four times a second so that printing
// never costs the simulation noticeable time.
#include "gg/progress.hpp"

#include <algorithm>
#include <cstdio>

namespace gg {
namespace {

constexpr auto kMinInterval = std::chrono::milliseconds(250);

}  // namespace

Progress::Progress(bool enabled, std::string label) : enabled_(enabled), label_(std::move(label)) {}

Progress::~Progress() {
  if (printed_) std::fputc('\n', stderr);
}

void Progress::update(double fraction, const std::string& detail) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  const bool done = fraction >= 1;
  if (printed_ && !done && now - last_ < kMinInterval) return;
  last_ = now;
  printed_ = true;
  char percent[16];
  std::snprintf(percent, sizeof percent, "%.1f%%", 100 * std::clamp(fraction, 0.0, 1.0));
  std::string line = label_ + " " + percent + (detail.empty() ? "" : " " + detail);
  left_.add(std::chrono::duration<double>(now - start_).count(), fraction);
  if (const std::optional<double> seconds = left_.seconds_left(); seconds && !done)
    line += ", " + describe_time_left(*seconds);
  const std::size_t width = line.size();
  // Spaces, not terminal escapes, erase the rest of a longer previous line: --progress may go to a log file.
  line.resize(std::max(width, width_), ' ');
  width_ = width;
  std::fprintf(stderr, "\r%s", line.c_str());
  std::fflush(stderr);
}

}  // namespace gg
