// Unit tests of collision-time prediction: head-on, grazing, touching, overlapping and receding.
#include <gtest/gtest.h>

#include <cmath>

#include "physics/collision_time.hpp"
#include "physics/crossing_time.hpp"

namespace granule {
namespace {

TEST(CollisionTime, HeadOn) {
  // Gap 3 − 1 = 2 closed at relative speed 4: τ = 0.5.
  EXPECT_DOUBLE_EQ(collision_time<2>({3.0, 0.0}, {-4.0, 0.0}, 1.0), 0.5);
}

TEST(CollisionTime, OffsetImpactMatchesGeometry) {
  // Partner at (5, b) moving at −1 along x: contact when (5 − τ)² + b² = 1.
  for (double b : {0.0, 0.3, 0.9, 0.999999}) {
    const double expected = 5.0 - std::sqrt(1.0 - b * b);
    EXPECT_NEAR(collision_time<2>({5.0, b}, {-1.0, 0.0}, 1.0), expected, 1e-12) << b;
  }
}

TEST(CollisionTime, GrazingMissAndExactGraze) {
  EXPECT_EQ(collision_time<2>({5.0, 1.0 + 1e-12}, {-1.0, 0.0}, 1.0), kNever);
  // Impact parameter exactly σ: tangential touch at τ = 5 (disc = 0).
  EXPECT_NEAR(collision_time<2>({5.0, 1.0}, {-1.0, 0.0}, 1.0), 5.0, 1e-6);
}

TEST(CollisionTime, TouchingApproachingCollidesNow) {
  EXPECT_EQ(collision_time<2>({1.0, 0.0}, {-1.0, 0.0}, 1.0), 0.0);
}

TEST(CollisionTime, OverlapByRoundOff) {
  // Overlapping and approaching: now.  Overlapping and receding: never (Bannerman et al. 2014).
  EXPECT_EQ(collision_time<2>({1.0 - 1e-13, 0.0}, {-1.0, 0.1}, 1.0), 0.0);
  EXPECT_EQ(collision_time<2>({1.0 - 1e-13, 0.0}, {1.0, 0.1}, 1.0), kNever);
}

TEST(CollisionTime, GrazingContactIsTangential) {
  // At contact with a normal velocity 10⁻¹⁷ of the speed: no impulse could separate the pair
  // (it would be lost in round-off), so it must not collide at all, or it collides forever at
  // one instant.  A normal velocity of 10⁻⁹ of the speed is resolved and collides now.
  EXPECT_EQ(collision_time<2>({1.0, 0.0}, {-1e-17, 1.0}, 1.0), kNever);
  EXPECT_FALSE(approaching<2>({1.0, 0.0}, {-1e-17, 1.0}));
  EXPECT_EQ(collision_time<2>({1.0, 0.0}, {-1e-9, 1.0}, 1.0), 0.0);
  EXPECT_TRUE(approaching<2>({1.0, 0.0}, {-1e-9, 1.0}));
}

TEST(CollisionTime, RecedingAndParallel) {
  EXPECT_EQ(collision_time<2>({3.0, 0.0}, {1.0, 0.0}, 1.0), kNever);
  EXPECT_EQ(collision_time<2>({3.0, 0.0}, {0.0, 1.0}, 1.0), kNever);
  EXPECT_EQ(collision_time<2>({3.0, 0.0}, {0.0, 0.0}, 1.0), kNever);
}

TEST(CrossingTime, Linear) {
  EXPECT_DOUBLE_EQ(first_exit_time(0.0, 2.0, -1.0), 0.5);
  EXPECT_EQ(first_exit_time(0.0, -2.0, -1.0), kNever);
  EXPECT_EQ(first_exit_time(0.0, 2.0, 1e-15), 0.0);  // just past the edge, moving out
}

TEST(CrossingTime, ParabolaLeavesOnTheUpwardRoot) {
  // g = τ² − 3τ + 2 = (τ−1)(τ−2) starts outside (g(0) = 2 > 0) and moving in: the upward
  // crossing is at τ = 2.
  EXPECT_NEAR(first_exit_time(1.0, -3.0, 2.0), 2.0, 1e-14);
  // g = −τ² + 3τ − 2 is inside, leaves at τ = 1, returns at 2.
  EXPECT_NEAR(first_exit_time(-1.0, 3.0, -2.0), 1.0, 1e-14);
  // Downward parabola that never reaches the edge.
  EXPECT_EQ(first_exit_time(-1.0, 0.0, -1.0), kNever);
  // Just entered through this edge (g(0) = +1e-17 by round-off, moving in, a < 0): it must not
  // be sent straight back out (the cell ping-pong this guards against).
  EXPECT_EQ(first_exit_time(-0.09, -1.6, 1e-17), kNever);
  EXPECT_EQ(first_exit_time(-0.09, -1.6, 0.0), kNever);
  // Same, but moving out: leaves now.
  EXPECT_EQ(first_exit_time(-0.09, 1.6, 1e-17), 0.0);
  // At the apex of its flight exactly on the edge (g = −τ², a double root at 0): it only touches the
  // edge, it never leaves (a grain at rest on a cell face under gravity swapped cells forever).
  EXPECT_EQ(first_exit_time(-0.5, 0.0, 0.0), kNever);
  EXPECT_EQ(first_exit_time(-0.5, -0.0, -0.0), kNever);
  // Upward parabola from inside: leaves at the larger root √2.
  EXPECT_NEAR(first_exit_time(1.0, 0.0, -2.0), std::sqrt(2.0), 1e-14);
}

}  // namespace
}  // namespace granule
