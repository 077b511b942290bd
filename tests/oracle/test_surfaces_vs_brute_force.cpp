// Oracle tier for walls, gravity and spin: before each of thousands of events (pair collisions
// and wall hits) the O(N²) reference of brute_force_surfaces.hpp predicts, from the engine's own
// state, which event comes next and when; the engine must execute exactly that event at that
// time (to 1e-9) and leave the grains with the velocities and spins the reference's rule gives.
// Disks and spheres; smooth and rough (with Coulomb friction) grains; walls at rest and moving;
// gravity tilted against the walls.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "cells/cell_grid.hpp"
#include "engine/simulation.hpp"
#include "oracle/brute_force_surfaces.hpp"

namespace granule {
namespace {

struct SurfaceCase {
  int dimension;
  int particles;
  double packing_fraction;
  double restitution;
  bool rough;
  double beta;
  double friction;
  std::array<bool, 3> walls;
  std::array<double, 3> gravity;
  double wall_speed;  // the y walls move along x at ∓wall_speed
  std::uint64_t seed;
  const char* name;
};

// Box 1 × 1.3 (× 0.9); grains placed at random one radius inside every wall, not overlapping
// (tested against every placed grain and its periodic images), Gaussian velocities and spins.
ParticleState surface_gas(SystemParams& p, const SurfaceCase& k) {
  const int d = k.dimension;
  p.dimension = d;
  p.particles = k.particles;
  p.length_x = 1.0;
  p.length_y = 1.3;
  p.length_z = 0.9;
  const double volume = p.length_x * p.length_y * (d == 3 ? p.length_z : 1.0);
  const double unit_ball = d == 3 ? M_PI / 6.0 : M_PI / 4.0;
  p.diameter = std::pow(k.packing_fraction * volume / unit_ball / k.particles, 1.0 / d);
  p.restitution = k.restitution;
  p.walls = k.walls;
  p.gravity = k.gravity;
  // Under gravity the walls conserve energy (normal restitution 1, tangential ±1) and the grains
  // are elastic: a dissipative gas comes to rest on the floor or in a corner within the test, a
  // cascade of ever shorter bounces whose order is decided by round-off.
  const bool gravity = k.gravity[0] != 0.0 || k.gravity[1] != 0.0 || k.gravity[2] != 0.0;
  for (int face = 0; face < 6; ++face) {
    p.wall[static_cast<std::size_t>(face)].restitution = gravity ? 1.0 : 0.7 + 0.05 * face;
    p.wall[static_cast<std::size_t>(face)].tangential_restitution = face % 2 == 0 ? (gravity ? 1.0 : 0.4) : (gravity ? -1.0 : -0.6);
  }
  p.wall[2].velocity[0] = -k.wall_speed;
  p.wall[3].velocity[0] = k.wall_speed;
  if (k.rough) {
    p.roughness.rough = true;
    p.roughness.tangential_restitution = k.beta;
    p.roughness.inertia_factor = d == 2 ? 0.5 : 0.4;
    p.roughness.friction = k.friction;
  }
  ParticleState s;
  s.dimension = d;
  s.resize(static_cast<std::size_t>(k.particles));
  if (k.rough) s.make_rough();
  std::mt19937_64 rng(k.seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::normal_distribution<double> normal(0.0, 1.0);
  const double radius = 0.5 * p.diameter;
  for (int i = 0; i < k.particles; ++i) {
    for (int attempt = 0;; ++attempt) {
      if (attempt > 100000) throw std::runtime_error("oracle gas: cannot place");
      for (int a = 0; a < d; ++a) {
        const double length = oracle::box_length(p, a);
        const double margin = p.walls[static_cast<std::size_t>(a)] ? radius : 0.0;
        s.position(a)[i] = margin + uniform(rng) * (length - 2.0 * margin);
      }
      bool free = true;
      for (int j = 0; j < i && free; ++j) {
        oracle::for_each_plain_image(p, d, [&](const oracle::Point& shift) {
          double r2 = 0.0;
          for (int a = 0; a < d; ++a) r2 += std::pow(s.position(a)[j] + shift[a] - s.position(a)[i], 2);
          free = free && r2 > p.diameter * p.diameter;
        });
      }
      if (free) break;
    }
    for (int a = 0; a < d; ++a) s.velocity(a)[i] = normal(rng);
    if (k.rough) {
      for (int c = 0; c < s.spin_components(); ++c) s.spin(c)[i] = 20.0 * normal(rng);
    }
  }
  return s;
}

template <int D>
struct EventLog final : EventObserver<D> {
  std::vector<CollisionRecord<D>> collisions;
  std::vector<SurfaceHitRecord<D>> hits;
  void on_collision(const CollisionRecord<D>& r) override { collisions.push_back(r); }
  void on_surface_hit(const SurfaceHitRecord<D>& r) override {
    if (r.surface.wall()) hits.push_back(r);
  }
};

template <int D>
void check(const SurfaceCase& k) {
  SystemParams p;
  const ParticleState initial = surface_gas(p, k);
  CellGridRequest request{p.length_x, p.length_y, p.diameter, p.particles, false, 1.0, std::nullopt};
  request.dimension = D;
  request.length_z = p.length_z;
  const auto grid = choose_cell_grid(request);
  ASSERT_TRUE(grid.grid) << grid.error;
  Simulation<D> sim(p, *grid.grid, initial);
  EventLog<D> log;
  sim.add_observer(&log);

  constexpr int kEvents = 4000;
  constexpr auto kNoLimit = std::numeric_limits<std::int64_t>::max();
  int ties = 0, wall_hits = 0, cascades = 0;
  for (int n = 1; n <= kEvents; ++n) {
    const ParticleState state = sim.state();
    const double t = sim.time();
    const oracle::SurfaceEvent expected = oracle::brute_force_next_surface_event(p, state);
    ASSERT_TRUE(std::isfinite(expected.delay));
    const double tolerance = 1e-9 * std::max(1.0, t);
    if (expected.runner_up_delay - expected.delay < 4.0 * tolerance) {
      // Two events within round-off of each other: either order is right; step past both.
      ++ties;
      sim.run(t + expected.runner_up_delay + 2.0 * tolerance, kNoLimit);
      log.collisions.clear();
      log.hits.clear();
      continue;
    }
    // Run just past the expected event (not to the runner-up: the event itself may cause an
    // earlier one), a little further if round-off put the engine's event a hair later.
    sim.run(t + expected.delay + std::min(0.5 * (expected.runner_up_delay - expected.delay), 0.1 * tolerance), kNoLimit);
    if (log.collisions.empty() && log.hits.empty()) sim.run(t + expected.delay + tolerance, kNoLimit);
    // The event may cause the next at once (a grain coming to rest on a floor re-hits it within
    // 1e-10): the first one executed is the one to compare, the rest is a cascade.
    ASSERT_GE(log.collisions.size() + log.hits.size(), 1u) << "event " << n << " at t = " << t << ": expected " << expected.first << "-" << expected.second << " face " << expected.face << " after " << expected.delay << " runner-up " << expected.runner_up_delay << " now " << sim.time();
    const bool cascade = log.collisions.size() + log.hits.size() > 1;
    cascades += cascade ? 1 : 0;
    const bool hit_first = !log.hits.empty() && (log.collisions.empty() || log.hits[0].time <= log.collisions[0].time);
    if (hit_first) log.collisions.clear();
    else log.hits.clear();
    const double restitution =
        expected.second < 0 ? p.wall[static_cast<std::size_t>(expected.face)].restitution : p.restitution;
    const auto after = oracle::brute_force_execute(p, state, expected, restitution);
    // Velocities to 1e-9 of the speed, plus what gravity adds over the event-time tolerance.
    double scale = 1.0, gravity = 0.0;
    for (int a = 0; a < D; ++a) {
      scale = std::max(scale, std::abs(state.velocity(a)[static_cast<std::size_t>(expected.first)]));
      gravity = std::max(gravity, std::abs(p.gravity[static_cast<std::size_t>(a)]));
    }
    scale += gravity * tolerance / 1e-9;
    if (expected.second < 0) {
      ++wall_hits;
      ASSERT_FALSE(log.hits.empty()) << "event " << n << ": the reference expects a wall hit";
      const SurfaceHitRecord<D>& hit = log.hits[0];
      ASSERT_EQ(hit.particle, expected.first) << "event " << n;
      ASSERT_EQ(2 * hit.surface.axis() + hit.surface.side(), expected.face) << "event " << n;
      ASSERT_NEAR(hit.time, t + expected.delay, tolerance) << "event " << n;
      for (int a = 0; a < D; ++a) ASSERT_NEAR(hit.velocity_after[a], after[0].v[a], 1e-9 * scale) << "event " << n;
    } else {
      ASSERT_FALSE(log.collisions.empty()) << "event " << n << ": the reference expects a collision";
      const CollisionRecord<D>& c = log.collisions[0];
      ASSERT_EQ(std::min(c.first, c.second), expected.first) << "event " << n;
      ASSERT_EQ(std::max(c.first, c.second), expected.second) << "event " << n;
      ASSERT_NEAR(c.time, t + expected.delay, tolerance) << "event " << n;
      const bool swapped = c.first != expected.first;
      for (int a = 0; a < D; ++a) {
        ASSERT_NEAR(c.first_velocity_after[a], after[swapped ? 1 : 0].v[a], 1e-9 * scale) << "event " << n;
        ASSERT_NEAR(c.second_velocity_after[a], after[swapped ? 0 : 1].v[a], 1e-9 * scale) << "event " << n;
      }
    }
    if (k.rough && !cascade) {  // spins of the grains involved, read back from the engine's state
      const ParticleState now = sim.state();
      const int grains[2] = {expected.first, expected.second};
      for (int g = 0; g < 2; ++g) {
        if (grains[g] < 0) continue;
        const oracle::Point w = oracle::spin_of(now, grains[g]);
        double spin_scale = 1.0;
        for (int a = 0; a < 3; ++a) spin_scale = std::max(spin_scale, std::abs(after[g].w[a]));
        for (int a = 0; a < 3; ++a) ASSERT_NEAR(w[a], after[g].w[a], 1e-9 * spin_scale) << "event " << n << " grain " << g;
      }
    }
    log.collisions.clear();
    log.hits.clear();
  }
  EXPECT_LT(ties, kEvents / 50);
  EXPECT_LT(cascades, kEvents / 20);
  if (k.walls[0] || k.walls[1] || k.walls[2]) {
    EXPECT_GT(wall_hits, kEvents / 20);
  }
  std::printf("%d events: %d wall hits, %d ties, %d cascades\n", kEvents, wall_hits, ties, cascades);
  sim.check_invariants();
}

class SurfacesVsBruteForce : public ::testing::TestWithParam<SurfaceCase> {};

TEST_P(SurfacesVsBruteForce, SameNextEventEveryTime) {
  const SurfaceCase& k = GetParam();
  if (k.dimension == 2) {
    check<2>(k);
  } else {
    check<3>(k);
  }
}

constexpr double kNoFriction = std::numeric_limits<double>::infinity();

INSTANTIATE_TEST_SUITE_P(
    Surfaces, SurfacesVsBruteForce,
    ::testing::Values(
        // Under gravity elastic grains (smooth, or perfectly rough: β = 1), to keep the gas a gas.
        SurfaceCase{2, 80, 0.2, 1.0, false, -1.0, kNoFriction, {false, true, false}, {0.0, -3.0, 0.0}, 0.0, 1, "SmoothFloorGravity"},
        SurfaceCase{2, 80, 0.25, 0.8, true, 0.3, kNoFriction, {false, true, false}, {0.0, 0.0, 0.0}, 1.5, 2, "RoughCouette"},
        SurfaceCase{2, 80, 0.2, 1.0, true, 1.0, kNoFriction, {true, true, false}, {1.0, -2.0, 0.0}, 0.0, 3, "RoughBoxTiltedGravity"},
        SurfaceCase{2, 80, 0.3, 0.95, true, -0.2, kNoFriction, {false, false, false}, {0.0, 0.0, 0.0}, 0.0, 4, "RoughPeriodic"},
        SurfaceCase{3, 50, 0.15, 1.0, true, 1.0, kNoFriction, {false, true, true}, {0.0, -2.0, 0.5}, 1.0, 5, "RoughSpheresWallsGravity"},
        SurfaceCase{3, 50, 0.2, 1.0, false, -1.0, kNoFriction, {true, true, true}, {0.3, -1.0, 0.0}, 0.0, 6, "SmoothSpheresClosedBox"},
        SurfaceCase{3, 50, 0.2, 0.85, true, 0.4, 0.3, {false, true, false}, {0.0, 0.0, 0.0}, 1.0, 7, "RoughFrictionSpheresCouette"}),
    [](const ::testing::TestParamInfo<SurfaceCase>& test) {
      return std::to_string(test.param.dimension) + "D_" + test.param.name;
    });

}  // namespace
}  // namespace granule
