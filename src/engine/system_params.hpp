// Physical and numerical parameters of one simulated system, in the thesis's units
// (unit mass; lengths in the units of the box; time in the units implied by the velocities).
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include "boundary/obstacle.hpp"
#include "boundary/shear_protocol.hpp"
#include "boundary/surface_set.hpp"
#include "boundary/wall.hpp"
#include "engine/particle_record.hpp"
#include "physics/rest_rule.hpp"
#include "physics/restitution_law.hpp"

namespace granule {

// Rough grains (Lun 1991, the collision model of thesis Fig C.4): spin, a moment of inertia
// I = q m σ²/4, and the tangential restitution β of the contact points' relative velocity,
// optionally capped by Coulomb friction μ (Walton's model: the tangential impulse never exceeds
// μ times the normal one).
struct RoughnessParams {
  bool rough = false;                    // grains carry spin (else smooth: β = −1, no spin)
  double tangential_restitution = -1.0;  // β ∈ [−1, 1]
  double inertia_factor = 0.5;           // q: ½ for uniform disks, 2/5 for uniform spheres
  double friction = std::numeric_limits<double>::infinity();  // μ ≥ 0; +inf: no Coulomb limit
};

// Measured with granule bench (docs/performance.md, "Particles renumbered along the cells").
inline constexpr double kDefaultRenumberEvery = 4.0;
// Renumbering pays only where the particle records outgrow a core's own cache (1 MiB of L2 on the
// machines measured): below twice that it cost 5–7 % and gained nothing (2·10⁴ disks, 1.6·10⁴
// spheres; docs/performance.md, "No renumbering for small systems").
inline constexpr double kRenumberFromRecordBytes = 2.0 * 1024.0 * 1024.0;

// The renumbering cadence of a run that does not set engine.renumber_every: kDefaultRenumberEvery
// from 43,691 disks or 32,769 spheres on, never below.
inline double default_renumber_every(int dimension, std::int64_t particles) {
  const double record_bytes = dimension == 3 ? sizeof(ParticleRecord<3>) : sizeof(ParticleRecord<2>);
  return static_cast<double>(particles) * record_bytes > kRenumberFromRecordBytes ? kDefaultRenumberEvery : 0.0;
}

struct SystemParams {
  std::int64_t particles = 0;
  // σ of a monodisperse system; the largest diameter of a polydisperse one (whose own diameters
  // and masses travel with its ParticleState): the cell grid is sized by it.
  double diameter = 0.0;
  double length_x = 1.0;        // L_x (flow direction under shear)
  double length_y = 1.0;        // L_y (gradient direction)
  double restitution = 1.0;     // ẽ ∈ (0, 1], thesis eq (1.2)
  // U₀: the steady Lees–Edwards image velocity (0 for a periodic box).  With a shear history the
  // image velocity U(t) follows ShearProtocol(shear_velocity, shear_history) in production
  // (image_protocol); between walls the history is the walls' (WallParams::along) and U₀ = 0.
  double shear_velocity = 0.0;
  // TC model (Luding & McNamara 1998): a collision is elastic if either partner collided less
  // than tc_duration ago.  0 switches it off.
  double tc_duration = 0.0;
  // How ẽ (and each wall's e_w) depends on the impact speed: constant (the thesis), elastic below a
  // threshold, or viscoelastic (physics/restitution_law.hpp).
  RestitutionLaw restitution_law;
  ShearHistory shear_history;
  int dimension = 2;            // d: disks (2) or spheres (3)
  double length_z = 1.0;        // L_z (vorticity direction, 3D only)
  // Per axis (x, y, z): flat walls at both ends (0 and L) instead of periodic images; y walls
  // exclude Lees–Edwards images (a wall-driven flow moves the walls instead).
  std::array<bool, 3> walls{};
  std::array<WallParams, 6> wall;  // per face 2·axis + side (0: at 0, 1: at L)
  std::array<double, 3> gravity{};  // uniform acceleration g (parabolic flights)
  // Fixed disks or spheres the grains bounce off (none under Lees–Edwards images).
  std::vector<Obstacle> obstacles;
  RoughnessParams roughness;
  // Grains at rest on static supports (physics/rest_rule.hpp), in production only: the elastic
  // pre-run puts no grain at rest.
  RestParams rest;
  // Events per particle between renumberings of the engine's particles along its cells (0: never;
  // Simulation::renumber).  A matter of speed only: the trajectory is the same for any value.
  // Runs and benchmarks that leave it unset take default_renumber_every().
  double renumber_every = kDefaultRenumberEvery;

  bool has_walls() const { return walls[0] || walls[1] || walls[2]; }
  // The surfaces a grain can hit (boundary/surface_set.hpp).
  SurfaceSet surfaces() const { return {walls, wall, obstacles, rest.on()}; }
  // The surfaces' parameters of `production` (restitutions, the walls' drives), whose surfaces
  // stand where these do.
  void set_surface_parameters(const SystemParams& production) {
    wall = production.wall;
    obstacles = production.obstacles;
  }
  bool has_gravity() const { return gravity[0] != 0.0 || gravity[1] != 0.0 || gravity[2] != 0.0; }
};

// The velocity U(t) of the Lees–Edwards images above the box: none in a walled box, whose walls
// carry a shear themselves (WallParams::along holds their share of the same history).
inline ShearProtocol image_protocol(const SystemParams& p) {
  return p.has_walls() ? ShearProtocol() : ShearProtocol(p.shear_velocity, p.shear_history);
}

// The parameters of the thesis's elastic pre-run (§1.4.2): every collision elastic and smooth, with
// grains, with walls and with obstacles (spins are kept but not exchanged; moving smooth walls do no work).
// Simulation::start_production switches the production values on.
inline SystemParams elastic_prerun(SystemParams params) {
  params.restitution = 1.0;
  params.restitution_law = {};
  params.roughness.tangential_restitution = -1.0;
  for (WallParams& wall : params.wall) {
    wall.restitution = 1.0;
    wall.tangential_restitution = -1.0;
  }
  for (Obstacle& obstacle : params.obstacles) {
    obstacle.restitution = 1.0;
    obstacle.tangential_restitution = -1.0;
  }
  return params;
}

// Entries first .. first + count - 1 of a per-particle array, or nothing when it is empty (an
// optional array: the diameters of a monodisperse system, the spins of smooth grains).
inline std::vector<double> entries_of(const std::vector<double>& all, std::size_t first, std::size_t count) {
  if (all.empty()) return {};
  const auto begin = all.begin() + static_cast<std::ptrdiff_t>(first);
  return std::vector<double>(begin, begin + static_cast<std::ptrdiff_t>(count));
}

// Positions and velocities in the lab frame, one entry per particle: the exchange format between
// the engine, initial states, files and analyses (which take the dimension at run time).
// z and vz are empty in 2D; diameter and mass are empty for a monodisperse system (all σ =
// SystemParams::diameter, unit mass); the angular velocities are empty for smooth grains, and a
// disk spins about z only (wz), a sphere about any axis (wx, wy, wz).
struct ParticleState {
  int dimension = 2;
  std::vector<double> x, y, z, vx, vy, vz;
  std::vector<double> diameter, mass;
  std::vector<double> wx, wy, wz;
  std::size_t size() const { return x.size(); }
  bool polydisperse() const { return !diameter.empty(); }
  bool rough() const { return !wz.empty(); }
  // Components of the angular velocity: 1 for disks (ω_z), 3 for spheres.
  int spin_components() const { return dimension == 3 ? 3 : 1; }
  // Component k of the angular velocity: ω_z for disks; ω_x, ω_y, ω_z for spheres.
  std::vector<double>& spin(int k) { return dimension == 2 || k == 2 ? wz : (k == 0 ? wx : wy); }
  const std::vector<double>& spin(int k) const { return dimension == 2 || k == 2 ? wz : (k == 0 ? wx : wy); }
  // Give every particle a zero angular velocity (the state of rough grains that have not spun yet).
  void make_rough() {
    for (int k = 0; k < spin_components(); ++k) spin(k).assign(size(), 0.0);
  }
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
    if (rough()) {
      for (int k = 0; k < spin_components(); ++k) spin(k).resize(n);
    }
  }
  // Particles first .. first + count - 1 (a block of a large state written piece by piece).
  ParticleState slice(std::size_t first, std::size_t count) const {
    const auto part = [&](const std::vector<double>& all) { return entries_of(all, first, count); };
    return ParticleState{dimension,     part(x),    part(y),    part(z),    part(vx), part(vy),
                         part(vz),      part(diameter), part(mass), part(wx), part(wy), part(wz)};
  }
  std::vector<double>& position(int axis) { return axis == 0 ? x : (axis == 1 ? y : z); }
  const std::vector<double>& position(int axis) const { return axis == 0 ? x : (axis == 1 ? y : z); }
  std::vector<double>& velocity(int axis) { return axis == 0 ? vx : (axis == 1 ? vy : vz); }
  const std::vector<double>& velocity(int axis) const { return axis == 0 ? vx : (axis == 1 ? vy : vz); }
  double diameter_of(std::size_t i, double monodisperse) const { return diameter.empty() ? monodisperse : diameter[i]; }
  double mass_of(std::size_t i) const { return mass.empty() ? 1.0 : mass[i]; }
  // The bytes its arrays hold: what another copy of it allocates.
  std::size_t array_bytes() const {
    std::size_t values = 0;
    for (const std::vector<double>* column : {&x, &y, &z, &vx, &vy, &vz, &diameter, &mass, &wx, &wy, &wz}) values += column->size();
    return values * sizeof(double);
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
