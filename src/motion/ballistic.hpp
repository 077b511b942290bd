// Free flight in straight lines, no external field: the motion of the thesis's gas.  A flight is
// stored as its state (r, v) at the engine's clock base; a delay t from there the particle is at
// r + v t (engine/particle_record.hpp, "false positions").
#pragma once

#include <algorithm>

#include "geometry/vec.hpp"
#include "physics/collision_time.hpp"

namespace granule {

// The first exit from a slab between two planes: its delay and the face (+1 upper, −1 lower).
struct SlabExit {
  double delay;
  int direction;
};

template <int D>
struct Ballistic {
  // Coordinate `axis` and its velocity a delay t after the clock base, for the base state (r, v).
  double coordinate_at(int /*axis*/, double r, double v, double t) const { return r + v * t; }
  double velocity_at(int /*axis*/, double v, double /*t*/) const { return v; }
  // The base velocity of a flight that has velocity v at t: v itself, stored as given, so that
  // energy and momentum budgets are those of the collision rule alone.
  double base_velocity(int /*axis*/, double v, double /*t*/) const { return v; }
  // The base state moved a delay t on (a re-base of the clock).
  void advance_base(int /*axis*/, double& r, double& v, double t) const { r += v * t; }
  // ½ g along `axis`: none.
  double half_acceleration(int /*axis*/) const { return 0.0; }
  // The delay until coordinate `axis`, now at `position` with velocity `velocity`, passes `plane`
  // moving in `direction` (+1 upwards, −1 downwards); 0 if it is already past it (by round-off)
  // and moving on; kNever if it never does.  (For a = 0 first_exit_time gives the same bits.)
  double time_to_plane(int /*axis*/, double position, double velocity, double plane, int direction) const {
    if (direction > 0 ? velocity > 0.0 : velocity < 0.0) return std::max(0.0, (plane - position) / velocity);
    return kNever;
  }
  // The delay until coordinate `axis` leaves the slab [lower, upper] through a face it may leave
  // by (`through_lower`, `through_upper`), and the face's direction (+1 upper, −1 lower): only the
  // face it moves towards.
  SlabExit exit_from_slab(int /*axis*/, double position, double velocity, double lower, double upper, bool through_lower,
                          bool through_upper) const {
    if (velocity > 0.0 && through_upper) return {std::max(0.0, (upper - position) / velocity), 1};
    if (velocity < 0.0 && through_lower) return {std::max(0.0, (lower - position) / velocity), -1};
    return {kNever, 1};
  }
};

}  // namespace granule
