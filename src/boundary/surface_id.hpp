// Which surface of the boundaries a grain touches: the flat wall at one of the box's faces, or a
// fixed obstacle.  The event queue stores only a surface's kind (EventKind = kFirstSurfaceHit +
// kind, events/event.hpp) and the hit's execution finds the obstacle again; observers, checks and
// messages get the whole id, so that the engine, which passes it on, names no kind of surface.
#pragma once

#include <cstdint>
#include <string>

namespace granule {

// Surface kinds: the walls at faces 0 … 5 (face 2·axis + side, side 0 at coordinate 0 and 1 at L),
// then one kind for all the obstacles.
inline constexpr int kObstacleSurface = 6;
inline constexpr int kSurfaceKinds = kObstacleSurface + 1;

// Whether surface kind `kind` can exist in d dimensions (checkpoints are checked against it).
constexpr bool surface_kind_exists(int kind, int dimension) {
  return (kind >= 0 && kind < 2 * dimension) || (kind >= kObstacleSurface && kind < kSurfaceKinds);
}

struct SurfaceId {
  int kind = -1;            // −1: none
  std::int32_t index = -1;  // which obstacle (its place in the configuration); −1 for a wall

  bool found() const { return kind >= 0; }
  bool wall() const { return kind >= 0 && kind < kObstacleSurface; }
  // A wall's face, axis and side.
  int face() const { return kind; }
  int axis() const { return kind / 2; }
  int side() const { return kind % 2; }
  // An obstacle's index, −1 for anything else.
  std::int32_t obstacle() const { return kind == kObstacleSurface ? index : -1; }
  // For messages: "the wall at face 2", "obstacle 3" ("an obstacle" when none was found).
  std::string name() const {
    if (wall()) return "the wall at face " + std::to_string(kind);
    return index >= 0 ? "obstacle " + std::to_string(index) : "an obstacle";
  }
};

}  // namespace granule
