// What measuring code sees of the dynamics: a record per collision, delivered as it happens.
// The engine knows observers only through this interface (thesis quantities such as the
// collisional stress (1.6), impact parameters and free paths are built from these records).
#pragma once

#include <cstdint>

#include "boundary/surface_id.hpp"
#include "geometry/vec.hpp"

namespace granule {

// d = 2 (disks) or 3 (spheres); positions are lab positions, the shear (images) acts along x
// across the y boundaries in both.
template <int D>
struct CollisionRecord {
  double time = 0.0;             // absolute simulation time of contact
  std::int32_t first = 0;        // disk "1" of thesis Fig 1.3
  std::int32_t second = 0;       // disk "2"
  Vec<D> first_position;           // lab position of disk 1 at contact (inside the box)
  Vec<D> contact_point;            // lab position of the contact point, mapped into the box
  Vec<D> contact_normal;           // k̂: unit vector from disk 1 to (the image of) disk 2
  Vec<D> first_velocity_before;    // lab velocity of disk 1 before the collision
  Vec<D> second_velocity_before;   // lab velocity of disk 2 before the collision (its own)
  Vec<D> relative_velocity;        // v21 = v1 − v2 before the collision (image-shifted)
  Vec<D> first_velocity_after;     // lab velocity of disk 1 after the collision
  Vec<D> second_velocity_after;    // lab velocity of disk 2 after the collision (its own, not its image's)
  double impulse = 0.0;          // J·k̂ = (1 + e)/2 (v21·k̂) > 0, momentum given to disk 2
                                 // ((1 + e) μ (v21·k̂) for masses m1, m2)
  double restitution = 1.0;      // the e actually applied (1 inside the TC model's window)
  double contact_distance = 0.0; // σ_ij = (σ1 + σ2)/2 (σ when monodisperse)
  double first_mass = 1.0;       // m1, m2 (1 unless the run is polydisperse)
  double second_mass = 1.0;
  int image_y = 0;               // which vertical image of disk 2 was hit (−1, 0, +1): it moves
                                 // at v_x + image_y U relative to disk 2 itself (§1.4.2)
  double image_velocity_x = 0.0; // that image's velocity relative to disk 2: image_y U at contact
  // The tangential part of the momentum given to disk 2 (rough grains only, zero for smooth ones:
  // the whole impulse is impulse·k̂ + tangential_impulse), and the change of the pair's total
  // kinetic energy, translational plus rotational (≤ 0).
  Vec<D> tangential_impulse;
  double energy_change = 0.0;
};

// A grain hitting a surface of infinite mass (boundary/surface_id.hpp: the wall at a face of the
// box, or a fixed obstacle): the surface takes the momentum `impulse_on_surface` — summed over a
// time, a wall's stress or an obstacle's drag and lift — and gives the grain the energy
// `energy_change` (> 0 when a moving or rough wall heats the gas).
template <int D>
struct SurfaceHitRecord {
  double time = 0.0;
  std::int32_t particle = 0;
  SurfaceId surface;
  Vec<D> position;                // lab position of the grain's centre at contact
  Vec<D> normal;                  // unit vector from the grain's centre into the surface
  Vec<D> velocity_before;
  Vec<D> velocity_after;
  Vec<D> impulse_on_surface;      // m (v_before − v_after)
  double energy_change = 0.0;     // translational plus rotational, given to the grain
  double restitution = 1.0;       // the restitution applied (1 inside the TC model's window)
  double mass = 1.0;
  // The hit put the grain at rest (physics/rest_rule.hpp): velocity_after and its spin are zero,
  // the surface took all its momentum.
  bool comes_to_rest = false;
};

// A grain that comes to rest on static supports, or is woken and moves again
// (physics/rest_rule.hpp): while at rest its weight bears on the supports (observers/wall_stress.hpp
// passes it to the floor).
template <int D>
struct RestRecord {
  double time = 0.0;
  std::int32_t particle = 0;
  Vec<D> position;
  double mass = 1.0;
  bool at_rest = false;  // true: came to rest; false: woken
};

// A disk leaving through the top or bottom of a Lees–Edwards box re-enters from the image on the
// other side with v_x changed by ∓U (thesis §1.4.2): the only place where the boundary changes
// the total momentum and, with cross-boundary collisions, the kinetic energy.
struct BoundaryCrossingRecord {
  double time = 0.0;
  std::int32_t particle = 0;
  int direction = 0;            // +1 out through the top, −1 out through the bottom
  double velocity_x_before = 0.0;
  double velocity_x_after = 0.0;
};

template <int D>
class EventObserver {
 public:
  virtual ~EventObserver() = default;
  virtual void on_collision(const CollisionRecord<D>& record) = 0;
  virtual void on_boundary_crossing(const BoundaryCrossingRecord&) {}
  virtual void on_surface_hit(const SurfaceHitRecord<D>&) {}
  virtual void on_rest_change(const RestRecord<D>&) {}
};

}  // namespace granule
