// Exact budgets: the engine may change the total momentum and kinetic energy only where the
// physics says, by exactly the amounts it says, to round-off, over ≥ 10⁴ collisions.
//   • a collision (thesis eq 1.2) conserves momentum and removes (1 − ẽ²)/4 (v₂₁·k̂)² (unit mass);
//     when the partner is a Lees–Edwards image moving at v + i_y U, the lab energy also changes
//     by −i_y U J k̂_x (J the impulse on the partner): the shear work that heats a sheared gas;
//   • a disk crossing the top (bottom) of a Lees–Edwards box changes v_x by −U (+U) (§1.4.2).
// Under a shear protocol (thesis §4.3) U is the image velocity at that moment, so the budget holds
// exactly in any protocol: the change of kinetic energy is the work done across the boundary
// minus the collisional losses.
// The budget is summed from the collision records with the formulas above, written here
// independently of the engine's collision rule, and compared with the state's own totals.
#include <gtest/gtest.h>

#include <cmath>

#include "validation/simulation_setup.hpp"

namespace granule {
namespace {

struct Budget final : EventObserver<2> {
  const Simulation<2>* sim = nullptr;  // U at the moment of each crossing: sim->image_velocity()
  double energy = 0.0, momentum_x = 0.0, magnitude = 0.0;  // predicted changes; Σ|terms| for round-off
  std::int64_t collisions = 0, crossings = 0, wrong_crossing_shifts = 0, wrong_image_velocities = 0;
  void on_collision(const CollisionRecord<2>& r) override {
    const double vn = r.relative_velocity.x * r.contact_normal.x + r.relative_velocity.y * r.contact_normal.y;
    const double e = r.restitution;
    const double impulse = 0.5 * (1.0 + e) * vn;  // on disk 2, along k̂
    const double loss = 0.25 * (1.0 - e * e) * vn * vn;
    const double shear_work = -r.image_velocity_x * impulse * r.contact_normal.x;
    if (r.image_velocity_x != r.image_y * sim->image_velocity()) ++wrong_image_velocities;
    energy += -loss + shear_work;
    magnitude += loss + std::abs(shear_work);
    ++collisions;
  }
  void on_boundary_crossing(const BoundaryCrossingRecord& r) override {
    const double shear_velocity = sim->image_velocity();
    if (r.velocity_x_after - r.velocity_x_before != -r.direction * shear_velocity) {
      // Exact in floating point only when v_x and U are of one magnitude; allow round-off.
      const double expected = r.velocity_x_before - r.direction * shear_velocity;
      if (std::abs(r.velocity_x_after - expected) > 1e-14 * (std::abs(expected) + std::abs(shear_velocity))) {
        ++wrong_crossing_shifts;
      }
    }
    const double change = 0.5 * (r.velocity_x_after * r.velocity_x_after - r.velocity_x_before * r.velocity_x_before);
    energy += change;
    magnitude += std::abs(change);
    momentum_x += -r.direction * shear_velocity;
    ++crossings;
  }
};

struct Totals {
  double energy = 0.0, px = 0.0, py = 0.0, scale = 0.0;
};
Totals totals(const ParticleState& s) {
  Totals t;
  for (std::size_t i = 0; i < s.size(); ++i) {
    t.energy += 0.5 * (s.vx[i] * s.vx[i] + s.vy[i] * s.vy[i]);
    t.px += s.vx[i];
    t.py += s.vy[i];
    t.scale += std::abs(s.vx[i]) + std::abs(s.vy[i]);
  }
  return t;
}

struct BudgetCase {
  double area_fraction, restitution, shear_velocity, tc_duration;
  ShearHistory history = {};
};

ShearHistory ramp_and_kick() {
  ShearHistory h;
  h.ramp_time = 0.05;
  h.oscillation = ShearOscillation{2.0, 0.03, 0.02, 4.0};
  return h;
}

ShearHistory steps_through_zero() {
  ShearHistory h;
  h.schedule = {{0.0, 0.0}, {0.02, 0.0}, {0.02, 6.0}, {0.06, -6.0}, {0.06, 3.0}};
  return h;
}

class ExactBudget : public ::testing::TestWithParam<BudgetCase> {};

TEST_P(ExactBudget, MomentumAndEnergyChangeOnlyAsThePhysicsSays) {
  const BudgetCase k = GetParam();
  SystemParams p = make_system(500, k.area_fraction, k.restitution, k.shear_velocity);
  p.tc_duration = k.tc_duration;
  p.shear_history = k.history;
  Simulation<2> sim = make_simulation(p, 41);
  sim.start_production(k.restitution);  // the protocol runs from here
  Budget budget;
  budget.sim = &sim;
  sim.add_observer(&budget);
  const Totals before = totals(sim.state());
  sim.run(kInf, collisions_for(p, 40.0));
  const Totals after = totals(sim.state());
  ASSERT_GE(budget.collisions, 20000);
  const double energy_residual = (after.energy - before.energy - budget.energy) / (before.energy + budget.magnitude);
  const double momentum_residual = (after.px - before.px - budget.momentum_x) / (before.scale + after.scale);
  std::printf("ν = %.2f, ẽ = %.2f, U = %g: %lld collisions, %lld boundary crossings; energy %.6g → %.6g, budget residual "
              "%.2e; momentum residuals x %.2e, y %.2e\n",
              k.area_fraction, k.restitution, k.shear_velocity, static_cast<long long>(budget.collisions),
              static_cast<long long>(budget.crossings), before.energy, after.energy, energy_residual, momentum_residual,
              (after.py - before.py) / (before.scale + after.scale));
  EXPECT_EQ(budget.wrong_crossing_shifts, 0);
  EXPECT_EQ(budget.wrong_image_velocities, 0);
  EXPECT_LT(std::abs(energy_residual), 1e-12);
  EXPECT_LT(std::abs(momentum_residual), 1e-13);
  EXPECT_LT(std::abs(after.py - before.py) / (before.scale + after.scale), 1e-13);
  if (k.shear_velocity != 0.0) {
    EXPECT_GT(budget.crossings, 100);
  }
}

INSTANTIATE_TEST_SUITE_P(Boxes, ExactBudget,
                         ::testing::Values(BudgetCase{0.3, 0.8, 0.0, 0.0}, BudgetCase{0.3, 0.8, 4.0, 1e-5},
                                           BudgetCase{0.05, 0.6, 10.0, 1e-6}, BudgetCase{0.5, 1.0, -3.0, 0.0},
                                           BudgetCase{0.2, 0.7, 6.0, 1e-6, ramp_and_kick()},
                                           BudgetCase{0.2, 1.0, 3.0, 0.0, steps_through_zero()}));

}  // namespace
}  // namespace granule
