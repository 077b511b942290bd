// The engine under the shear protocols of thesis §4.3 (boundary/shear_protocol.hpp): the image
// velocity it applies stays within the protocol's tolerance of the exact U(t); its image offset
// follows Δ(t) − Δ(0) = ∫₀ᵗ U dt (mod L_x) in closed form; a ramp with τ → 0 is the constant
// drive; and the invariants hold through every change of U.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "validation/simulation_setup.hpp"

namespace granule {
namespace {

struct Drive {
  const char* name;
  double steady;
  ShearHistory history;
};

std::vector<Drive> drives() {
  ShearHistory ramp;
  ramp.ramp_time = 0.08;
  ShearHistory schedule;  // up, hold, a step down through zero, up again
  schedule.schedule = {{0.0, 0.0}, {0.05, 6.0}, {0.1, 6.0}, {0.1, -4.0}, {0.3, 8.0}};
  ShearHistory kick;
  kick.oscillation = ShearOscillation{3.0, 0.05, 0.05, 3.0};
  return {{"ramp", 8.0, ramp}, {"schedule", 0.0, schedule}, {"kick", 6.0, kick}};
}

SystemParams driven_system(const Drive& d) {
  SystemParams p = make_system(600, 0.1, 0.8, d.history.schedule.empty() ? d.steady : d.history.schedule.back().velocity);
  p.shear_history = d.history;
  p.tc_duration = 1e-6;
  return p;
}

// Production from the §1.4.2 state with no pre-run: the protocol starts at once.
Simulation<2> driven_simulation(const SystemParams& p, std::uint64_t seed, double held_velocity) {
  const auto grid = choose_cell_grid({p.length_x, p.length_y, p.diameter, p.particles, true, 1.0, std::nullopt});
  const auto init = make_initial_state(p, 1.0, seed, Placement::kAuto, held_velocity);
  EXPECT_TRUE(init.error.empty()) << init.error;
  ClockState clock;
  clock.held_shear_velocity = held_velocity;
  Simulation<2> sim(p, *grid.grid, init.state, clock);
  sim.start_production(p.restitution);
  return sim;
}

// x reduced to (−L/2, L/2].
double centred(double x, double length) { return x - length * std::round(x / length); }

TEST(ShearProtocols, ImageVelocityAndOffsetFollowTheProtocol) {
  for (const Drive& d : drives()) {
    const SystemParams p = driven_system(d);
    const ShearProtocol protocol(p.shear_velocity, p.shear_history);
    Simulation<2> sim = driven_simulation(p, 5, protocol.velocity(0.0));
    const double offset0 = sim.shear_offset();
    const double scale = protocol.velocity_scale();
    double worst_velocity = 0.0, worst_offset = 0.0;
    int stops = 0;
    for (double t = 0.0017; t < 0.4; t += 0.0023, ++stops) {
      ASSERT_EQ(sim.run(t, INT64_MAX), StopReason::kTimeReached) << d.name;
      const double exact = protocol.velocity(sim.time());
      worst_velocity = std::max(worst_velocity, std::abs(sim.image_velocity() - exact));
      // Within a segment [a, b] the offset may lag the exact integral by ∫_a^t (Ū − U) ≤ (t − a)·tol·scale.
      const ShearSegment segment = protocol.segment_containing(sim.time());
      const double allowed = (sim.time() - segment.start) * p.shear_history.tolerance * scale + 1e-12;
      const double error = centred(sim.shear_offset() - offset0 - protocol.integral(0.0, sim.time()), p.length_x);
      worst_offset = std::max(worst_offset, std::abs(error) / allowed);
      if (stops % 40 == 0) {
        ASSERT_NO_THROW(sim.check_invariants()) << d.name << " at t = " << sim.time();
      }
    }
    std::printf("%s: %d stops to t = 0.4, c = %.1f; max |U − U_exact| = %.3g (tolerance %.3g); max offset error / bound %.3f\n",
                d.name, stops, sim.collisions_per_particle(), worst_velocity, p.shear_history.tolerance * scale, worst_offset);
    EXPECT_LE(worst_velocity, p.shear_history.tolerance * scale * (1.0 + 1e-9)) << d.name;
    EXPECT_LE(worst_offset, 1.0) << d.name;
    EXPECT_GT(sim.collisions_per_particle(), 5.0) << d.name;
  }
}

// τ → 0: the ramp is the constant drive switched on at t = 0, so from one state both runs stay
// together (to the chaos-amplified lag of the offset, U₀ τ), while a ramp over a tenth of a
// collision time leaves a visibly different state.
TEST(ShearProtocols, RampWithVanishingTimeIsTheConstantDrive) {
  const double u0 = 8.0;
  const auto final_positions = [&](double ramp_time) {
    Drive d{"ramp", u0, {}};
    d.history.ramp_time = ramp_time;
    const SystemParams p = driven_system(d);
    Simulation<2> sim = driven_simulation(p, 9, u0);  // both start from the same profile of U₀
    sim.run(kInf, collisions_for(p, 0.5));
    return sim.state();
  };
  const ParticleState constant = final_positions(0.0);
  const auto distance = [&](const ParticleState& s) {
    double worst = 0.0;
    for (std::size_t i = 0; i < s.size(); ++i) {
      worst = std::max(worst, std::hypot(centred(s.x[i] - constant.x[i], 1.0), centred(s.y[i] - constant.y[i], 1.0)));
    }
    return worst;
  };
  const double vanishing = distance(final_positions(1e-13));
  const double short_ramp = distance(final_positions(3e-3));
  std::printf("largest position difference after c = 0.5: τ = 1e-13: %.3g, τ = 3e-3: %.3g\n", vanishing, short_ramp);
  EXPECT_LT(vanishing, 1e-8);
  EXPECT_GT(short_ramp, 1e-3);
}

}  // namespace
}  // namespace granule
