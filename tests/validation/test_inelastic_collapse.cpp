// Inelastic collapse (McNamara & Young 1994): with constant small restitution a dense group of
// disks collides infinitely often in finite time.  The run must stop with a report instead of
// hanging, and the TC model (Luding & McNamara 1998) must let the same run continue.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "cells/cell_grid.hpp"
#include "engine/simulation.hpp"
#include "init/initial_state.hpp"

namespace granule {
namespace {

Simulation make(double tc) {
  SystemParams p;
  p.particles = 400;
  p.diameter = std::sqrt(4.0 * 0.4 / (M_PI * 400));
  p.restitution = 0.1;
  p.tc_duration = tc;
  const auto grid = choose_cell_grid({1.0, 1.0, p.diameter, p.particles, false, 1.0, std::nullopt});
  const auto init = make_initial_state(p, 1.0, 17, Placement::kRandom);
  return Simulation(p, *grid.grid, init.state);
}

TEST(InelasticCollapse, DetectedWithoutTcAndAvoidedWithIt) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  Simulation plain = make(0.0);
  const StopReason reason = plain.run(kInf, 400L * 2000);
  ASSERT_EQ(reason, StopReason::kInelasticCollapse) << "c reached " << plain.collisions_per_particle();
  EXPECT_GE(plain.collapse().first, 0);

  // t_c far below the initial mean free time (~1e-2 here).
  Simulation tc = make(1e-7);
  EXPECT_EQ(tc.run(kInf, 400L * 200), StopReason::kCollisionsReached);
}

}  // namespace
}  // namespace granule
