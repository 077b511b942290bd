// Why Simulation::run() returned, and where an inelastic collapse happened.
#pragma once

#include <cstdint>

#include "geometry/vec.hpp"

namespace granule {

enum class StopReason {
  kTimeReached,        // the requested time
  kCollisionsReached,  // the requested number of collisions
  kNoEvents,           // nothing will ever happen (all disks at rest relative to each other)
  kInelasticCollapse,  // collisions piled up in vanishing time (see CollapseDetector)
  kInterrupted,        // the interrupt flag was raised (a signal): stopped after a whole event
};

struct CollapseReport {
  double time = 0.0;
  std::int32_t first = -1;
  std::int32_t second = -1;  // −1: the last collision was with a wall
  Vec3 position;  // z = 0 in 2D
};

}  // namespace granule
