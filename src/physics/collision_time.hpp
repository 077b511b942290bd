// Time until two free-flying disks or spheres touch, robust against round-off (Bannerman et al. 2014).
#pragma once

#include <cmath>
#include <limits>

#include "geometry/vec.hpp"

namespace granule {

inline constexpr double kNever = std::numeric_limits<double>::infinity();
// A pair whose normal velocity is below 10⁻¹⁰ of its relative speed (r·v)² ≤ 10⁻²⁰ r² v² grazes:
// an impulse that small is lost in the round-off of the velocities, so such a pair would collide
// again and again at the same instant (seen: a pair with r·v = −2·10⁻¹⁸ froze the clock).  It is
// treated as tangential, that is as not approaching; the overlap this allows is below 10⁻¹⁰ σ.
inline constexpr double kGrazingCosineSquared = 1e-20;

template <int D>
inline bool approaching(double r_dot_v, const Vec<D>& r, const Vec<D>& v) {
  return r_dot_v < 0.0 && r_dot_v * r_dot_v > kGrazingCosineSquared * norm2(r) * norm2(v);
}
template <int D>
inline bool approaching(const Vec<D>& r, const Vec<D>& v) {
  return approaching(dot(r, v), r, v);
}

// r = r2 − r1 and v = v2 − v1 at the current time; sigma is the contact distance.
// Returns the delay τ ≥ 0 until |r + vτ| = σ on approach, or kNever.
//  * receding or tangential pairs (r·v ≥ 0, or grazing: see approaching()) never collide, even
//    if round-off left them overlapping: they are separating already;
//  * an approaching pair that touches or overlaps (|r| ≤ σ) collides now (τ = 0);
//  * otherwise the smaller root of |r + vτ|² = σ² in the cancellation-free form
//    τ = c / (−b + √(b² − v²c)), with b = r·v < 0 and c = r² − σ² > 0.
template <int D>
inline double collision_time(Vec<D> r, Vec<D> v, double sigma) {
  const double b = dot(r, v);
  if (!approaching(b, r, v)) return kNever;
  const double c = norm2(r) - sigma * sigma;
  if (c <= 0.0) return 0.0;
  const double disc = b * b - norm2(v) * c;
  if (disc < 0.0) return kNever;
  return c / (-b + std::sqrt(disc));
}

}  // namespace granule
