// The smooth inelastic binary collision (thesis eq 1.2, Fig 1.3) of disks or spheres, of equal
// unit masses (the thesis) or of masses m1, m2 (polydisperse runs).
#pragma once

#include "geometry/vec.hpp"

namespace granule {

// Scalar impulse J·k̂ transferred to disk 2 by disk 1 along k̂ (thesis Fig 1.3):
// J = (1 + e)/2 (v21·k̂) k̂ with v21 = v1 − v2 and k̂ the unit vector from disk 1 to disk 2.
// Positive when the disks approach.
template <int D>
constexpr double normal_impulse(Vec<D> v21, Vec<D> k_hat, double restitution) {
  return 0.5 * (1.0 + restitution) * dot(v21, k_hat);
}

// The same for masses m1, m2: J = (1 + e) μ (v21·k̂) with the reduced mass μ = m1 m2/(m1 + m2)
// (unit masses give the form above, but the form above is kept for them: it is the thesis's
// expression, and its bits are what the golden tier fixes).
template <int D>
constexpr double normal_impulse(Vec<D> v21, Vec<D> k_hat, double restitution, double m1, double m2) {
  return (1.0 + restitution) * (m1 * m2 / (m1 + m2)) * dot(v21, k_hat);
}

template <int D>
struct PostCollisionVelocities {
  Vec<D> v1;
  Vec<D> v2;
};

// Thesis eq (1.2): v1' = v1 − J k̂,  v2' = v2 + J k̂.  Momentum is conserved exactly in exact
// arithmetic; the kinetic energy falls by (1 − e²)/4 (v21·k̂)².
template <int D>
constexpr PostCollisionVelocities<D> collide(Vec<D> v1, Vec<D> v2, Vec<D> k_hat, double restitution) {
  const double j = normal_impulse(v1 - v2, k_hat, restitution);
  return {v1 - j * k_hat, v2 + j * k_hat};
}

// Masses m1, m2: v1' = v1 − (J/m1) k̂, v2' = v2 + (J/m2) k̂; the kinetic energy falls by
// (1 − e²) μ/2 (v21·k̂)².
template <int D>
constexpr PostCollisionVelocities<D> collide(Vec<D> v1, Vec<D> v2, Vec<D> k_hat, double restitution, double m1,
                                             double m2) {
  const double j = normal_impulse(v1 - v2, k_hat, restitution, m1, m2);
  return {v1 - (j / m1) * k_hat, v2 + (j / m2) * k_hat};
}

}  // namespace granule
