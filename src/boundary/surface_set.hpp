// The surfaces a grain can hit, as a configuration gives them: flat walls at both ends of the axes
// `walls` marks (faces 2·axis + side, boundary/wall.hpp) and fixed obstacles (boundary/obstacle.hpp).
// What the boundaries are built from and what a checkpoint records of them.
#pragma once

#include <array>
#include <vector>

#include "boundary/obstacle.hpp"
#include "boundary/wall.hpp"

namespace granule {

struct SurfaceSet {
  const std::array<bool, 3>& walls;
  const std::array<WallParams, 6>& wall;
  const std::vector<Obstacle>& obstacles;
  bool grains_rest = false;  // grains may come to rest (physics/rest_rule.hpp)
};

}  // namespace granule
