// Coarse-grained fields on 3D grids and with per-particle masses, against independent references:
// exact laws (a uniform flow has no temperature, Galilean invariance), a Maxwellian sample's known T
// within its standard error, a linear shear profile, and brute-force sums over the particles.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>

#include "analysis/cell_fields.hpp"
#include "init/random.hpp"

namespace granule {
namespace {

FieldGrid cube_grid(int n, double length) { return {n, n, length, length, n, length, 3}; }

// n spheres uniform in the box, velocities drift + √T₀ × standard normal per component.
ParticleState maxwellian_spheres(Random& random, std::size_t n, const FieldGrid& box, std::array<double, 3> drift, double t0) {
  ParticleState s;
  s.dimension = 3;
  s.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    s.x[i] = box.length_x * random.uniform();
    s.y[i] = box.length_y * random.uniform();
    s.z[i] = box.length_z * random.uniform();
    for (int a = 0; a < 3; ++a) s.velocity(a)[i] = drift[a] + std::sqrt(t0) * random.normal();
  }
  return s;
}

CellFields fields_of(const ParticleState& s, const FieldGrid& grid, const ShearFrame& frame, bool subtract = false,
                     double shear_offset = 0.0) {
  CellMoments m(grid);
  m.add(s, frame, subtract);
  return fields_from_moments(m, frame, shear_offset, subtract);
}

TEST(CellFields3d, UniformFlowHasItsVelocityAndNoTemperatureStressOrHeatFlux) {
  Random random(11);
  const FieldGrid grid = cube_grid(3, 2.0);
  ParticleState s = maxwellian_spheres(random, 600, grid, {0.0, 0.0, 0.0}, 0.0);
  for (std::size_t i = 0; i < s.size(); ++i) {
    s.vx[i] = 0.75;
    s.vy[i] = -1.5;
    s.vz[i] = 2.25;
  }
  const CellFields f = fields_of(s, grid, ShearFrame{2.0, 2.0, 0.0});
  double particles = 0.0;
  for (std::size_t c = 0; c < grid.cells(); ++c) {
    particles += f.count[c];
    EXPECT_DOUBLE_EQ(f.density[c], f.count[c] / std::pow(2.0 / 3.0, 3)) << "density is per unit volume";
    if (f.count[c] == 0.0) continue;
    EXPECT_DOUBLE_EQ(f.velocity_x[c], 0.75);
    EXPECT_DOUBLE_EQ(f.velocity_y[c], -1.5);
    EXPECT_DOUBLE_EQ(f.velocity_z[c], 2.25);
    for (const auto* v : {&f.temperature, &f.kinetic_xx, &f.kinetic_xz, &f.kinetic_yz, &f.kinetic_zz, &f.pressure_kinetic,
                          &f.heat_flux_kinetic_x, &f.heat_flux_kinetic_z, &f.vorticity}) {
      EXPECT_NEAR((*v)[c], 0.0, 1e-12);
    }
  }
  EXPECT_EQ(particles, 600.0);
}

TEST(CellFields3d, MaxwellianTemperaturePerDegreeOfFreedomWithinItsStandardError) {
  // T̂ of n samples of a 3D Maxwellian at T₀ (unit mass) has standard error T₀ √(2 / (3 n)).
  Random random(2024);
  const double t0 = 0.7;
  const std::size_t n = 30000;
  const FieldGrid box = cube_grid(1, 1.0);
  const ParticleState s = maxwellian_spheres(random, n, box, {0.3, -0.2, 0.1}, t0);
  const CellFields f = fields_of(s, box, ShearFrame{1.0, 1.0, 0.0});
  const double standard_error = t0 * std::sqrt(2.0 / (3.0 * n));
  std::printf("Maxwellian n = %zu: T = %.5f against T0 = %.5f (standard error %.5f); p/(n T) = %.15f\n", n,
              f.temperature[0], t0, standard_error, f.pressure_kinetic[0] / (f.density[0] * f.temperature[0]));
  EXPECT_NEAR(f.temperature[0], t0, 3.0 * standard_error);
  // Each diagonal stress over ρ is one component's variance: standard error T₀ √(2/n).
  for (const double tau : {f.kinetic_xx[0], f.kinetic_yy[0], f.kinetic_zz[0]}) EXPECT_NEAR(tau / f.density[0], t0, 3.0 * t0 * std::sqrt(2.0 / n));
  // Off-diagonal ⟨v'_a v'_b⟩ has standard error T₀/√n; p = ρ T exactly.
  for (const double tau : {f.kinetic_xy[0], f.kinetic_xz[0], f.kinetic_yz[0]}) EXPECT_NEAR(tau / f.density[0], 0.0, 3.0 * t0 / std::sqrt(n));
  EXPECT_NEAR(f.pressure_kinetic[0], f.density[0] * f.temperature[0], 1e-12 * f.pressure_kinetic[0]);
  // A Maxwellian's heat flux vanishes: ½⟨|v'|² v'_a⟩ has standard error ½ √(15) T₀^{3/2} / √n.
  const double flux_error = 0.5 * std::sqrt(15.0) * std::pow(t0, 1.5) / std::sqrt(n);
  for (const double q : {f.heat_flux_kinetic_x[0], f.heat_flux_kinetic_y[0], f.heat_flux_kinetic_z[0]}) {
    EXPECT_NEAR(q / f.density[0], 0.0, 3.0 * flux_error);
  }
}

TEST(CellFields3d, TemperatureStressAndHeatFluxAreGalileanInvariant) {
  Random random(5);
  const FieldGrid grid{4, 3, 2.0, 1.5, 2, 1.0, 3};
  const ParticleState s = maxwellian_spheres(random, 5000, grid, {0.0, 0.0, 0.0}, 1.3);
  ParticleState boosted = s;
  const std::array<double, 3> boost{5.0, -3.0, 2.0};
  for (std::size_t i = 0; i < s.size(); ++i) {
    for (int a = 0; a < 3; ++a) boosted.velocity(a)[i] += boost[a];
  }
  const ShearFrame frame{2.0, 1.5, 0.0};
  CellFields rest = fields_of(s, grid, frame), moving = fields_of(boosted, grid, frame);
  for (std::size_t c = 0; c < grid.cells(); ++c) {
    for (int a = 0; a < 3; ++a) {
      EXPECT_NEAR(moving.velocity(a)[c], rest.velocity(a)[c] + boost[a], 1e-12);
      EXPECT_NEAR(moving.heat_flux_kinetic(a)[c], rest.heat_flux_kinetic(a)[c], 1e-9);
      for (int b = 0; b < 3; ++b) EXPECT_NEAR(moving.kinetic(a, b)[c], rest.kinetic(a, b)[c], 1e-10);
    }
    EXPECT_NEAR(moving.temperature[c], rest.temperature[c], 1e-12);
  }
}

TEST(CellFields3d, LinearShearProfileIsRecoveredInVxOfYWithItsVorticity) {
  // v_x = γ (y − L_y/2) + thermal noise: V_x at row centres is γ (y_c − L_y/2) within the sampling
  // error, and ω_z = −γ everywhere, across the Lees–Edwards boundary too (images at ±U = ±γ L_y/2
  // relative to the box centre, offset Δ).
  Random random(77);
  const double gamma = 4.0, noise = 0.1;
  const FieldGrid grid{4, 8, 2.0, 2.0, 2, 1.0, 3};
  ParticleState s = maxwellian_spheres(random, 64000, grid, {0.0, 0.0, 0.0}, noise * noise);
  for (std::size_t i = 0; i < s.size(); ++i) s.vx[i] += gamma * (s.y[i] - 1.0);
  const ShearFrame frame{2.0, 2.0, gamma * 2.0};
  const CellFields f = fields_of(s, grid, frame, false, 0.37);
  const StreamwiseProfiles p = streamwise_profiles(f);
  const double per_row = 64000.0 / grid.ny;
  // Within a row y is uniform over the row's height h: the mean has error γ h/√(12 n) plus noise/√n.
  const double error = std::hypot(gamma * grid.cell_height() / std::sqrt(12.0 * per_row), noise / std::sqrt(per_row));
  double worst = 0.0;
  for (int iy = 0; iy < grid.ny; ++iy) {
    EXPECT_NEAR(p.velocity_x[iy], gamma * (grid.center_y(iy) - 1.0), 4.0 * error) << "row " << iy;
    worst = std::max(worst, std::abs(p.velocity_x[iy] - gamma * (grid.center_y(iy) - 1.0)));
  }
  std::printf("linear shear: worst |V_x(y) - gamma (y - L/2)| = %.2e (standard error %.2e)\n", worst, error);
  // Central differences of the cell means: each difference carries ~√2 of a cell's error over 2h.
  const double cell_error = std::hypot(gamma * grid.cell_height() / std::sqrt(12.0 * per_row / 8.0), noise / std::sqrt(per_row / 8.0));
  for (std::size_t c = 0; c < grid.cells(); ++c) EXPECT_NEAR(f.vorticity[c], -gamma, 5.0 * cell_error / grid.cell_height());
  // Relative to the profile, nothing is left.
  const CellFields relative = fields_of(s, grid, frame, true, 0.37);
  for (double v : streamwise_profiles(relative).velocity_x) EXPECT_NEAR(v, 0.0, 4.0 * error);
}

// Brute-force references over the particles of one cell: M, V = Σ m v / M, Σ m v'_a v'_b and
// Σ ½ m|v'|² v'_a with v' = v − V, straight from the definitions (no moment identities).
struct HandSums {
  double count = 0.0, mass = 0.0;
  std::array<double, 3> velocity{}, heat{};
  std::array<std::array<double, 3>, 3> stress{};
};

HandSums hand_sums(const ParticleState& s, int d) {
  HandSums h;
  for (std::size_t i = 0; i < s.size(); ++i) {
    h.count += 1.0;
    h.mass += s.mass[i];
    for (int a = 0; a < d; ++a) h.velocity[a] += s.mass[i] * s.velocity(a)[i];
  }
  for (int a = 0; a < d; ++a) h.velocity[a] /= h.mass;
  for (std::size_t i = 0; i < s.size(); ++i) {
    std::array<double, 3> c{};
    double c2 = 0.0;
    for (int a = 0; a < d; ++a) {
      c[a] = s.velocity(a)[i] - h.velocity[a];
      c2 += c[a] * c[a];
    }
    for (int a = 0; a < d; ++a) {
      h.heat[a] += 0.5 * s.mass[i] * c2 * c[a];
      for (int b = 0; b < d; ++b) h.stress[a][b] += s.mass[i] * c[a] * c[b];
    }
  }
  return h;
}

ParticleState weighted_particles(Random& random, int d, std::size_t n) {
  ParticleState s;
  s.dimension = d;
  s.diameter.assign(n, 0.0);  // polydisperse: resize() sizes diameter and mass too
  s.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    for (int a = 0; a < d; ++a) {
      s.position(a)[i] = 0.999 * random.uniform();
      s.velocity(a)[i] = 2.0 * random.normal() + (a == 0 ? 1.0 : 0.0);
    }
    s.diameter[i] = 0.01 * (1.0 + random.uniform());
    s.mass[i] = std::pow(s.diameter[i] / 0.01, d);  // m ∝ σ^d, from 1 to 2^d
  }
  return s;
}

void expect_mass_weighted_fields(int d) {
  Random random(31 + d);
  const ParticleState s = weighted_particles(random, d, 40);
  const FieldGrid cell = d == 3 ? FieldGrid{1, 1, 1.0, 1.0, 1, 1.0, 3} : FieldGrid{1, 1, 1.0, 1.0};
  CellFields f = fields_of(s, cell, ShearFrame{1.0, 1.0, 0.0});
  const HandSums h = hand_sums(s, d);
  double trace = 0.0;
  for (int a = 0; a < d; ++a) trace += h.stress[a][a];
  EXPECT_DOUBLE_EQ(f.density[0], 40.0);
  EXPECT_NEAR(f.temperature[0], trace / (d * h.count), 1e-13 * trace);
  EXPECT_NEAR(f.pressure_kinetic[0], trace / d, 1e-13 * trace);
  for (int a = 0; a < d; ++a) {
    EXPECT_NEAR(f.velocity(a)[0], h.velocity[a], 1e-13) << "axis " << a;
    EXPECT_NEAR(f.heat_flux_kinetic(a)[0], h.heat[a], 1e-11 * std::abs(trace)) << "axis " << a;
    for (int b = 0; b < d; ++b) EXPECT_NEAR(f.kinetic(a, b)[0], h.stress[a][b], 1e-12 * trace) << a << b;
  }
}

TEST(CellFields3d, MassWeightedFieldsEqualHandSumsIn3d) { expect_mass_weighted_fields(3); }
TEST(CellFields3d, MassWeightedFieldsEqualHandSumsIn2d) { expect_mass_weighted_fields(2); }

TEST(CellFields3d, UnitMassesGiveTheMonodisperseFieldsBitForBit) {
  Random random(8);
  const FieldGrid grid{3, 2, 1.0, 1.0};
  ParticleState plain;
  plain.resize(500);
  for (std::size_t i = 0; i < plain.size(); ++i) {
    plain.x[i] = random.uniform();
    plain.y[i] = random.uniform();
    plain.vx[i] = random.normal();
    plain.vy[i] = random.normal() - 0.5;
  }
  ParticleState weighted = plain;
  weighted.diameter.assign(500, 0.01);
  weighted.mass.assign(500, 1.0);
  const ShearFrame frame{1.0, 1.0, 0.5};
  CellFields a = fields_of(plain, grid, frame, false, 0.2), b = fields_of(weighted, grid, frame, false, 0.2);
  std::vector<std::vector<double>> values_a, values_b;
  for_each_field(a, [&](const char*, const std::vector<double>& v) { values_a.push_back(v); });
  for_each_field(b, [&](const char*, const std::vector<double>& v) { values_b.push_back(v); });
  EXPECT_EQ(values_a, values_b);
}

TEST(CellFields3d, MomentsSurviveACheckpointWithTheirZComponentsAndMasses) {
  Random random(3);
  const FieldGrid grid = cube_grid(2, 1.0);
  CellMoments m(grid);
  m.add(weighted_particles(random, 3, 100), ShearFrame{1.0, 1.0, 0.0}, false);
  StateArchive archive;
  m.save(archive, "fields/");
  CellMoments restored(grid);
  restored.restore(archive, "fields/");
  EXPECT_EQ(restored.configurations, 1);
  EXPECT_EQ(restored.pzz, m.pzz);
  EXPECT_EQ(restored.energy_flux_z, m.energy_flux_z);
  EXPECT_EQ(restored.mass, m.mass);
}

TEST(CellFields3d, TwoDimensionalCheckpointsKeepTheirEntries) {
  CellMoments m(FieldGrid{2, 2, 1.0, 1.0});
  StateArchive archive;
  m.save(archive, "");
  std::vector<std::string> names;
  for (const auto& [name, values] : archive.arrays()) names.push_back(name);
  EXPECT_EQ(names, (std::vector<std::string>{"configurations", "count", "energy_flux_x", "energy_flux_y", "px", "pxx", "pxy",
                                             "py", "pyy"}));
}

TEST(CellFields3d, RefusesAConfigurationOfTheOtherDimension) {
  CellMoments m(cube_grid(2, 1.0));
  ParticleState disks;
  disks.resize(3);
  EXPECT_THROW(m.add(disks, ShearFrame{1.0, 1.0, 0.0}, false), std::invalid_argument);
}

}  // namespace
}  // namespace granule
