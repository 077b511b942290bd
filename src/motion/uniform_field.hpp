// Flight in a uniform field g (gravity): parabolic flights, thesis Appendix A.1's "parabolic
// flights".  The base state (r, v) at the engine's clock base gives, a delay t later,
// r + (v + ½ g t) t and v + g t.  Two grains in the same field move in straight lines relative to
// each other, so pair collision times are those of Ballistic; only crossings and wall hits meet
// the parabola (physics/crossing_time.hpp).
#pragma once

#include <array>

#include "geometry/vec.hpp"
#include "motion/ballistic.hpp"
#include "physics/crossing_time.hpp"

namespace granule {

template <int D>
struct UniformField {
  Vec<D> g;  // the acceleration

  double coordinate_at(int axis, double r, double v, double t) const { return r + (v + 0.5 * g[axis] * t) * t; }
  double velocity_at(int axis, double v, double t) const { return v + t * g[axis]; }
  // The base velocity of the flight that has velocity v at t.
  double base_velocity(int axis, double v, double t) const { return v - g[axis] * t; }
  void advance_base(int axis, double& r, double& v, double t) const {
    r += (v + 0.5 * g[axis] * t) * t;
    v += g[axis] * t;
  }
  double half_acceleration(int axis) const { return 0.5 * g[axis]; }
  // As Ballistic::time_to_plane and exit_from_slab, along the parabola (which may turn back
  // towards the other face: both are tried, the upper first on a tie).
  double time_to_plane(int axis, double position, double velocity, double plane, int direction) const {
    const double half_g = 0.5 * g[axis];
    return direction > 0 ? first_exit_time(half_g, velocity, position - plane)
                         : first_exit_time(-half_g, -velocity, plane - position);
  }
  SlabExit exit_from_slab(int axis, double position, double velocity, double lower, double upper, bool through_lower,
                          bool through_upper) const {
    SlabExit exit{kNever, 1};
    if (through_upper) exit.delay = time_to_plane(axis, position, velocity, upper, 1);
    if (through_lower) {
      if (const double t = time_to_plane(axis, position, velocity, lower, -1); t < exit.delay) exit = {t, -1};
    }
    return exit;
  }
};

}  // namespace granule
