// The collisional heat flux q^(c) (observers/collisional_stress.hpp, docs/macrostructure.md) on
// real trajectories:
//  • exact budget: summed over the cells, the per-cell energy transfer equals the global sum over
//    the collision records, written here independently with the image velocity U (the observer
//    itself needs no U), to round-off, in a Lees–Edwards run with thousands of boundary contacts;
//  • an elastic gas at equilibrium carries no heat: the mean of q^(c) over blocks of the run is 0
//    within 4 standard errors, in a gas drifting at W = (3, −2) (the flux must be taken about the
//    local mean velocity: the lab-frame transfer alone is τ^(c)·W, hundreds of standard errors off).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "observers/collisional_stress.hpp"
#include "validation/simulation_setup.hpp"

namespace granule {
namespace {

// Σ J k̂ (k̂·s) with s the pair velocity in the lab frame of the contact point's cell, from U.
struct GlobalEnergyTransfer final : EventObserver<2> {
  double shear_velocity = 0.0, diameter = 0.0, length_y = 1.0;
  Vec2 sum{0.0, 0.0};
  double magnitude = 0.0;
  std::int64_t mapped_contacts = 0, image_contacts = 0;
  void on_collision(const CollisionRecord<2>& r) override {
    Vec2 s = 0.5 * (r.first_velocity_before + r.second_velocity_before);
    s.x += 0.5 * r.image_y * shear_velocity;  // the partner is an image moving at v₂ + i_y U
    const double unmapped_y = r.first_position.y + 0.5 * diameter * r.contact_normal.y;
    if (unmapped_y >= length_y || unmapped_y < 0.0) {
      // The contact point is mapped through the top (bottom): velocities change by ∓U with it.
      s.x -= (unmapped_y >= length_y ? 1.0 : -1.0) * shear_velocity;
      ++mapped_contacts;
    }
    if (r.image_y != 0) ++image_contacts;
    const double carried = r.impulse * dot(r.contact_normal, s);
    sum = sum + carried * r.contact_normal;
    magnitude += std::abs(carried);
  }
};

TEST(CollisionalHeatFlux, CellsSumToTheGlobalTransferOfTheRecordsUnderLeesEdwards) {
  const SystemParams p = make_system(500, 0.3, 0.8, 4.0);
  Simulation<2> sim = make_simulation(p, 17);
  const FieldGrid grid{4, 5, p.length_x, p.length_y};
  CollisionalStressField<2> field(grid, p.diameter);
  GlobalEnergyTransfer global;
  global.shear_velocity = p.shear_velocity;
  global.diameter = p.diameter;
  global.length_y = p.length_y;
  sim.add_observer(&field);
  sim.add_observer(&global);
  sim.run(kInf, collisions_for(p, 100.0));
  const CollisionalStress s = field.stress(sim.time());
  Vec2 cells{0.0, 0.0};
  for (std::size_t c = 0; c < grid.cells(); ++c) cells = cells + Vec2{s.energy_x[c], s.energy_y[c]};
  const double to_sums = grid.cell_area() * s.interval / p.diameter;  // undo σ/(V t)
  const double rx = (cells.x * to_sums - global.sum.x) / global.magnitude;
  const double ry = (cells.y * to_sums - global.sum.y) / global.magnitude;
  std::printf("Lees–Edwards U = 4: %lld collisions, %lld with an image partner, %lld contacts mapped; relative residuals "
              "%.2e, %.2e\n",
              static_cast<long long>(sim.collisions()), static_cast<long long>(global.image_contacts),
              static_cast<long long>(global.mapped_contacts), rx, ry);
  EXPECT_GT(global.mapped_contacts, 250);
  EXPECT_LT(std::abs(rx), 1e-13);
  EXPECT_LT(std::abs(ry), 1e-13);
}

TEST(CollisionalHeatFlux, DriftingElasticGasAtEquilibriumCarriesNoHeat) {
  SystemParams p = make_system(500, 0.3, 1.0);
  const Vec2 drift{3.0, -2.0};
  auto init = make_initial_state(p, 1.0, 23, Placement::kAuto);
  ASSERT_TRUE(init.error.empty()) << init.error;
  for (std::size_t i = 0; i < init.state.size(); ++i) init.state.vx[i] += drift.x, init.state.vy[i] += drift.y;
  const auto engine_grid = choose_cell_grid({p.length_x, p.length_y, p.diameter, p.particles, false, 1.0, std::nullopt});
  Simulation<2> sim(p, *engine_grid.grid, init.state);
  sim.run(kInf, collisions_for(p, 5.0));  // forget the initial state
  const FieldGrid box{1, 1, p.length_x, p.length_y};
  CollisionalStressField<2> field(box, p.diameter);
  sim.add_observer(&field);
  // 40 blocks of 2 collisions per disk: block means of q^(c) about the drift, and of the lab-frame transfer.
  const int blocks = 40;
  std::vector<double> qx, qy;
  double lab_x = 0.0, pressure = 0.0;
  for (int b = 0; b < blocks; ++b) {
    field.restart(sim.time());
    sim.run(kInf, sim.collisions() + collisions_for(p, 2.0));
    const CollisionalStress s = field.stress(sim.time());
    const HeatFlux q = collisional_heat_flux(s, {drift.x}, {drift.y});
    qx.push_back(q.x[0]);
    qy.push_back(q.y[0]);
    lab_x += s.energy_x[0] / blocks;
    pressure += 0.5 * (s.xx[0] + s.yy[0]) / blocks;
  }
  const auto mean_and_error = [&](const std::vector<double>& v) {
    double m = 0.0, m2 = 0.0;
    for (double x : v) m += x / blocks;
    for (double x : v) m2 += (x - m) * (x - m) / (blocks - 1);
    return std::pair{m, std::sqrt(m2 / blocks)};
  };
  const auto [mx, ex] = mean_and_error(qx);
  const auto [my, ey] = mean_and_error(qy);
  std::printf("elastic ν = 0.3 drifting at (3, −2): q^(c) = (%.3g ± %.2g, %.3g ± %.2g); lab-frame transfer x %.3g "
              "(P^(c) W_x = %.3g)\n",
              mx, ex, my, ey, lab_x, pressure * drift.x);
  EXPECT_LT(std::abs(mx), 4.0 * ex);
  EXPECT_LT(std::abs(my), 4.0 * ey);
  // The test can see a flux: the lab-frame transfer is P^(c) W, far outside those errors.
  EXPECT_GT(std::abs(lab_x), 100.0 * ex);
}

}  // namespace
}  // namespace granule
