// Pending events are plain data: one per particle, invalidated lazily by collision counters.
// A cell crossing is data too: the face it leaves through, 2·axis + direction (0: towards lower
// coordinates, 1: higher), so that one code path serves every axis of a 2D or 3D grid; and so is
// a wall hit: the wall's face, 2·axis + side (side 0 at coordinate 0, 1 at L); and an obstacle hit,
// whose obstacle the execution finds again as the one the grain touches (cells/obstacle_lists.hpp).
#pragma once

#include <cstdint>

namespace granule {

// One byte per particle: 0 nothing, 1 a collision, 2 + face a crossing of that face, 8 + face a hit
// of the wall at that face (8: past the crossings of a 3D grid, so 2D and 3D share the codes), 14
// a hit of a fixed obstacle.
enum class EventKind : std::uint8_t {
  kNone = 0,       // nothing ahead (event time is +inf)
  kCollision = 1,  // with `partner`, valid while the partner's collision counter is unchanged
};

inline constexpr std::uint8_t kFirstCrossing = 2;
inline constexpr std::uint8_t kFirstWallHit = 8;
inline constexpr std::uint8_t kObstacleHitKind = kFirstWallHit + 6;
inline constexpr EventKind kObstacleHit = static_cast<EventKind>(kObstacleHitKind);

constexpr EventKind crossing_through(int axis, int direction) {
  return static_cast<EventKind>(kFirstCrossing + 2 * axis + direction);
}
constexpr bool is_crossing(EventKind kind) {
  return static_cast<std::uint8_t>(kind) >= kFirstCrossing && static_cast<std::uint8_t>(kind) < kFirstWallHit;
}
constexpr EventKind wall_hit(int face) { return static_cast<EventKind>(kFirstWallHit + face); }
constexpr bool is_wall_hit(EventKind kind) {
  return static_cast<std::uint8_t>(kind) >= kFirstWallHit && static_cast<std::uint8_t>(kind) < kObstacleHitKind;
}
constexpr int wall_face(EventKind kind) { return static_cast<int>(kind) - kFirstWallHit; }
constexpr int crossing_axis(EventKind kind) { return (static_cast<int>(kind) - kFirstCrossing) / 2; }
// +1 towards higher coordinates, −1 towards lower.
constexpr int crossing_direction(EventKind kind) { return (static_cast<int>(kind) - kFirstCrossing) % 2 == 1 ? 1 : -1; }
// Whether a kind can exist in d dimensions (checkpoints are checked against it).
constexpr bool valid_event_kind(std::uint8_t kind, int dimension) {
  return kind < kFirstCrossing + 2 * dimension || (kind >= kFirstWallHit && kind < kFirstWallHit + 2 * dimension) ||
         kind == kObstacleHitKind;
}

}  // namespace granule
