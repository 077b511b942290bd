// Pending events are plain data: one per particle, invalidated lazily by collision counters.
// A cell crossing is data too: the face it leaves through, 2·axis + direction (0: towards lower
// coordinates, 1: higher), so that one code path serves every axis of a 2D or 3D grid; and so is
// a surface hit: the kind of surface of the boundaries (boundary/surface_id.hpp), which the hit's
// execution resolves to the surface the grain touches.
#pragma once

#include <cstdint>

#include "boundary/surface_id.hpp"

namespace granule {

// One byte per particle: 0 nothing, 1 a collision, 2 + face a crossing of that face, 8 + kind a
// hit of a surface of that kind (8: past the crossings of a 3D grid, so 2D and 3D share the codes).
enum class EventKind : std::uint8_t {
  kNone = 0,       // nothing ahead (event time is +inf)
  kCollision = 1,  // with `partner`, valid while the partner's collision counter is unchanged
};

inline constexpr std::uint8_t kFirstCrossing = 2;
inline constexpr std::uint8_t kFirstSurfaceHit = 8;
inline constexpr std::uint8_t kLastEventKind = kFirstSurfaceHit + kSurfaceKinds - 1;

constexpr EventKind crossing_through(int axis, int direction) {
  return static_cast<EventKind>(kFirstCrossing + 2 * axis + direction);
}
constexpr bool is_crossing(EventKind kind) {
  return static_cast<std::uint8_t>(kind) >= kFirstCrossing && static_cast<std::uint8_t>(kind) < kFirstSurfaceHit;
}
constexpr EventKind surface_hit(int surface) { return static_cast<EventKind>(kFirstSurfaceHit + surface); }
constexpr bool is_surface_hit(EventKind kind) { return static_cast<std::uint8_t>(kind) >= kFirstSurfaceHit; }
constexpr int hit_surface(EventKind kind) { return static_cast<int>(kind) - kFirstSurfaceHit; }
constexpr int crossing_axis(EventKind kind) { return (static_cast<int>(kind) - kFirstCrossing) / 2; }
// +1 towards higher coordinates, −1 towards lower.
constexpr int crossing_direction(EventKind kind) { return (static_cast<int>(kind) - kFirstCrossing) % 2 == 1 ? 1 : -1; }
// Whether a kind can exist in d dimensions (checkpoints are checked against it).
constexpr bool valid_event_kind(std::uint8_t kind, int dimension) {
  return kind < kFirstCrossing + 2 * dimension || (kind >= kFirstSurfaceHit && surface_kind_exists(kind - kFirstSurfaceHit, dimension));
}

}  // namespace granule
