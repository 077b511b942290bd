// When a particle leaves an interval whose edge moves relative to it along a parabola: cell
// crossings on the sheared (Lees–Edwards) cell grid, where the sheared abscissa
// ξ(τ) = x − s(t)(y − y_c) of a free particle is quadratic in the delay τ, and crossings and wall
// hits of flights in a uniform field (motion/uniform_field.hpp).
#pragma once

#include <cmath>
#include <utility>

#include "physics/collision_time.hpp"

namespace granule {

// g(τ) = aτ² + bτ + c measures how far a particle is beyond an edge (g > 0: outside).
// Returns the earliest τ ≥ 0 at which g crosses zero upwards (the particle leaves), 0 if it is
// already outside (by round-off) and moving out, or kNever.  A particle a hair outside but
// moving in is not sent back: that would bounce it between two cells forever.
inline double first_exit_time(double a, double b, double c) {
  if (a == 0.0) {
    if (b <= 0.0) return kNever;
    const double tau = -c / b;
    return tau > 0.0 ? tau : 0.0;
  }
  const double disc = b * b - 4.0 * a * c;
  // Always outside / always inside; a < 0 with a double root only touches the edge (a grain at the
  // apex of its flight exactly on a face) and never leaves.
  if (disc < 0.0 || (disc == 0.0 && a < 0.0)) return a > 0.0 ? 0.0 : kNever;
  // Numerically stable roots q/a and c/q.
  const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
  double r1 = q / a;
  double r2 = (q != 0.0) ? c / q : r1;
  if (r1 > r2) std::swap(r1, r2);
  if (a > 0.0) return r2 > 0.0 ? r2 : 0.0;  // upward crossing at the larger root
  // a < 0: the only upward crossing is at the smaller root.  If it is past and g ≥ 0 now (round-off
  // at an edge just crossed), leave now only when moving outwards (g'(0) = b > 0).
  if (r1 >= 0.0) return r1;
  return (r2 >= 0.0 && b > 0.0) ? 0.0 : kNever;
}

}  // namespace granule
