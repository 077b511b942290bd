// Unit tests of the collision rule (thesis eq 1.2): momentum conservation and the exact energy
// loss (1 − e²)/4 (v21·k̂)² per collision of unit-mass disks.
#include <gtest/gtest.h>

#include <cmath>

#include "physics/collision_rule.hpp"

namespace granule {
namespace {

double kinetic(Vec2 a, Vec2 b) { return 0.5 * (norm2(a) + norm2(b)); }

TEST(CollisionRule, ConservesMomentumAndLosesExactEnergy) {
  const Vec2 v1{1.3, -0.4};
  const Vec2 v2{-0.7, 0.9};
  const double angle = 0.37;
  const Vec2 k{std::cos(angle), std::sin(angle)};
  for (double e : {1.0, 0.9, 0.6, 0.1}) {
    const auto out = collide(v1, v2, k, e);
    const Vec2 p_before = v1 + v2;
    const Vec2 p_after = out.v1 + out.v2;
    EXPECT_NEAR(p_after.x, p_before.x, 1e-15);
    EXPECT_NEAR(p_after.y, p_before.y, 1e-15);
    const double vn = dot(v1 - v2, k);
    const double expected_loss = 0.25 * (1.0 - e * e) * vn * vn;
    EXPECT_NEAR(kinetic(v1, v2) - kinetic(out.v1, out.v2), expected_loss, 1e-14) << "e=" << e;
    // Normal relative velocity reversed and scaled by e; tangential unchanged.
    EXPECT_NEAR(dot(out.v1 - out.v2, k), -e * vn, 1e-14);
    EXPECT_NEAR(cross(out.v1 - out.v2, k), cross(v1 - v2, k), 1e-14);
  }
}

TEST(CollisionRule, HeadOnElasticSwapsVelocities) {
  const auto out = collide<2>({1.0, 0.0}, {-2.0, 0.0}, {1.0, 0.0}, 1.0);
  EXPECT_DOUBLE_EQ(out.v1.x, -2.0);
  EXPECT_DOUBLE_EQ(out.v2.x, 1.0);
}

TEST(CollisionRule, PerfectlyInelasticHeadOnSticks) {
  // e → 0 limit: equal normal velocities afterwards (the thesis restricts e > 0, this checks J).
  const auto out = collide<2>({1.0, 0.5}, {-1.0, 0.0}, {1.0, 0.0}, 0.0);
  EXPECT_DOUBLE_EQ(out.v1.x, out.v2.x);
  EXPECT_DOUBLE_EQ(out.v1.y, 0.5);
}

}  // namespace
}  // namespace granule
