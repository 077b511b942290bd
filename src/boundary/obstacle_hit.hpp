// When a grain first touches a fixed obstacle, and whether it touches one now: the one test the
// search and the hit's execution share (boundary/box_boundaries.hpp: earliest_surface_hit, contact).
//
// Relative to a fixed point a grain's flight is its own: a straight line, or a parabola under
// gravity.  On a line the hit is the root of a quadratic, computed exactly as a pair's
// (physics/collision_time.hpp).  On a parabola |d(τ)|² − S² is a quartic; instead of its roots the
// search advances conservatively on the gap G(τ) = |d(τ)| − S, whose second derivative
// G'' = d̂·g + (|v|² − (d̂·v)²)/|d| ≥ −|g| (the distance to a point is convex along a line): G stays
// above the parabola G + G' s − ½|g| s², and nothing is touched before that parabola's positive
// root.  Each step moves there: from below a simple root this converges like Newton's method,
// never past it.  A hit is a gap within `tolerance` while approaching (the pairs' grazing rule,
// `approaching`).  Round-off guards as for a moving wall (boundary/moving_wall_hit.hpp): every step
// moves the absolute time on by at least one ulp; the search ends at `horizon` (the grain leaves
// the cell whose obstacles were searched) or after kMostObstacleSteps steps, where it returns the
// time it stands at, and the execution there finds the grain not touching and predicts again.
#pragma once

#include <cmath>
#include <limits>
#include <type_traits>

#include "boundary/clock_step.hpp"
#include "geometry/vec.hpp"
#include "motion/ballistic.hpp"
#include "physics/collision_time.hpp"

namespace granule {

// Whether a grain at offset `d` from an obstacle's centre (d = grain − centre), moving at `v`,
// touches it within `tolerance` (contact distance `contact`) while moving into it.
template <int D>
inline bool touches_obstacle(const Vec<D>& d, const Vec<D>& v, double contact, double tolerance) {
  return norm(d) - contact <= tolerance && approaching(d, v);
}

inline constexpr int kMostObstacleSteps = 100000;

// The delay τ ∈ [0, horizon) until a grain on `flight` (the motion policy), at offset `d` from an
// obstacle's centre and moving at `v` now (absolute time `now`), touches it at contact distance
// `contact`; +inf if it does not before `horizon`.
template <int D, typename Flight>
double obstacle_hit(const Flight& flight, const Vec<D>& d, const Vec<D>& v, double contact, double now, double horizon,
                    double tolerance) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  double field = 0.0;
  for (int a = 0; a < D; ++a) field += 4.0 * flight.half_acceleration(a) * flight.half_acceleration(a);
  field = std::sqrt(field);  // |g|
  if (std::is_same_v<Flight, Ballistic<D>> || field == 0.0) {
    const double t = collision_time<D>(d, v, contact);  // symmetric in the sign of (d, v)
    return t < horizon ? t : kInf;
  } else {
    double tau = 0.0;
    for (int step = 0; step < kMostObstacleSteps; ++step) {
      Vec<D> at;
      Vec<D> velocity;
      for (int a = 0; a < D; ++a) {
        at[a] = flight.coordinate_at(a, d[a], v[a], tau);
        velocity[a] = flight.velocity_at(a, v[a], tau);
      }
      const double distance = norm(at);
      const double gap = distance - contact;
      if (gap <= tolerance && approaching(at, velocity)) return tau;
      const double rate = distance > 0.0 ? dot(at, velocity) / distance : 0.0;
      const double ahead = std::max(gap, 0.0);
      const double s = (rate + std::sqrt(rate * rate + 2.0 * field * ahead)) / field;
      const double next = clock_moves_on(now, tau, tau + s);
      if (!(next < horizon)) return kInf;
      tau = next;
    }
    return tau;
  }
}

}  // namespace granule
