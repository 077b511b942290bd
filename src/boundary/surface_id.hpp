// Which surface of the boundaries a grain touches: the flat wall at one of the box's faces, a
// fixed obstacle, or a grain at rest (physics/rest_rule.hpp), which stands as a fixed support.  The event queue stores only a surface's kind (EventKind = kFirstSurfaceHit +
// kind, events/event.hpp) and the hit's execution finds the obstacle again; observers, checks and
// messages get the whole id, so that the engine, which passes it on, names no kind of surface.
#pragma once

#include <cstdint>
#include <string>

namespace granule {

// Surface kinds: the walls at faces 0 … 5 (face 2·axis + side, side 0 at coordinate 0 and 1 at L),
// then one kind for all the obstacles and one for all the grains at rest: the round surfaces, fixed
// spheres listed by the cells they can be touched from.
inline constexpr int kObstacleSurface = 6;
inline constexpr int kRestingGrainSurface = 7;
inline constexpr int kSurfaceKinds = kRestingGrainSurface + 1;
constexpr bool is_round_surface(int kind) { return kind >= kObstacleSurface; }

// Whether surface kind `kind` can exist in d dimensions (checkpoints are checked against it).
constexpr bool surface_kind_exists(int kind, int dimension) {
  return (kind >= 0 && kind < 2 * dimension) || (kind >= kObstacleSurface && kind < kSurfaceKinds);
}

struct SurfaceId {
  int kind = -1;            // −1: none
  // Which obstacle (its place in the configuration) or which grain at rest (the engine's number
  // inside the engine, the user's id in what observers get); −1 for a wall.
  std::int32_t index = -1;

  bool found() const { return kind >= 0; }
  bool wall() const { return kind >= 0 && kind < kObstacleSurface; }
  // A wall's face, axis and side.
  int face() const { return kind; }
  int axis() const { return kind / 2; }
  int side() const { return kind % 2; }
  // An obstacle's index, −1 for anything else.
  std::int32_t obstacle() const { return kind == kObstacleSurface ? index : -1; }
  // For messages: "the wall at face 2", "obstacle 3" ("an obstacle" when none was found), "the
  // grain at rest 12".
  // A grain at rest's number, −1 for anything else.
  std::int32_t resting_grain() const { return kind == kRestingGrainSurface ? index : -1; }
  std::string name() const {
    if (wall()) return "the wall at face " + std::to_string(kind);
    if (kind == kRestingGrainSurface) return index >= 0 ? "the grain at rest " + std::to_string(index) : "a grain at rest";
    return index >= 0 ? "obstacle " + std::to_string(index) : "an obstacle";
  }
};

}  // namespace granule
