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
  // σ of a monodisperse system; the largest diameter of a polydisperse one (whose own diameters
  // and masses travel with its ParticleState): the cell grid is sized by it.
  double diameter = 0.0;
  double length_x = 1.0;        // L_x (flow direction under shear)
  double length_y = 1.0;        // L_y (gradient direction)
  double restitution = 1.0;     // ẽ ∈ (0, 1], thesis eq (1.2)
  // U₀: the steady Lees–Edwards image velocity (0 for a periodic box).  With a shear history the
  // image velocity U(t) follows ShearProtocol(shear_velocity, shear_history) in production.
  double shear_velocity = 0.0;
  // TC model (Luding & McNamara 1998): a collision is elastic if either partner collided less
  // than tc_duration ago.  0 switches it off.
  double tc_duration = 0.0;
  ShearHistory shear_history;
  int dimension = 2;            // d: disks (2) or spheres (3)
  double length_z = 1.0;        // L_z (vorticity direction, 3D only)
};

// Positions and velocities in the lab frame, one entry per particle: the exchange format between
// the engine, initial states, files and analyses (which take the dimension at run time).
// z and vz are empty in 2D; diameter and mass are empty for a monodisperse system (all σ =
// SystemParams::diameter, unit mass).
struct ParticleState {
  int dimension = 2;
  std::vector<double> x, y, z, vx, vy, vz;
  std::vector<double> diameter, mass;
  std::size_t size() const { return x.size(); }
  bool polydisperse() const { return !diameter.empty(); }
  void resize(std::size_t n) {
    x.resize(n);
    y.resize(n);
    vx.resize(n);
    vy.resize(n);
    if (dimension == 3) {
      z.resize(n);
      vz.resize(n);
    }
    if (polydisperse()) {
      diameter.resize(n);
      mass.resize(n);
    }
  }
  std::vector<double>& position(int axis) { return axis == 0 ? x : (axis == 1 ? y : z); }
  const std::vector<double>& position(int axis) const { return axis == 0 ? x : (axis == 1 ? y : z); }
  std::vector<double>& velocity(int axis) { return axis == 0 ? vx : (axis == 1 ? vy : vz); }
  const std::vector<double>& velocity(int axis) const { return axis == 0 ? vx : (axis == 1 ? vy : vz); }
  double diameter_of(std::size_t i, double monodisperse) const { return diameter.empty() ? monodisperse : diameter[i]; }
  double mass_of(std::size_t i) const { return mass.empty() ? 1.0 : mass[i]; }
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
