// Physical and numerical parameters of one simulated system, in the thesis's units
// (unit mass; lengths in the units of the box; time in the units implied by the velocities).
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "boundary/shear_protocol.hpp"

namespace granule {

struct SystemParams {
  std::int64_t particles = 0;
  double diameter = 0.0;        // σ
  double length_x = 1.0;        // L_x
  double length_y = 1.0;        // L_y
  double restitution = 1.0;     // ẽ ∈ (0, 1], thesis eq (1.2)
  // U₀: the steady Lees–Edwards image velocity (0 for a periodic box).  With a shear history the
  // image velocity U(t) follows ShearProtocol(shear_velocity, shear_history) in production.
  double shear_velocity = 0.0;
  // TC model (Luding & McNamara 1998): a collision is elastic if either partner collided less
  // than tc_duration ago.  0 switches it off.
  double tc_duration = 0.0;
  ShearHistory shear_history;
};

// Positions and velocities in the lab frame, one entry per particle.
struct ParticleState {
  std::vector<double> x, y, vx, vy;
  std::size_t size() const { return x.size(); }
  void resize(std::size_t n) {
    x.resize(n);
    y.resize(n);
    vx.resize(n);
    vy.resize(n);
  }
};

// Everything besides positions and velocities that a synchronised engine needs to continue a
// run exactly (stored with every snapshot, read back on restart).
struct ClockState {
  double time = 0.0;                 // absolute simulation time
  double strain_reference = 0.0;     // t_ref − t (≤ 0): when the grid strain was last set
  double strain_at_reference = 0.0;  // the grid strain at t_ref (0 unless U has changed since)
  std::int64_t collisions = 0;       // since the restitution was switched on
  std::int64_t events = 0;
  std::vector<double> last_collision;  // TC model only: time of each disk's last collision − t
  // In production the image velocity follows the shear protocol from `time`; before it (the
  // elastic pre-run) it is held at `held_shear_velocity`, by default the protocol's U(0).
  bool protocol_running = false;
  std::optional<double> held_shear_velocity;
};

}  // namespace granule
