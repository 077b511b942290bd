// An event's outcome as plain data: computed from the state without changing it (the "plan": what
// would happen), then applied by a commit that writes it and predicts again.  A plan reads only
// the records, spins and TC history of the particles it names, the clocks and the boundaries;
// its commit writes those particles' records, spins, histories and cells, and their event slots.
// That split is what a speculative parallel engine needs: plans can be made ahead and checked
// against the collision counters of the particles they read (ARCHITECTURE.md, "The event loop").
#pragma once

#include <cstdint>
#include <optional>

#include "boundary/box_boundaries.hpp"
#include "geometry/vec.hpp"
#include "physics/collision_law.hpp"

namespace granule {

// A particle's flight as its record holds it: position and velocity at the clock base.
template <int D>
struct FlightState {
  Vec<D> r;
  Vec<D> v;
};

// Entering the box from the image on the other side of a face: the new flight, and across a
// Lees–Edwards face (thesis §1.4.2) the change of v_x that observers are told of.
template <int D>
struct ImageEntry {
  FlightState<D> flight;
  bool moving_image = false;
  double velocity_x_before = 0.0;
  double velocity_x_after = 0.0;
};

// A cell crossing: the cell entered and, out through a face of the box, the entry from the image.
// Small and built whole: most events of a dilute gas are crossings.
template <int D>
struct CrossingPlan {
  std::int32_t particle;
  int axis;
  int direction;
  std::int32_t new_cell;
  std::optional<ImageEntry<D>> entry;
};

// A collision of `first` and `second`: unless the pair has stopped approaching (re-validated,
// Bannerman et al. 2014), both new flights and what observers are told.
template <int D>
struct CollisionPlan {
  std::int32_t first = -1;
  std::int32_t second = -1;
  bool approaching = false;
  FlightState<D> first_flight;
  FlightState<D> second_flight;
  ContactSide<D> first_side;   // after the contact (the second's velocity as its image's)
  ContactSide<D> second_side;
  ContactOutcome<D> outcome;
  typename BoxBoundaries<D>::PartnerImage image;  // of the second, as the first meets it
  Vec<D> first_position;
  Vec<D> k_hat;
  Vec<D> first_velocity_before;
  Vec<D> second_velocity_before;  // its image's
  double energy_before = 0.0;     // both sides, translational plus rotational
};

// A grain hitting a surface of infinite mass (a wall or an obstacle), unless it no longer moves into
// it: its new flight and spin, and what observers are told.
template <int D>
struct SurfaceHit {
  std::int32_t particle = -1;
  bool approaching = false;
  FlightState<D> flight{};
  ContactSide<D> side{};  // the grain after the hit
  ContactOutcome<D> outcome{};
  Vec<D> velocity_before{};
  double energy_before = 0.0;
};

// A hit of surface `surface` of the boundaries (none: the grain no longer touches it), which may put
// the grain at rest; or, struck hard enough, the grain at rest it hits moves again and the two
// collide; or a grain at rest wedging the grain against the surface moves again
// (physics/rest_rule.hpp).
template <int D>
struct SurfaceHitPlan {
  SurfaceId surface{};
  Vec<D> normal{};  // from the grain into the surface
  SurfaceHit<D> hit{};
  bool comes_to_rest = false;
  // The grain at rest woken (−1: none): the struck one, which the grain then collides with; or,
  // after the hit, one the grain would bounce into at once.
  std::int32_t wakes = -1;
  bool wakes_struck = false;
};

}  // namespace granule
