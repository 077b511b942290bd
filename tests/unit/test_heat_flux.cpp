// The heat-flux fields q = q^(k) + q^(c) (docs/macrostructure.md) against hand-computed values,
// direct sums over particles, the analytic standard error of a Maxwellian sample, and the energy
// changes of a single collision (the form the collisional flux is derived from).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "analysis/cell_fields.hpp"
#include "observers/collisional_stress.hpp"
#include "init/random.hpp"
#include "physics/collision_rule.hpp"
#include "unit/particle_rows.hpp"

namespace granule {
namespace {

TEST(KineticHeatFlux, HandBuiltThirdMomentIsExactAndGalileanInvariant) {
  // Box 2 × 2, cells 2 × 1 (each 1 × 2).  Left cell: v = (1,0), (3,2), (−1,1): V = (1,1),
  // c = (0,−1), (2,1), (−2,0), |c|² = 1, 5, 4; Σ ½|c|² c = ½ (0 + 10 − 8, −1 + 5 + 0) = (1, 2);
  // over the cell area 2: q^(k) = (0.5, 1).  The right cell's lone disk carries no flux.
  const FieldGrid grid{2, 1, 2.0, 2.0};
  const ShearFrame frame{2.0, 2.0, 0.0};
  for (const double drift : {0.0, 1e3}) {
    const ParticleState s = particles_from_rows(
        {{0.2, 0.5, 1.0 + drift, 0.0}, {0.7, 1.5, 3.0 + drift, 2.0}, {0.5, 1.0, -1.0 + drift, 1.0}, {1.5, 1.0, 4.0, -2.0}});
    CellMoments m(grid);
    m.add(s, frame, false);
    const CellFields f = fields_from_moments(m, frame, 0.0, false);
    const double tolerance = 1e-14 * (1.0 + drift * drift * drift);  // the raw third moments are O(drift³)
    EXPECT_NEAR(f.heat_flux_kinetic_x[0], 0.5, tolerance) << "drift " << drift;
    EXPECT_NEAR(f.heat_flux_kinetic_y[0], 1.0, tolerance) << "drift " << drift;
    EXPECT_EQ(f.heat_flux_kinetic_x[1], 0.0);
    EXPECT_EQ(f.heat_flux_kinetic_y[1], 0.0);
  }
}

TEST(KineticHeatFlux, IntervalAverageIsTheDirectSumAboutTheIntervalMeanVelocity) {
  // Moments of two configurations add: q^(k) = Σ_all ½|v − V|²(v − V) / (K · cell area), V the mean
  // over both (mass-weighted, as the other averaged fields).  Reference: the sum written out.
  const FieldGrid grid{1, 1, 1.0, 1.0};
  const ShearFrame frame{1.0, 1.0, 0.0};
  const ParticleState a = particles_from_rows({{0.1, 0.1, 1.0, 0.5}, {0.6, 0.3, -2.0, 1.5}, {0.4, 0.9, 0.25, -1.0}});
  const ParticleState b = particles_from_rows({{0.3, 0.2, 3.0, 0.0}, {0.8, 0.7, 0.5, -0.5}});
  CellMoments m(grid);
  m.add(a, frame, false);
  m.add(b, frame, false);
  const CellFields f = fields_from_moments(m, frame, 0.0, false);
  double vx = 0, vy = 0;
  for (const ParticleState* s : {&a, &b}) {
    for (std::size_t i = 0; i < s->size(); ++i) vx += s->vx[i], vy += s->vy[i];
  }
  vx /= 5.0;
  vy /= 5.0;
  double qx = 0, qy = 0;
  for (const ParticleState* s : {&a, &b}) {
    for (std::size_t i = 0; i < s->size(); ++i) {
      const double cx = s->vx[i] - vx, cy = s->vy[i] - vy;
      qx += 0.5 * (cx * cx + cy * cy) * cx;
      qy += 0.5 * (cx * cx + cy * cy) * cy;
    }
  }
  EXPECT_NEAR(f.heat_flux_kinetic_x[0], qx / 2.0, 1e-13);
  EXPECT_NEAR(f.heat_flux_kinetic_y[0], qy / 2.0, 1e-13);
  // The profile of a single row is the cell's own flux.
  const StreamwiseProfiles p = streamwise_profiles(f);
  EXPECT_DOUBLE_EQ(p.heat_flux_kinetic_x[0], f.heat_flux_kinetic_x[0]);
}

TEST(KineticHeatFlux, DriftingAnisotropicMaxwellianHasNoFluxWithinItsStandardError) {
  // v = W + (√T_x ξ, √T_y η): every odd central moment vanishes, so q^(k) has mean 0.  Per disk
  // ½|c|²c_x has variance ¼⟨|c|⁴c_x²⟩ = ¼(15T_x³ + 6T_x²T_y + 3T_xT_y²) (Gaussian moments), but
  // taking c about the cell's own mean removes its regression on c_x, a = (3T_x + T_y)/2, leaving
  // ¼(15T_x³ + 6T_x²T_y + 3T_xT_y²) − a²T_x = ½T_x(3T_x² + T_y²) to leading order in 1/n.
  // Over 100 cells × 2 components Σ z² is χ² with 200 degrees of freedom: 0.1% bounds 140.7–272.4.
  const double tx = 2.0, ty = 0.5;
  const FieldGrid grid{10, 10, 1.0, 1.0};
  const ShearFrame frame{1.0, 1.0, 0.0};
  Random random(2024);
  ParticleState s = uniform_positions(random, 200000, 1.0, 1.0);
  for (std::size_t i = 0; i < s.size(); ++i) {
    s.vx[i] = 7.0 + std::sqrt(tx) * random.normal();
    s.vy[i] = -3.0 + std::sqrt(ty) * random.normal();
  }
  CellMoments m(grid);
  m.add(s, frame, false);
  const CellFields f = fields_from_moments(m, frame, 0.0, false);
  const double var_x = 0.5 * tx * (3 * tx * tx + ty * ty);
  const double var_y = 0.5 * ty * (3 * ty * ty + tx * tx);
  double chi2 = 0.0;
  for (std::size_t c = 0; c < grid.cells(); ++c) {
    const double se = std::sqrt(f.count[c]) / grid.cell_area();
    chi2 += f.heat_flux_kinetic_x[c] * f.heat_flux_kinetic_x[c] / (var_x * se * se);
    chi2 += f.heat_flux_kinetic_y[c] * f.heat_flux_kinetic_y[c] / (var_y * se * se);
  }
  std::printf("Maxwellian q^(k): chi2 = %.1f over 200 cell components (0.1%% bounds 140.7-272.4)\n", chi2);
  EXPECT_GT(chi2, 140.7);
  EXPECT_LT(chi2, 272.4);
}

// A collision record as the engine writes it, for disks inside the box.
CollisionRecord<2> record_of(Vec2 r1, Vec2 v1, Vec2 v2_partner, Vec2 k_hat, double diameter, double e) {
  CollisionRecord<2> r;
  r.first_position = r1;
  r.contact_point = r1 + (0.5 * diameter) * k_hat;
  r.contact_normal = k_hat;
  r.first_velocity_before = v1;
  r.second_velocity_before = v2_partner;
  r.relative_velocity = v1 - v2_partner;
  r.impulse = normal_impulse(r.relative_velocity, k_hat, e);
  const PostCollisionVelocities after = collide(v1, v2_partner, k_hat, e);
  r.first_velocity_after = after.v1;
  r.second_velocity_after = after.v2;
  r.restitution = e;
  return r;
}

TEST(CollisionalHeatFlux, OneCollisionCarriesHalfTheDifferenceOfTheEnergyChangesOverSigma) {
  // Reference: the local energy changes ΔE₁, ΔE₂ of the peculiar velocities c = v − V (before and
  // after, from the collision rule (1.2)); the flux is σ/(A t) k̂ (ΔE₂ − ΔE₁)/2.
  const double sigma = 0.05, e = 0.7, t = 2.5;
  const Vec2 v1{2.0, 0.5}, v2{-1.0, 0.3}, k{0.6, 0.8}, reference{0.4, -0.2};
  const FieldGrid grid{1, 1, 1.0, 1.0};
  CollisionalStressField<2> field(grid, sigma);
  field.restart(0.0);
  const CollisionRecord<2> r = record_of({0.3, 0.4}, v1, v2, k, sigma, e);
  field.on_collision(r);
  const CollisionalStress stress = field.stress(t);
  const HeatFlux q = collisional_heat_flux(stress, {reference.x}, {reference.y});
  const auto energy = [&](Vec2 v) { return 0.5 * dot(v - reference, v - reference); };
  const double de1 = energy(r.first_velocity_after) - energy(v1);
  const double de2 = energy(r.second_velocity_after) - energy(v2);
  const double carried = 0.5 * (de2 - de1) * sigma / t;
  EXPECT_NEAR(q.x[0], carried * k.x, 1e-15);
  EXPECT_NEAR(q.y[0], carried * k.y, 1e-15);
  // The loss (ΔE₁ + ΔE₂) is not part of the flux: it is the (1 − e²)/4 (v₂₁·k̂)² of (1.2).
  EXPECT_NEAR(de1 + de2, -0.25 * (1 - e * e) * dot(v1 - v2, k) * dot(v1 - v2, k), 1e-14);
  EXPECT_NEAR(stress.xx[0], r.impulse * k.x * k.x * sigma / t, 1e-15);
}

TEST(CollisionalHeatFlux, PairAcrossTheLeesEdwardsBoundaryIsTakenInTheFrameOfTheContactCell) {
  // Disk 1 near the top hits the upper image of disk 2, which moves at v₂ + U.  If the contact
  // point lies above the top it is mapped into the bottom row, where disk 2 itself moves at v₂ and
  // disk 1's image at v₁ − U: the pair moves at (v₁ − U + v₂)/2 there.  Below the top it stays in
  // disk 1's frame: (v₁ + v₂ + U)/2.
  const double sigma = 0.1, length_y = 1.0, u = 3.0;
  const Vec2 v1{0.5, 1.0}, v2{-0.2, -0.7}, k{0.0, 1.0};
  const Vec2 image_velocity{v2.x + u, v2.y};
  CollisionRecord<2> above = record_of({0.5, 0.98}, v1, image_velocity, k, sigma, 0.9);
  above.second_velocity_before = v2;  // the record holds disk 2's own velocity
  above.image_y = 1;
  above.contact_point = {0.5 + 0.37, 0.98 + 0.05 - length_y};  // mapped: shifted by Δ = 0.37 and down by L_y
  const Vec2 s_above = pair_velocity_at_contact(above, sigma, length_y);
  EXPECT_NEAR(s_above.x, 0.5 * (v1.x - u + v2.x), 1e-15);
  EXPECT_NEAR(s_above.y, 0.5 * (v1.y + v2.y), 1e-15);
  CollisionRecord<2> below = record_of({0.5, 0.92}, v1, image_velocity, k, sigma, 0.9);
  below.second_velocity_before = v2;
  below.image_y = 1;
  const Vec2 s_below = pair_velocity_at_contact(below, sigma, length_y);
  EXPECT_NEAR(s_below.x, 0.5 * (v1.x + v2.x + u), 1e-15);
  EXPECT_NEAR(s_below.y, 0.5 * (v1.y + v2.y), 1e-15);
}

TEST(CollisionalHeatFlux, ProfileSubtractedFieldsTakeTheFluxAboutTheMeanFlowAtTheCellCentre) {
  // Fields measured relative to u(y) = γ (y − L_y/2): V(r) is relative, the collision sums are in
  // the lab frame, so the reference becomes V(r) + u(y_cell).  One collision in the upper of two rows.
  const double sigma = 0.05;
  const FieldGrid grid{1, 2, 1.0, 1.0};
  const ShearFrame frame{1.0, 1.0, 4.0};  // u(0.75) = 1
  CollisionalStressField<2> field(grid, sigma);
  const Vec2 k{0.8, 0.6};
  field.on_collision(record_of({0.5, 0.7}, {2.0, 0.0}, {0.0, 0.0}, k, sigma, 1.0));
  const CollisionalStress stress = field.stress(1.0);
  CellFields average;
  average.grid = grid;
  for_each_field(average, [](const char*, std::vector<double>& v) { v.assign(2, 0.0); });
  average.velocity_x = {0.0, 0.5};
  const HeatFlux relative = collisional_heat_flux(stress, average, frame, true);
  const HeatFlux lab = collisional_heat_flux(stress, {0.0, 1.5}, {0.0, 0.0});
  EXPECT_DOUBLE_EQ(relative.x[1], lab.x[1]);
  EXPECT_DOUBLE_EQ(relative.y[1], lab.y[1]);
  EXPECT_EQ(relative.x[0], 0.0);
}

}  // namespace
}  // namespace granule
