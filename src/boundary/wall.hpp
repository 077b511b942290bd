// A flat wall at one end of an axis (thesis Appendix A.1, "reflective boundaries"): a grain touches
// it when its centre is one radius away.  The wall moves tangentially at `velocity` (a wall-driven
// Couette flow moves the y walls at ±U/2 along x), optionally following a drive in time (`along`),
// and may move normal to itself (`motion`, boundary/wall_motion.hpp: a vibrated floor).  It reflects
// the grain's velocity relative to it at the contact point: normal part × −restitution, tangential
// part × −tangential_restitution (physics/collision_law.hpp, the same law as between grains).
#pragma once

#include <array>
#include <vector>

#include "boundary/shear_protocol.hpp"

namespace granule {

// A point of a wall's schedule: its displacement into the box h at production time t.
struct WallPositionPoint {
  double time = 0.0;
  double displacement = 0.0;
};

// The shape of a wall's vibration h(t) between 0 and 2A over a period 1/f, each starting at the face:
// a sine, h = A (1 − cos 2πft) (peak acceleration (2πf)² A); a triangle, h rising at 4Af for half a
// period and falling back at 4Af (the floor's velocity a square wave: a sawtooth-like drive whose
// every hit is a line against a parabola); or bi-parabolic, h made of parabolic arcs of acceleration
// ±32Af², so that the floor's velocity is a triangle wave of peak 8Af (the constant-acceleration
// drive of vibrated-bed simulations, whose peak acceleration Γ g = 32Af² is the sine's over ≈ 1.23).
enum class VibrationShape { kSine, kTriangle, kBiparabolic };

// How a wall moves normal to itself over the production time t (it rests at the box face, h = 0,
// during the elastic pre-run): its displacement into the box h(t) ≥ 0 is the sum of
//  • a vibration of amplitude A and frequency f, h between 0 and 2A in the shape `shape`, and
//  • a schedule of points (t, h), h joined linearly between them (the wall's velocity constant on
//    each piece), 0 before the first point and held after the last.
struct WallMotion {
  double amplitude = 0.0;  // A ≥ 0
  double frequency = 0.0;  // f > 0 when A > 0
  std::vector<WallPositionPoint> schedule;  // times increasing, the first h = 0
  VibrationShape shape = VibrationShape::kSine;

  bool moves() const { return amplitude > 0.0 || !schedule.empty(); }
  // The wall's velocity into the box, dh/dt, as a protocol of the Lees–Edwards drives of Chapter 4
  // (an oscillation; a schedule of velocity steps): its closed-form integral is h, its breaks and
  // slope bound bound h'' for the hit-time search (boundary/moving_wall_hit.hpp).
  ShearProtocol velocity() const;
  // The largest h it ever reaches.
  double reach() const;
};

struct WallParams {
  double restitution = 1.0;              // e_w ∈ (0, 1]
  double tangential_restitution = -1.0;  // β_w ∈ [−1, 1]: −1 a smooth wall, +1 a perfectly rough one
  std::array<double, 3> velocity{};      // tangential, steady: its component along the wall's axis is 0
  // In production the component of the velocity along `along_axis` follows this history with
  // `velocity[along_axis]` as its steady value (ShearProtocol): a wall-driven shear ramped,
  // scheduled or oscillated as the Lees–Edwards images of Chapter 4 are.  Empty: steady.
  ShearHistory along{};
  int along_axis = 0;
  WallMotion motion{};  // normal to the wall
};

}  // namespace granule
