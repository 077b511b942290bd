// Pending events are plain data: one per particle, invalidated lazily by collision counters.
// A cell crossing is data too: the face it leaves through, 2·axis + direction (0: towards lower
// coordinates, 1: higher), so that one code path serves every axis of a 2D or 3D grid.
#pragma once

#include <cstdint>

namespace granule {

// One byte per particle: 0 nothing, 1 a collision, 2 + face a crossing of that face.
enum class EventKind : std::uint8_t {
  kNone = 0,       // nothing ahead (event time is +inf)
  kCollision = 1,  // with `partner`, valid while the partner's collision counter is unchanged
};

inline constexpr std::uint8_t kFirstCrossing = 2;

constexpr EventKind crossing_through(int axis, int direction) {
  return static_cast<EventKind>(kFirstCrossing + 2 * axis + direction);
}
constexpr bool is_crossing(EventKind kind) { return static_cast<std::uint8_t>(kind) >= kFirstCrossing; }
constexpr int crossing_axis(EventKind kind) { return (static_cast<int>(kind) - kFirstCrossing) / 2; }
// +1 towards higher coordinates, −1 towards lower.
constexpr int crossing_direction(EventKind kind) { return (static_cast<int>(kind) - kFirstCrossing) % 2 == 1 ? 1 : -1; }
// The largest valid kind in d dimensions (checkpoints are checked against it).
constexpr std::uint8_t last_event_kind(int dimension) { return static_cast<std::uint8_t>(kFirstCrossing + 2 * dimension - 1); }

}  // namespace granule
