// The collision measurements of spheres and mixtures from hand-made 3D collision records: the
// collisional stress (1.6) with σ_ij per cell of a 3D grid, the collisional heat flux of unequal
// masses against the energy changes of the collision rule itself, the impact parameter as the
// distance of closest approach, free paths with the polar angle cos θ, the local density per unit
// volume, and the isotropy summary of free-path angles.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "observers/collision_statistics_fits.hpp"
#include "observers/collisional_stress.hpp"
#include "observers/free_paths.hpp"
#include "observers/impact_parameters.hpp"
#include "init/random.hpp"
#include "physics/collision_rule.hpp"

namespace granule {
namespace {

CollisionRecord<3> record3(double t, int a, int b, Vec3 contact, Vec3 k, Vec3 v21, double impulse = 1.0) {
  CollisionRecord<3> r;
  r.time = t;
  r.first = a;
  r.second = b;
  r.first_position = contact;
  r.contact_point = contact;
  r.contact_normal = k;
  r.relative_velocity = v21;
  r.impulse = impulse;
  return r;
}

TEST(CollisionalStress3D, EachCollisionAddsSigmaJkkOverCellVolumeAndIntervalInItsCell) {
  const FieldGrid grid{2, 2, 2.0, 1.0, 2, 0.5, 3};  // cells 1 × 0.5 × 0.25
  CollisionalStressField<3> field(grid, 0.1);
  field.restart(1.0);
  const Vec3 k{1.0 / 3.0, 2.0 / 3.0, 2.0 / 3.0};
  field.on_collision(record3(1.5, 0, 1, {1.5, 0.75, 0.4}, k, {1.0, 0.0, 0.0}, 2.0));  // cell (1, 1, 1) = 7
  const CollisionalStress c = field.stress(3.0);
  const double scale = 0.1 * 2.0 / (0.125 * 2.0);  // σ J / (V t)
  EXPECT_NEAR(c.xx[7], scale / 9.0, 1e-15);
  EXPECT_NEAR(c.yy[7], scale * 4.0 / 9.0, 1e-15);
  EXPECT_NEAR(c.zz[7], scale * 4.0 / 9.0, 1e-15);
  EXPECT_NEAR(c.xy[7], scale * 2.0 / 9.0, 1e-15);
  EXPECT_NEAR(c.xz[7], scale * 2.0 / 9.0, 1e-15);
  EXPECT_NEAR(c.yz[7], scale * 4.0 / 9.0, 1e-15);
  EXPECT_NEAR(c.pressure(7), scale / 3.0, 1e-15);  // Tr k̂k̂ = 1
  EXPECT_DOUBLE_EQ(c.collisions[7], 1.0);
  for (std::size_t cell = 0; cell < 7; ++cell) EXPECT_EQ(c.zz[cell], 0.0);
}

TEST(CollisionalHeatFlux3D, UnequalMassesCarryHalfTheDifferenceOfTheEnergyChangesOverSigmaIJ) {
  // Reference: the energy changes ΔE₁, ΔE₂ of the peculiar velocities from the unequal-mass rule,
  // the flux σ_ij/(V t) k̂ (ΔE₂ − ΔE₁)/2, and the stress σ_ij J k̂k̂/(V t) with J = m₂ |Δv₂|.
  const double sigma1 = 0.04, sigma2 = 0.06, m1 = 1.0, m2 = 3.375, e = 0.8, t = 2.0;
  const double sigma12 = 0.5 * (sigma1 + sigma2);
  const Vec3 v1{1.5, -0.4, 0.7}, v2{-0.9, 0.3, -0.2}, reference{0.3, -0.1, 0.25};
  const Vec3 k = (1.0 / std::sqrt(14.0)) * Vec3{1.0, 2.0, 3.0};  // v₂₁·k̂ > 0: approaching
  const FieldGrid grid{1, 1, 1.0, 1.0, 1, 1.0, 3};
  CollisionalStressField<3> field(grid, std::nullopt);  // polydisperse: σ_ij from each record
  field.restart(0.0);
  CollisionRecord<3> r;
  r.first_position = {0.5, 0.5, 0.5};
  r.contact_point = r.first_position + (0.5 * sigma1) * k;
  r.contact_normal = k;
  r.first_velocity_before = v1;
  r.second_velocity_before = v2;
  r.relative_velocity = v1 - v2;
  r.impulse = normal_impulse(r.relative_velocity, k, e, m1, m2);
  const PostCollisionVelocities<3> after = collide(v1, v2, k, e, m1, m2);
  r.first_velocity_after = after.v1;
  r.second_velocity_after = after.v2;
  r.contact_distance = sigma12;
  r.first_mass = m1;
  r.second_mass = m2;
  ASSERT_NEAR(m2 * norm(after.v2 - v2), r.impulse, 1e-14);
  field.on_collision(r);
  const CollisionalStress stress = field.stress(t);
  const std::vector<double> reference_x{reference.x}, reference_y{reference.y}, reference_z{reference.z};
  const HeatFlux q = collisional_heat_flux(stress, reference_x, reference_y, reference_z);
  const auto energy = [&](double m, Vec3 v) { return 0.5 * m * norm2(v - reference); };
  const double de1 = energy(m1, after.v1) - energy(m1, v1);
  const double de2 = energy(m2, after.v2) - energy(m2, v2);
  const double carried = 0.5 * (de2 - de1) * sigma12 / t;
  for (int a = 0; a < 3; ++a) {
    EXPECT_NEAR(q.component(a)[0], carried * k[a], 1e-14) << "axis " << a;
    for (int b = 0; b < 3; ++b) EXPECT_NEAR(stress.component(a, b)[0], sigma12 * r.impulse * k[a] * k[b] / t, 1e-14);
  }
}

TEST(ImpactParameter3D, IsTheDistanceOfClosestApproachAndItsSquareIsTheUniformVariable) {
  const double sigma = 0.02;
  const Vec3 k{0.0, 0.0, 1.0};
  EXPECT_NEAR(impact_parameter(record3(0, 0, 1, {}, k, {0.0, 0.0, 3.0}), sigma), 0.0, 1e-18);
  EXPECT_NEAR(impact_parameter(record3(0, 0, 1, {}, k, {1.0, -2.0, 0.0}), sigma), sigma, 1e-18);
  // v₂₁ at 0.3 rad from k̂, in an oblique plane: the straight relative path passes at σ sin 0.3.
  const double angle = 0.3, phi = 1.1;
  const Vec3 v = 4.0 * Vec3{std::sin(angle) * std::cos(phi), std::sin(angle) * std::sin(phi), std::cos(angle)};
  const CollisionRecord<3> oblique = record3(0, 0, 1, {}, k, v);
  EXPECT_NEAR(impact_parameter(oblique, sigma), sigma * std::sin(angle), 1e-15);
  EXPECT_NEAR(uniform_impact_variable(oblique, sigma), std::sin(angle) * std::sin(angle), 1e-15);
}

TEST(ImpactParameterStatistics3D, PolydisperseRecordsAreMeasuredInUnitsOfTheirOwnSigmaIJ) {
  const FieldGrid grid{1, 1, 1.0, 1.0, 2, 2.0, 3};  // two layers of volume 1
  LocalDensity density(grid);
  ParticleState s;
  s.dimension = 3;
  s.x = {0.1, 0.2, 0.3};
  s.y = {0.5, 0.5, 0.5};
  s.z = {0.5, 0.6, 1.5};  // two spheres in the lower layer, one in the upper
  s.vx = s.vy = s.vz = {0, 0, 0};
  density.update(s);
  EXPECT_DOUBLE_EQ(density.at(Vec3{0.5, 0.5, 0.2}), 2.0);
  EXPECT_DOUBLE_EQ(density.at(Vec3{0.5, 0.5, 1.9}), 1.0);
  ImpactParameterStatistics<3> stats(std::nullopt, 4, 10, {{1.5, 3.0}}, &density);
  const double angle = std::asin(std::sqrt(0.6));  // (b/σ_ij)² = 0.6: bin 2 of 4
  CollisionRecord<3> r = record3(1.0, 0, 1, {0.5, 0.5, 0.5}, {0, 0, 1}, {std::sin(angle), 0, std::cos(angle)});
  r.contact_distance = 0.07;
  stats.on_collision(r);
  r.contact_point.z = 1.5;  // the dilute layer: outside the density window
  stats.on_collision(r);
  EXPECT_EQ(stats.total(), (std::vector<double>{0, 0, 2, 0}));
  EXPECT_EQ(stats.by_density()[0], (std::vector<double>{0, 0, 1, 0}));
}

TEST(FreePathStatistics3D, PathsAreBinnedByLengthAndByTheCosineOfTheirAngleToTheFlow) {
  FreePathSettings settings;
  settings.length_bins = 10;
  settings.angle_bins = 4;  // cos θ in [−1, −½), [−½, 0), [0, ½), [½, 1]
  settings.max_length = 10.0;
  FreePathStatistics<3> paths(3, settings, nullptr);
  paths.start();
  CollisionRecord<3> a = record3(1.0, 0, 1, {}, {1, 0, 0}, {1, 0, 0});
  a.first_velocity_after = {0.0, 0.0, 2.0};  // particle 0 flies along z: cos θ = 0
  a.second_velocity_after = {3.0, 0.0, 0.0};  // particle 1 along the flow: cos θ = 1
  paths.on_collision(a);
  CollisionRecord<3> b = record3(3.5, 0, 1, {}, {1, 0, 0}, {1, 0, 0});
  paths.on_collision(b);  // 0 flew 2 × 2.5 = 5, 1 flew 3 × 2.5 = 7.5
  EXPECT_DOUBLE_EQ(paths.total().paths, 2.0);
  EXPECT_DOUBLE_EQ(paths.total().sum_length, 12.5);
  EXPECT_DOUBLE_EQ(paths.total().counts[5 * 4 + 2], 1.0);  // length bin 5, cos θ = 0 in [0, ½)
  EXPECT_DOUBLE_EQ(paths.total().counts[7 * 4 + 3], 1.0);  // length bin 7, cos θ = 1 in the last bin
  EXPECT_EQ(paths.angle_bins().low, -1.0);
  EXPECT_EQ(paths.angle_bins().high, 1.0);
}

TEST(FreePathSummary3D, IsotropicDirectionsAreUniformInCosThetaAndAlignedOnesAreNot) {
  // Directions uniform on the sphere (normalised Gaussian vectors) against directions crowded
  // towards the flow axis (x stretched by 3).
  Random random(5);
  const UniformBins lengths{0.0, 1.0, 10}, angles = free_path_angle_bins(3, 40);
  const auto histogram = [&](double stretch_x) {
    PathHistogram h;
    h.counts.assign(10 * 40, 0.0);
    h.overflow.assign(40, 0.0);
    for (int i = 0; i < 100000; ++i) {
      const Vec3 v{stretch_x * random.normal(), random.normal(), random.normal()};
      const int a = std::min(39, angles.bin(v.x / norm(v)));
      h.counts[static_cast<std::size_t>(a)] += 1.0;  // length bin 0
      h.paths += 1.0;
      h.sum_length += 0.05;
    }
    return summarize_free_paths(h, lengths, angles, 3);
  };
  const FreePathSummary isotropic = histogram(1.0), aligned = histogram(3.0);
  EXPECT_LT(isotropic.ks_isotropic, 1.63 / std::sqrt(1e5));  // the 1% Kolmogorov critical value
  EXPECT_GT(aligned.ks_isotropic, 0.1);
  EXPECT_TRUE(std::isnan(isotropic.alpha0));
  EXPECT_NEAR(isotropic.angular_fit[19], 0.5, 1e-15);  // (1 + cos θ)/2 at cos θ = 0
}

}  // namespace
}  // namespace granule
