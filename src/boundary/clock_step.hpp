// The one round-off guard of the conservative searches (boundary/moving_wall_hit.hpp,
// boundary/obstacle_hit.hpp): every step must move the absolute clock on, or a search that stands
// on a root it cannot resolve would stand still.
#pragma once

#include <cmath>
#include <limits>

namespace granule {

// The delay ≥ `next` whose absolute time now + delay lies after now + tau.  A step below the
// clock's ulp jumps to the clock's next representable instant at once: stepping the delay by its
// own ulps would take ulp(now)/ulp(delay) steps, millions late in a run.
inline double clock_moves_on(double now, double tau, double next) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const double t = now + tau;
  if (now + next > t) return next;
  next = std::nextafter(t, kInf) - now;
  while (now + next <= t) next = std::nextafter(next, kInf);
  return next;
}

}  // namespace granule
