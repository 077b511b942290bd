// Time until two free-flying disks or spheres touch, robust against round-off (Bannerman et al. 2014).
#pragma once

#include <cmath>
#include <limits>

#include "geometry/vec.hpp"

namespace granule {

inline constexpr double kNever = std::numeric_limits<double>::infinity();

// r = r2 − r1 and v = v2 − v1 at the current time; sigma is the contact distance.
// Returns the delay τ ≥ 0 until |r + vτ| = σ on approach, or kNever.
//  * receding or tangential pairs (r·v ≥ 0) never collide, even if round-off left them
//    overlapping: they are separating already;
//  * an approaching pair that touches or overlaps (|r| ≤ σ) collides now (τ = 0);
//  * otherwise the smaller root of |r + vτ|² = σ² in the cancellation-free form
//    τ = c / (−b + √(b² − v²c)), with b = r·v < 0 and c = r² − σ² > 0.
template <int D>
inline double collision_time(Vec<D> r, Vec<D> v, double sigma) {
  const double b = dot(r, v);
  if (b >= 0.0) return kNever;
  const double c = norm2(r) - sigma * sigma;
  if (c <= 0.0) return 0.0;
  const double disc = b * b - norm2(v) * c;
  if (disc < 0.0) return kNever;
  return c / (-b + std::sqrt(disc));
}

}  // namespace granule
