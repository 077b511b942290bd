// When a grain first touches a wall that moves normal to itself (boundary/wall.hpp, WallMotion):
// the root of the gap between the grain's flight (a line, or a parabola under gravity) and the
// wall's contact plane, whose displacement h(t) is a sinusoid or a piecewise-linear schedule.
//
// The gap G(τ) = ι (x(τ) − p) − h(t + τ) (ι = +1 for the wall at 0, −1 for the wall at L; p the
// contact plane at rest) is not a polynomial, so the search advances conservatively: between
// breaks of the wall's velocity |G''| ≤ |g| + max |h''| = M, so G stays above the parabola
// G + G' s − ½ M s², and nothing is touched before that parabola's positive root.  Each step moves
// there: from below a simple root this converges like Newton's method (quadratically), never
// past the root; at a break (a kink of a schedule) it stops and starts afresh.  A hit is a gap
// within `tolerance` closing (G' < 0), the same test the wall hit's execution makes, so an event
// is never predicted that its execution then refuses at the same instant.  Round-off guards: a
// grain beyond the wall's farthest reach jumps first to the time it enters it (the closed-form
// root of a static plane); every step moves the absolute time on by at least one ulp; a search
// that takes kMostSteps steps returns where it stands, and the event there finds the grain not
// touching and predicts again (a re-check, never a hit at a distance).
#pragma once

#include <cmath>
#include <limits>

#include "boundary/clock_step.hpp"
#include "boundary/shear_protocol.hpp"

namespace granule {

struct MovingPlane {
  double rest = 0.0;    // the contact plane at h = 0 (a radius inside the face)
  int inward = 1;       // +1: the wall at 0 moves up the axis; −1: the wall at L moves down
  double reach = 0.0;   // the largest displacement h ever
  const ShearProtocol* velocity = nullptr;  // dh/dt
};

// The gap G and its rate G' of a grain at coordinate x moving at v along the wall's axis, at
// production time t: the one formula the search and the wall hit's execution share.
inline double moving_gap(const MovingPlane& plane, double x, double t) {
  return plane.inward * (x - plane.rest) - plane.velocity->integral(0.0, t);
}
inline double moving_gap_rate(const MovingPlane& plane, double v, double t) {
  return plane.inward * v - plane.velocity->velocity(t);
}

inline constexpr int kMostMovingWallSteps = 100000;

// The delay τ ∈ [0, horizon) after the production time `now` at which a grain on `flight` (the
// motion policy, motion/motion.hpp) along `axis`, now at `position` with `velocity`, touches the
// moving plane while closing on it; +inf when it does not before `horizon`.  Never inlined: the
// prediction it is called from is flattened into the neighbour scan (the hot path), which this
// rare loop would only crowd.
template <typename Flight>
[[gnu::noinline]] double moving_wall_hit(const Flight& flight, int axis, double position, double velocity, const MovingPlane& plane,
                       double now, double horizon, double tolerance) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const ShearProtocol& wall = *plane.velocity;
  double tau = 0.0;
  const double farthest = plane.rest + plane.inward * plane.reach;
  if (plane.inward * (position - farthest) > 0.0) {  // out of the wall's reach: first get there
    tau = flight.time_to_plane(axis, position, velocity, farthest, -plane.inward);
    if (!(tau < horizon)) return kInf;
  }
  const double field = 2.0 * std::abs(flight.half_acceleration(axis));
  for (int step = 0; step < kMostMovingWallSteps; ++step) {
    const double t = now + tau;
    const double gap = moving_gap(plane, flight.coordinate_at(axis, position, velocity, tau), t);
    const double rate = moving_gap_rate(plane, flight.velocity_at(axis, velocity, tau), t);
    if (gap <= tolerance && rate < 0.0) return tau;
    const double bound = field + wall.slope_bound(t);
    const double ahead = std::max(gap, 0.0);
    const double s = bound > 0.0 ? (rate + std::sqrt(rate * rate + 2.0 * bound * ahead)) / bound
                                 : (rate < 0.0 ? ahead / -rate : kInf);
    const double next_break = wall.next_break(t);
    double next = tau + s;
    if (now + next >= next_break) {
      // The bound holds only up to the break: stop on it (its first representable instant).
      next = next_break - now;
      while (now + next < next_break) next = std::nextafter(next, kInf);
    }
    next = clock_moves_on(now, tau, next);
    if (!(next < horizon)) return kInf;
    tau = next;
  }
  return tau;
}

}  // namespace granule
