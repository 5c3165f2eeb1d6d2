#pragma once
// Why an engine's run() returned (engine.hpp).

namespace ggsim {

// kOneLeft and kOutgrewBox end an aggregating run only (aggregates.hpp): every particle has merged
// into one, or an aggregate has grown too large for the box to give each pair a single nearest image.
enum class StopReason { kTimeReached, kCollisionBudget, kInterrupted, kCollapse, kNothingLeft, kOneLeft, kOutgrewBox };

}  // namespace ggsim
