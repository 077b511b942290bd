// Oracle tier: the cell engine against the O(N²) reference of brute_force.hpp.
//
// Hard-disk dynamics is chaotic, so two correct codes drift apart after a few dozen collisions
// per particle from round-off alone.  The comparison is therefore made event by event from the
// engine's own state: before each of ≥ 10^4 collisions the reference predicts, from the
// engine's configuration, which pair collides next and when; the engine must execute exactly
// that pair at that time (to 1e-9), across periodic and Lees–Edwards boxes, densities and seeds,
// and leave both disks with the velocities the reference's own collision rule gives.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "cells/cell_grid.hpp"
#include "engine/simulation.hpp"
#include "init/initial_state.hpp"
#include "oracle/brute_force.hpp"

namespace granule {
namespace {

struct OracleCase {
  int particles;
  double area_fraction;
  double restitution;
  double shear_velocity;
  std::uint64_t seed;
};

class EngineVsBruteForce : public ::testing::TestWithParam<OracleCase> {};

TEST_P(EngineVsBruteForce, SameNextCollisionEveryTime) {
  const OracleCase k = GetParam();
  SystemParams p;
  p.particles = k.particles;
  p.length_x = 1.0;
  p.length_y = 1.3;  // not square, so that x and y mix-ups show
  p.diameter = std::sqrt(4.0 * k.area_fraction * p.length_x * p.length_y / (M_PI * k.particles));
  p.restitution = k.restitution;
  p.shear_velocity = k.shear_velocity;
  const auto grid = choose_cell_grid({p.length_x, p.length_y, p.diameter, p.particles, k.shear_velocity != 0.0, 1.0, std::nullopt});
  ASSERT_TRUE(grid.grid) << grid.error;
  const auto init = make_initial_state(p, 1.0, k.seed, Placement::kAuto);
  ASSERT_TRUE(init.error.empty()) << init.error;
  Simulation sim(p, *grid.grid, init.state);

  struct Recorder final : EventObserver {
    CollisionRecord last;
    void on_collision(const CollisionRecord& r) override { last = r; }
  } recorder;
  sim.add_observer(&recorder);

  constexpr int kCollisions = 10000;
  int ties = 0;
  for (int n = 1; n <= kCollisions; ++n) {
    const ParticleState state = sim.state();
    const double t = sim.time();
    const auto expected = oracle::brute_force_next_collision(p, state, t);
    ASSERT_TRUE(std::isfinite(expected.delay));
    ASSERT_EQ(sim.run(std::numeric_limits<double>::infinity(), n), StopReason::kCollisionsReached);
    const double tolerance = 1e-9 * std::max(1.0, t);
    const int a = std::min(recorder.last.first, recorder.last.second);
    const int b = std::max(recorder.last.first, recorder.last.second);
    ASSERT_NEAR(recorder.last.time, t + expected.delay, tolerance) << "collision " << n;
    const CollisionRecord& r = recorder.last;
    const auto after = oracle::brute_force_collide(p, state, t, r.first, r.second, r.time - t, r.restitution);
    double speed = 0.0;
    for (double v : {r.first_velocity_before.x, r.first_velocity_before.y, r.second_velocity_before.x, r.second_velocity_before.y}) {
      speed = std::max(speed, std::abs(v));
    }
    ASSERT_NEAR(r.first_velocity_after.x, after.v1x, 1e-9 * speed) << "collision " << n;
    ASSERT_NEAR(r.first_velocity_after.y, after.v1y, 1e-9 * speed) << "collision " << n;
    ASSERT_NEAR(r.second_velocity_after.x, after.v2x, 1e-9 * speed) << "collision " << n;
    ASSERT_NEAR(r.second_velocity_after.y, after.v2y, 1e-9 * speed) << "collision " << n;
    EXPECT_EQ(r.restitution, p.restitution);
    if (expected.runner_up_delay - expected.delay < tolerance) {
      ++ties;  // two collisions at the same time to 1e-9: either order is correct
      continue;
    }
    ASSERT_EQ(a, expected.first) << "collision " << n << " at t = " << t;
    ASSERT_EQ(b, expected.second) << "collision " << n << " at t = " << t;
    if (n % 500 == 0) {
      ASSERT_GT(oracle::min_distance_ratio(p, sim.state(), sim.time()), 1.0 - 1e-9);
    }
  }
  EXPECT_LT(ties, kCollisions / 100);
}

INSTANTIATE_TEST_SUITE_P(
    Boxes, EngineVsBruteForce,
    ::testing::Values(OracleCase{100, 0.05, 1.0, 0.0, 1}, OracleCase{100, 0.3, 0.9, 0.0, 2},
                      OracleCase{120, 0.6, 1.0, 0.0, 3}, OracleCase{100, 0.05, 0.8, 3.0, 4},
                      OracleCase{100, 0.3, 1.0, 2.0, 5}, OracleCase{80, 0.5, 0.9, -4.0, 6}),
    [](const ::testing::TestParamInfo<OracleCase>& test) {
      const OracleCase& k = test.param;
      return std::string(k.shear_velocity != 0.0 ? "LeesEdwards" : "Periodic") + "_nu" +
             std::to_string(static_cast<int>(100 * k.area_fraction)) + "_seed" + std::to_string(k.seed);
    });

}  // namespace
}  // namespace granule
