// Coarse-grained fields of thesis §1.4.3 against hand-computed values and exact sum rules.
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "analysis/cell_fields.hpp"
#include "init/random.hpp"
#include "unit/particle_rows.hpp"

namespace granule {
namespace {

TEST(CellFields, HandBuiltConfiguration) {
  // Box 2 × 2, cells 2 × 1 (each 1 × 2): three disks in the left cell, one in the right.
  const FieldGrid grid{2, 1, 2.0, 2.0};
  const ShearFrame frame{2.0, 2.0, 0.0};
  const ParticleState s = particles_from_rows({{0.2, 0.5, 1.0, 0.0}, {0.7, 1.5, 3.0, 2.0}, {0.5, 1.0, -1.0, 1.0}, {1.5, 1.0, 4.0, -2.0}});
  CellMoments m(grid);
  m.add(s, frame, false);
  const CellFields f = fields_from_moments(m, frame, 0.0, false);
  // Left cell: V = (1, 1); v' = (0,−1), (2,1), (−2,0); T = ½⟨v'²⟩ = ½ (1 + 5 + 4)/3 = 5/3.
  EXPECT_DOUBLE_EQ(f.count[0], 3.0);
  EXPECT_DOUBLE_EQ(f.density[0], 1.5);
  EXPECT_DOUBLE_EQ(f.velocity_x[0], 1.0);
  EXPECT_DOUBLE_EQ(f.velocity_y[0], 1.0);
  EXPECT_NEAR(f.temperature[0], 5.0 / 3.0, 1e-14);
  // τ^(k) = ρ ⟨v'v'⟩: ⟨v'x²⟩ = 8/3, ⟨v'x v'y⟩ = 2/3, ⟨v'y²⟩ = 2/3 (1.4).
  EXPECT_NEAR(f.kinetic_xx[0], 1.5 * 8.0 / 3.0, 1e-14);
  EXPECT_NEAR(f.kinetic_xy[0], 1.5 * 2.0 / 3.0, 1e-14);
  EXPECT_NEAR(f.kinetic_yy[0], 1.5 * 2.0 / 3.0, 1e-14);
  EXPECT_NEAR(f.pressure_kinetic[0], 1.5 * 5.0 / 3.0, 1e-14);
  // A lone disk has no fluctuation.
  EXPECT_DOUBLE_EQ(f.temperature[1], 0.0);
  EXPECT_DOUBLE_EQ(f.velocity_x[1], 4.0);
}

TEST(CellFields, CellSumsEqualGlobalMassMomentumAndEnergy) {
  Random random(7);
  ParticleState s;
  s.resize(5000);
  for (std::size_t i = 0; i < s.size(); ++i) {
    s.x[i] = 3.0 * random.uniform();
    s.y[i] = 2.0 * random.uniform();
    s.vx[i] = random.normal() + 0.5;
    s.vy[i] = 2.0 * random.normal();
  }
  const FieldGrid grid{7, 5, 3.0, 2.0};
  const ShearFrame frame{3.0, 2.0, 0.0};
  CellMoments m(grid);
  m.add(s, frame, false);
  const CellFields f = fields_from_moments(m, frame, 0.0, false);
  double mass = 0, px = 0, py = 0, energy = 0;
  for (std::size_t c = 0; c < grid.cells(); ++c) {
    mass += f.density[c] * grid.cell_area();
    px += f.count[c] * f.velocity_x[c];
    py += f.count[c] * f.velocity_y[c];
    // Kinetic energy of a cell: mean flow plus fluctuation, ½ n |V|² + n T.
    energy += 0.5 * f.count[c] * (f.velocity_x[c] * f.velocity_x[c] + f.velocity_y[c] * f.velocity_y[c]) + f.count[c] * f.temperature[c];
  }
  double gx = 0, gy = 0, ge = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    gx += s.vx[i];
    gy += s.vy[i];
    ge += 0.5 * (s.vx[i] * s.vx[i] + s.vy[i] * s.vy[i]);
  }
  EXPECT_NEAR(mass, 5000.0, 1e-9);
  EXPECT_NEAR(px, gx, 1e-6);
  EXPECT_NEAR(py, gy, 1e-6);
  EXPECT_NEAR(energy, ge, 1e-9 * ge);
}

TEST(CellFields, UniformShearHasVorticityMinusGammaEverywhereAcrossTheLeesEdwardsBoundary) {
  // v_x = γ (y − L_y/2) exactly: ω = −γ in every cell, including the rows whose neighbours are
  // Lees–Edwards images (shifted by Δ and moving at ±U).
  const double gamma = 3.0;
  const ShearFrame frame{1.0, 1.0, gamma};
  Random random(3);
  ParticleState s;
  s.resize(20000);
  for (std::size_t i = 0; i < s.size(); ++i) {
    s.x[i] = random.uniform();
    s.y[i] = random.uniform();
    s.vx[i] = frame.mean_flow(s.y[i]);
    s.vy[i] = 0.0;
  }
  const FieldGrid grid{8, 8, 1.0, 1.0};
  CellMoments m(grid);
  m.add(s, frame, false);
  const CellFields lab = fields_from_moments(m, frame, 0.37, false);
  for (double w : lab.vorticity) EXPECT_NEAR(w, -gamma, 0.05 * gamma);
  // With the linear profile subtracted the flow is at rest: no vorticity, no temperature.
  CellMoments relative(grid);
  relative.add(s, frame, true);
  const CellFields r = fields_from_moments(relative, frame, 0.37, true);
  for (std::size_t c = 0; c < grid.cells(); ++c) {
    EXPECT_NEAR(r.vorticity[c], 0.0, 1e-9);
    EXPECT_NEAR(r.temperature[c], 0.0, 1e-12);
  }
}

TEST(CellFields, IntervalAverageOfRepeatedConfigurationEqualsInstantaneousFields) {
  const FieldGrid grid{2, 2, 1.0, 1.0};
  const ShearFrame frame{1.0, 1.0, 0.0};
  const ParticleState s = particles_from_rows({{0.1, 0.1, 1.0, 0.0}, {0.2, 0.3, -1.0, 0.5}, {0.7, 0.8, 0.0, 2.0}});
  CellMoments once(grid), thrice(grid);
  once.add(s, frame, false);
  for (int k = 0; k < 3; ++k) thrice.add(s, frame, false);
  const CellFields a = fields_from_moments(once, frame, 0.0, false);
  const CellFields b = fields_from_moments(thrice, frame, 0.0, false);
  for (std::size_t c = 0; c < grid.cells(); ++c) {
    EXPECT_DOUBLE_EQ(a.density[c], b.density[c]);
    EXPECT_NEAR(a.temperature[c], b.temperature[c], 1e-14);
  }
}

TEST(StreamwiseProfiles, MassWeightedRowAverages) {
  const FieldGrid grid{2, 2, 2.0, 2.0};
  const ShearFrame frame{2.0, 2.0, 0.0};
  // Bottom row: one disk at v_x = 1 on the left, three at v_x = 3 on the right.
  const ParticleState s = particles_from_rows({{0.5, 0.5, 1.0, 0.0}, {1.5, 0.5, 3.0, 0.0}, {1.6, 0.6, 3.0, 0.0}, {1.7, 0.7, 3.0, 0.0}});
  CellMoments m(grid);
  m.add(s, frame, false);
  const StreamwiseProfiles p = streamwise_profiles(fields_from_moments(m, frame, 0.0, false));
  EXPECT_DOUBLE_EQ(p.y[0], 0.5);
  EXPECT_DOUBLE_EQ(p.density[0], 2.0);     // (1 + 3) / 2 cells of unit area
  EXPECT_DOUBLE_EQ(p.velocity_x[0], 2.5);  // (1·1 + 3·3) / 4
  EXPECT_DOUBLE_EQ(p.density[1], 0.0);
}

}  // namespace
}  // namespace granule
