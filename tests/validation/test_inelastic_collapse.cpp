// Inelastic collapse (McNamara & Young 1994): with constant small restitution a dense group of
// disks collides infinitely often in finite time.  The run must stop with a report instead of
// hanging, and the TC model (Luding & McNamara 1998) must let the same run continue.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>

#include "cells/cell_grid.hpp"
#include "engine/simulation.hpp"
#include "init/initial_state.hpp"

namespace granule {
namespace {

Simulation<2> make(double tc) {
  SystemParams p;
  p.particles = 400;
  p.diameter = std::sqrt(4.0 * 0.4 / (M_PI * 400));
  p.restitution = 0.1;
  p.tc_duration = tc;
  const auto grid = choose_cell_grid({1.0, 1.0, p.diameter, p.particles, false, 1.0, std::nullopt});
  const auto init = make_initial_state(p, 1.0, 17, Placement::kRandom);
  return Simulation<2>(p, *grid.grid, init.state);
}

TEST(InelasticCollapse, DetectedWithoutTcAndAvoidedWithIt) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  Simulation<2> plain = make(0.0);
  const StopReason reason = plain.run(kInf, 400L * 2000);
  ASSERT_EQ(reason, StopReason::kInelasticCollapse) << "c reached " << plain.collisions_per_particle();
  EXPECT_GE(plain.collapse().first, 0);
  EXPECT_GE(plain.collapse().second, 0);
  std::printf("collapse without TC at c = %.4g, t = %.9g\n", plain.collisions_per_particle(), plain.time());

  // The same system with t_c far below the initial mean free time (~1e-2 here) runs well past the
  // point where the plain one collapsed, and its clock keeps moving.
  Simulation<2> tc = make(1e-7);
  const std::int64_t beyond = 3 * plain.collisions();
  EXPECT_EQ(tc.run(kInf, beyond), StopReason::kCollisionsReached);
  EXPECT_GT(tc.time(), plain.time());
  const double t_then = tc.time();
  EXPECT_EQ(tc.run(kInf, beyond + 400L * 10), StopReason::kCollisionsReached);
  EXPECT_GT(tc.time(), t_then);
}

// The detector must not depend on how the run is driven: stopping every 0.1 collisions per
// particle (as frequent outputs do) detects the collapse at exactly the same collision.
TEST(InelasticCollapse, DetectedAlikeWhenStoppedEveryTenthCollisionPerParticle) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  Simulation<2> reference = make(0.0);
  ASSERT_EQ(reference.run(kInf, 400L * 2000), StopReason::kInelasticCollapse);
  Simulation<2> stopped = make(0.0);
  StopReason reason = StopReason::kCollisionsReached;
  for (std::int64_t target = 40; reason == StopReason::kCollisionsReached && target <= 400L * 2000; target += 40) {
    reason = stopped.run(kInf, target);
  }
  EXPECT_EQ(reason, StopReason::kInelasticCollapse);
  EXPECT_EQ(stopped.collisions(), reference.collisions());
  EXPECT_EQ(stopped.time(), reference.time());
}

}  // namespace
}  // namespace granule
