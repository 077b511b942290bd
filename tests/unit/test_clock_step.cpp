// The conservative searches' round-off guard (boundary/clock_step.hpp) late in a run, where a
// step of the delay is far below an ulp of the absolute clock: the search must still move on and
// find the hit, not step the delay one ulp of its own at a time.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "boundary/clock_step.hpp"
#include "boundary/obstacle_hit.hpp"
#include "motion/uniform_field.hpp"

namespace granule {
namespace {

TEST(ClockStep, KeepsAStepThatMovesTheClock) {
  EXPECT_EQ(clock_moves_on(1.0, 0.5, 0.75), 0.75);
}

TEST(ClockStep, JumpsToTheClocksNextInstant) {
  for (const double now : {1e-3, 1.0, 3.7, 1e4, 1e9}) {
    const double tau = 1e-7;
    const double next = clock_moves_on(now, tau, tau + 1e-30);
    EXPECT_EQ(now + next, std::nextafter(now + tau, std::numeric_limits<double>::infinity())) << "now = " << now;
  }
}

// A disk of radius ½ (σ = 1) at rest at (0.6, 0.9) from the centre of an obstacle of radius ½, under
// g = 1, falls onto it at (0.6, 0.8) after √0.2.  The search's steps shrink as it closes in, below an ulp
// of a clock of 10⁹ (1.2·10⁻⁷) for the last ones: stepping the delay by its own ulps (5.6·10⁻¹⁷) there
// would take millions of steps each.
TEST(ClockStep, ObstacleHitLateInARun) {
  const UniformField<2> field{{0.0, -1.0}};
  for (const double now : {0.0, 1e3, 1e9}) {
    const double t = obstacle_hit<2>(field, Vec<2>{0.6, 0.9}, Vec<2>{0.0, 0.0}, 1.0, now, 1.0, 1e-12);
    const double clock_ulp = now > 0.0 ? std::nextafter(now, 2.0 * now) - now : 0.0;
    EXPECT_NEAR(t, std::sqrt(0.2), 1e-10 + 2.0 * clock_ulp) << "now = " << now;
  }
}

// A disk touching the top of an obstacle and sliding over it at v = √(g R), R = σ: its flight (x = t,
// y = 1 − t²/2) keeps |d|² = 1 + t⁴/4 off contact, so there is no hit.  At τ = 0 it touches without
// approaching and the conservative step is 0; a delay stepped by its own ulps from 0 would never move
// the clock.  The search moves it on by the clock's ulps and, at its step limit, stops where it
// stands: a time at which the grain does not touch while approaching (its execution predicts again).
TEST(ClockStep, SlidingOffTheTopOfAnObstacle) {
  const UniformField<2> field{{0.0, -1.0}};
  for (const double now : {1.0, 1e3}) {
    const double t = obstacle_hit<2>(field, Vec<2>{0.0, 1.0}, Vec<2>{1.0, 0.0}, 1.0, now, 1.0, 1e-12);
    ASSERT_GT(t, 0.0) << "now = " << now;
    if (t == std::numeric_limits<double>::infinity()) continue;
    const Vec<2> at{t, 1.0 - 0.5 * t * t};
    const Vec<2> velocity{1.0, -t};
    EXPECT_FALSE(touches_obstacle<2>(at, velocity, 1.0, 1e-12)) << "now = " << now << ", t = " << t;
  }
}

}  // namespace
}  // namespace granule
