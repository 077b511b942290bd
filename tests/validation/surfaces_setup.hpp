// Shared set-up of the validation tests of walls, gravity and spin: a box with walls on chosen
// axes, grains on a simple lattice kept a radius away from every wall (independent of the
// initial-state code, which these tests must not depend on), Maxwellian velocities and spins.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "cells/cell_grid.hpp"
#include "engine/simulation.hpp"

namespace granule {

// A box L_x × L_y (× L_z) with n grains of diameter sigma on a lattice of `per_axis` sites per axis.
template <int D>
SystemParams surfaces_system(std::array<int, D> per_axis, std::array<double, D> box, double sigma, double e) {
  SystemParams p;
  p.dimension = D;
  p.particles = 1;
  for (int a = 0; a < D; ++a) p.particles *= per_axis[static_cast<std::size_t>(a)];
  p.diameter = sigma;
  p.restitution = e;
  p.length_x = box[0];
  p.length_y = box[1];
  if constexpr (D == 3) p.length_z = box[2];
  return p;
}

// Lattice sites at (k + ½) L/n along each axis (a radius inside any wall when L/n ≥ σ);
// velocities N(0, T/m) with zero total momentum; spins N(0, T/I) when the grains are rough.
template <int D>
ParticleState lattice_gas(const SystemParams& p, std::array<int, D> per_axis, double temperature, std::uint64_t seed) {
  ParticleState s;
  s.dimension = D;
  s.resize(static_cast<std::size_t>(p.particles));
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal;
  const std::array<double, 3> box{p.length_x, p.length_y, p.length_z};
  for (std::size_t i = 0; i < s.size(); ++i) {
    std::size_t rest = i;
    for (int a = 0; a < D; ++a) {
      const auto n = static_cast<std::size_t>(per_axis[static_cast<std::size_t>(a)]);
      const double spacing = box[static_cast<std::size_t>(a)] / static_cast<double>(n);
      s.position(a)[i] = (static_cast<double>(rest % n) + 0.5) * spacing;
      rest /= n;
      s.velocity(a)[i] = std::sqrt(temperature) * normal(rng);
    }
  }
  for (int a = 0; a < D; ++a) {
    double mean = 0.0;
    for (double v : s.velocity(a)) mean += v;
    mean /= static_cast<double>(s.size());
    for (double& v : s.velocity(a)) v -= mean;
  }
  if (p.roughness.rough) {
    s.make_rough();
    const double inertia = p.roughness.inertia_factor * 0.25 * p.diameter * p.diameter;
    for (int k = 0; k < s.spin_components(); ++k) {
      for (double& w : s.spin(k)) w = std::sqrt(temperature / inertia) * normal(rng);
    }
  }
  return s;
}

template <int D>
CellGrid surfaces_grid(const SystemParams& p, double particles_per_cell = 1.0) {
  CellGridRequest request;
  request.length_x = p.length_x;
  request.length_y = p.length_y;
  request.length_z = p.length_z;
  request.diameter = p.diameter;
  request.particles = p.particles;
  request.sheared = p.shear_velocity != 0.0;
  request.particles_per_cell = particles_per_cell;
  request.dimension = D;
  const CellGridChoice choice = choose_cell_grid(request);
  EXPECT_TRUE(choice.grid.has_value()) << choice.error;
  return *choice.grid;
}

// Walls on `axis` at rest, with normal and tangential restitutions e_w, β_w.
inline void add_walls(SystemParams& p, int axis, double e_w, double beta_w) {
  p.walls[static_cast<std::size_t>(axis)] = true;
  for (int side = 0; side < 2; ++side) {
    p.wall[static_cast<std::size_t>(2 * axis + side)].restitution = e_w;
    p.wall[static_cast<std::size_t>(2 * axis + side)].tangential_restitution = beta_w;
  }
}

inline void make_rough(SystemParams& p, double beta, double inertia_factor, double friction = INFINITY) {
  p.roughness.rough = true;
  p.roughness.tangential_restitution = beta;
  p.roughness.inertia_factor = inertia_factor;
  p.roughness.friction = friction;
}

// Σ ½ m v² + ½ I ω² − m g·r (unit masses, I = q m σ²/4).
inline double total_energy(const SystemParams& p, const ParticleState& s) {
  const double inertia = p.roughness.inertia_factor * 0.25 * p.diameter * p.diameter;
  double energy = 0.0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    for (int a = 0; a < s.dimension; ++a) {
      energy += 0.5 * s.velocity(a)[i] * s.velocity(a)[i] - p.gravity[static_cast<std::size_t>(a)] * s.position(a)[i];
    }
    if (s.rough()) {
      for (int k = 0; k < s.spin_components(); ++k) energy += 0.5 * inertia * s.spin(k)[i] * s.spin(k)[i];
    }
  }
  return energy;
}

// What the walls and collisions of a run did: every wall hit, the impulses the walls took, and the
// energy the walls gave and the collisions took (with the sum of their magnitudes, the scale of
// the round-off of a budget).
template <int D>
struct WallLog final : EventObserver<D> {
  bool rough = false;  // rough grains: the record's own energy change (smooth: thesis eq 1.2's loss)
  std::vector<SurfaceHitRecord<D>> hits;
  Vec<D> impulse_on_walls;
  double wall_energy = 0.0, collision_energy = 0.0, magnitude = 0.0;
  std::int64_t collisions = 0;
  void on_surface_hit(const SurfaceHitRecord<D>& r) override {
    if (!r.surface.wall()) return;
    hits.push_back(r);
    impulse_on_walls = impulse_on_walls + r.impulse_on_surface;
    wall_energy += r.energy_change;
    magnitude += std::abs(r.energy_change);
  }
  void on_collision(const CollisionRecord<D>& r) override {
    ++collisions;
    const double vn = dot(r.relative_velocity, r.contact_normal);
    // Smooth grains of unit mass: (1 − e²)/4 v_n² lost (eq 1.2); rough ones report their own.
    const double change = rough ? r.energy_change : -0.25 * (1.0 - r.restitution * r.restitution) * vn * vn;
    collision_energy += change;
    magnitude += std::abs(change);
  }
};

// A unit box (L_y = `height`) for one grain of diameter `sigma`.
template <int D>
SystemParams one_grain_box(double sigma, double height = 1.0) {
  std::array<int, D> one{};
  std::array<double, D> box{};
  one.fill(1);
  box.fill(1.0);
  box[1] = height;
  return surfaces_system<D>(one, box, sigma, 1.0);
}

template <int D>
Simulation<D> single_grain(const SystemParams& p, const Vec<D>& position, const Vec<D>& velocity) {
  ParticleState s;
  s.dimension = D;
  s.resize(1);
  for (int a = 0; a < D; ++a) {
    s.position(a)[0] = position[a];
    s.velocity(a)[0] = velocity[a];
  }
  if (p.roughness.rough) s.make_rough();
  return Simulation<D>(p, surfaces_grid<D>(p, 0.001), s);
}

}  // namespace granule
