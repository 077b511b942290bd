// Shared set-up of the validation tests: systems of the thesis's unit box, simulations started
// from the §1.4.2 initial state, and the hard-disk equation of state they are checked against.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "cells/cell_grid.hpp"
#include "engine/simulation.hpp"
#include "init/initial_state.hpp"

namespace granule {

inline constexpr double kInf = std::numeric_limits<double>::infinity();

inline SystemParams make_system(int n, double nu, double e, double shear_velocity = 0.0) {
  SystemParams p;
  p.particles = n;
  p.diameter = std::sqrt(4.0 * nu / (M_PI * n));
  p.restitution = e;
  p.shear_velocity = shear_velocity;
  return p;
}

inline Simulation<2> make_simulation(const SystemParams& p, std::uint64_t seed, double temperature = 1.0) {
  const auto grid = choose_cell_grid({p.length_x, p.length_y, p.diameter, p.particles, p.shear_velocity != 0.0, 1.0, std::nullopt});
  const auto init = make_initial_state(p, temperature, seed, Placement::kAuto);
  EXPECT_TRUE(init.error.empty()) << init.error;
  return Simulation<2>(p, *grid.grid, init.state);
}

inline std::int64_t collisions_for(const SystemParams& p, double c) {
  return std::llround(c * static_cast<double>(p.particles));
}

// Henderson (Mol. Phys. 30, 971 (1975)) hard-disk equation of state Z = (1 + ν²/8)/(1 − ν)²,
// accurate to better than 1% against MD in the fluid up to ν ≈ 0.6; its contact value
// g(σ) = (Z − 1)/(2ν) = (1 − 7ν/16)/(1 − ν)².
inline double henderson_z(double nu) { return (1.0 + nu * nu / 8.0) / ((1.0 - nu) * (1.0 - nu)); }
inline double henderson_contact(double nu) { return (1.0 - 7.0 * nu / 16.0) / ((1.0 - nu) * (1.0 - nu)); }

}  // namespace granule
