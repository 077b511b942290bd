// The smooth inelastic binary collision of identical unit-mass disks (thesis eq 1.2, Fig 1.3).
#pragma once

#include "geometry/vec2.hpp"

namespace granule {

// Scalar impulse J·k̂ transferred to disk 2 by disk 1 along k̂ (thesis Fig 1.3):
// J = (1 + e)/2 (v21·k̂) k̂ with v21 = v1 − v2 and k̂ the unit vector from disk 1 to disk 2.
// Positive when the disks approach.
constexpr double normal_impulse(Vec2 v21, Vec2 k_hat, double restitution) {
  return 0.5 * (1.0 + restitution) * dot(v21, k_hat);
}

struct PostCollisionVelocities {
  Vec2 v1;
  Vec2 v2;
};

// Thesis eq (1.2): v1' = v1 − J k̂,  v2' = v2 + J k̂.  Momentum is conserved exactly in exact
// arithmetic; the kinetic energy falls by (1 − e²)/4 (v21·k̂)².
constexpr PostCollisionVelocities collide(Vec2 v1, Vec2 v2, Vec2 k_hat, double restitution) {
  const double j = normal_impulse(v1 - v2, k_hat, restitution);
  return {v1 - j * k_hat, v2 + j * k_hat};
}

}  // namespace granule
