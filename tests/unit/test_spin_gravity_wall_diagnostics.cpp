// The time-series columns of rough grains, gravity and walls against hand-computed values:
// T_rot = I⟨|ω|²⟩/d_rot with I = q m σ²/4, the potential energy −⟨m g·r⟩, and the wall pressure,
// shear stress and heat input as sums of known records over wall area × interval.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include "io/timeseries_csv.hpp"
#include "observers/global_diagnostics.hpp"
#include "unit/particle_rows.hpp"

namespace granule {
namespace {

SystemParams disks_in_unit_box() {
  SystemParams p;
  p.particles = 4;
  p.diameter = 0.1;
  p.length_x = 2.0;
  p.length_y = 1.0;
  return p;
}

// Four disks at rest in the mean (so T_global = ⟨v²⟩/2 exactly), spinning at 1, −2, 3, 4.
ParticleState spinning_disks() {
  ParticleState s = particles_from_rows({{0.5, 0.2, 1.0, 0.0}, {1.5, 0.4, -1.0, 0.0}, {0.5, 0.6, 0.0, 2.0}, {1.5, 0.8, 0.0, -2.0}});
  s.wz = {1.0, -2.0, 3.0, 4.0};
  return s;
}

TEST(SpinDiagnostics, RotationalTemperatureOfDisks) {
  SystemParams p = disks_in_unit_box();
  p.roughness.rough = true;
  p.roughness.inertia_factor = 0.5;
  GlobalDiagnostics<2> diagnostics(p, 1, 1);
  const DiagnosticsSample d = diagnostics.sample(spinning_disks(), 1.0, 0, 0.0, 0.0);
  // I = ½ · 1 · 0.1²/4 = 1/800; ⟨ω²⟩ = (1 + 4 + 9 + 16)/4 = 7.5; d_rot = 1.
  ASSERT_TRUE(d.rotation.has_value());
  EXPECT_DOUBLE_EQ(d.rotation->rotational_temperature, 7.5 / 800.0);
  // T = ⟨v²⟩/2 = (1 + 1 + 4 + 4)/4/2 = 1.25.
  EXPECT_DOUBLE_EQ(d.temperature_global, 1.25);
  EXPECT_DOUBLE_EQ(d.rotation->rotational_temperature_ratio, 7.5 / 800.0 / 1.25);
  EXPECT_FALSE(d.gravity.has_value());
  for (const auto& wall : d.walls) EXPECT_FALSE(wall.has_value());
}

TEST(SpinDiagnostics, RotationalTemperatureOfPolydisperseSpheres) {
  SystemParams p;
  p.dimension = 3;
  p.particles = 2;
  p.diameter = 0.2;
  p.length_x = p.length_y = p.length_z = 1.0;
  p.roughness.rough = true;
  p.roughness.inertia_factor = 0.4;
  ParticleState s;
  s.dimension = 3;
  s.x = {0.25, 0.75};
  s.y = {0.5, 0.5};
  s.z = {0.5, 0.5};
  s.vx = {1.0, -1.0};
  s.vy = {0.0, 0.0};
  s.vz = {0.0, 0.0};
  s.diameter = {0.1, 0.2};
  s.mass = {1.0, 8.0};
  s.wx = {1.0, 0.0};
  s.wy = {2.0, 0.0};
  s.wz = {2.0, -1.0};
  GlobalDiagnostics<3> diagnostics(p, FieldGrid{1, 1, 1.0, 1.0, 1, 1.0, 3});
  const DiagnosticsSample d = diagnostics.sample(s, 1.0, 0, 0.0, 0.0);
  // I₁ = 0.4 · 1 · 0.01/4 = 0.001, |ω₁|² = 9; I₂ = 0.4 · 8 · 0.04/4 = 0.032, |ω₂|² = 1.
  // T_rot = (0.009 + 0.032)/2/3; T = ⟨m v²⟩/3 = (1 + 8)/2/3.
  ASSERT_TRUE(d.rotation.has_value());
  EXPECT_NEAR(d.rotation->rotational_temperature, 0.041 / 6.0, 1e-17);
  EXPECT_NEAR(d.rotation->rotational_temperature_ratio, 0.041 / 9.0, 1e-16);
}

TEST(GravityDiagnostics, PotentialAndTotalEnergy) {
  SystemParams p = disks_in_unit_box();
  p.gravity = {0.5, -2.0, 0.0};
  p.roughness.rough = true;
  GlobalDiagnostics<2> diagnostics(p, 1, 1);
  const DiagnosticsSample d = diagnostics.sample(spinning_disks(), 1.0, 0, 0.0, 0.0);
  // −⟨m g·r⟩ = ⟨2y − x/2⟩ = 2 · 0.5 − 0.5 · 1.0.
  ASSERT_TRUE(d.gravity.has_value());
  EXPECT_DOUBLE_EQ(d.gravity->potential_energy, 0.5);
  // Kinetic ½⟨v²⟩ = 1.25, rotational ½ I⟨ω²⟩ = 7.5/1600.
  EXPECT_DOUBLE_EQ(d.kinetic_energy, 1.25);
  EXPECT_DOUBLE_EQ(d.gravity->total_energy, 1.25 + 7.5 / 1600.0 + 0.5);
}

SurfaceHitRecord<2> wall_hit(int axis, int side, Vec2 impulse_on_wall, double energy_change) {
  SurfaceHitRecord<2> r;
  r.surface = {2 * axis + side, -1};
  r.impulse_on_surface = impulse_on_wall;
  r.energy_change = energy_change;
  return r;
}

TEST(WallDiagnostics, PressureShearStressAndHeatInputOfKnownRecords) {
  SystemParams p = disks_in_unit_box();  // L_x = 2: the y walls are 2 long
  p.walls = {false, true, false};
  GlobalDiagnostics<2> diagnostics(p, 1, 1);
  diagnostics.restart_interval(1.0, 0);
  diagnostics.on_surface_hit(wall_hit(1, 0, {0.3, -2.0}, 0.25));  // floor: pushed down by 2
  diagnostics.on_surface_hit(wall_hit(1, 0, {-0.1, -1.0}, -0.05));
  diagnostics.on_surface_hit(wall_hit(1, 1, {0.2, 4.0}, 0.0));    // ceiling: pushed up by 4
  const DiagnosticsSample d = diagnostics.sample(spinning_disks(), 5.0, 0, 0.0, 0.0);  // Δt = 4
  for (int face : {0, 1, 4, 5}) EXPECT_FALSE(d.walls[static_cast<std::size_t>(face)].has_value()) << face;
  ASSERT_TRUE(d.walls[2].has_value());
  ASSERT_TRUE(d.walls[3].has_value());
  const double per_area_time = 1.0 / (2.0 * 4.0);
  EXPECT_DOUBLE_EQ(d.walls[2]->pressure, 3.0 * per_area_time);
  EXPECT_DOUBLE_EQ(d.walls[2]->shear_stress, 0.2 * per_area_time);
  EXPECT_DOUBLE_EQ(d.walls[2]->heat_input, 0.2 * per_area_time);
  EXPECT_EQ(d.walls[2]->collisions, 2.0);
  EXPECT_DOUBLE_EQ(d.walls[3]->pressure, 4.0 * per_area_time);
  EXPECT_DOUBLE_EQ(d.walls[3]->shear_stress, 0.2 * per_area_time);
  EXPECT_EQ(d.walls[3]->collisions, 1.0);
  // The next interval starts empty.
  const DiagnosticsSample next = diagnostics.sample(spinning_disks(), 6.0, 0, 0.0, 0.0);
  EXPECT_EQ(next.walls[2]->collisions, 0.0);
  EXPECT_EQ(next.walls[2]->pressure, 0.0);
}

TEST(WallDiagnostics, OpenIntervalSurvivesACheckpoint) {
  SystemParams p = disks_in_unit_box();
  p.walls = {true, false, false};  // x walls, 1 long; their shear stress is along y
  GlobalDiagnostics<2> before(p, 1, 1);
  before.restart_interval(0.0, 0);
  before.on_surface_hit(wall_hit(0, 1, {1.5, -0.5}, 0.1));
  StateArchive archive;
  before.save(archive, "d/");
  GlobalDiagnostics<2> after(p, 1, 1);
  after.restore(archive, "d/");
  const DiagnosticsSample d = after.sample(spinning_disks(), 2.0, 0, 0.0, 0.0);
  ASSERT_TRUE(d.walls[1].has_value());
  EXPECT_DOUBLE_EQ(d.walls[1]->pressure, 1.5 / 2.0);
  EXPECT_DOUBLE_EQ(d.walls[1]->shear_stress, -0.5 / 2.0);
  EXPECT_DOUBLE_EQ(d.walls[1]->heat_input, 0.1 / 2.0);
}

TEST(WallDiagnostics, FaceAreaOfSpheres) {
  SystemParams p;
  p.dimension = 3;
  p.particles = 1;
  p.diameter = 0.1;
  p.length_x = 2.0;
  p.length_y = 3.0;
  p.length_z = 5.0;
  p.walls = {false, false, true};
  WallStress<3> walls(p);
  SurfaceHitRecord<3> r;
  r.surface = {4, -1};  // the z floor
  r.impulse_on_surface = {0.7, 0.0, -6.0};
  walls.add(r);
  const auto faces = walls.sample(0.5, 0.5);
  ASSERT_TRUE(faces[4].has_value());
  EXPECT_DOUBLE_EQ(faces[4]->pressure, 6.0 / (2.0 * 3.0 * 0.5));  // the z floor is L_x · L_y
  EXPECT_DOUBLE_EQ(faces[4]->shear_stress, 0.7 / 3.0);
}

TEST(SpinDiagnostics, RoughCollisionsAddTheirTangentialImpulseToTheShearStress) {
  SystemParams p = disks_in_unit_box();
  p.roughness.rough = true;
  GlobalDiagnostics<2> diagnostics(p, 1, 1);
  diagnostics.restart_interval(0.0, 0);
  CollisionRecord<2> r;
  r.contact_normal = {0.6, 0.8};
  r.contact_distance = p.diameter;
  r.impulse = 2.0;
  r.tangential_impulse = {-0.4, 0.3};  // ⊥ k̂
  diagnostics.on_collision(r);
  const DiagnosticsSample d = diagnostics.sample(spinning_disks(), 1.0, 1, 0.0, 0.0);
  // τ_yx = σ k_y P_x / (V Δt), P = J k̂ + P_t: 0.1 · 0.8 · (2 · 0.6 − 0.4) / 2.
  EXPECT_NEAR(d.shear_stress_collisional, 0.1 * 0.8 * 0.8 / 2.0, 1e-16);
  // The trace is unchanged by a tangential impulse: σ J / (d V Δt).
  EXPECT_DOUBLE_EQ(d.pressure_collisional, 0.1 * 2.0 / (2.0 * 2.0));
}

TEST(TimeseriesColumns, SmoothRunsKeepTheirColumns) {
  EXPECT_EQ(timeseries_header(diagnostics_layout(disks_in_unit_box())), timeseries_header());
  const std::string header = timeseries_header();
  EXPECT_EQ(header.find("rotational"), std::string::npos);
  EXPECT_EQ(header.find("wall_"), std::string::npos);
}

TEST(TimeseriesColumns, OptionalColumnsAreWrittenAndReadBack) {
  SystemParams p = disks_in_unit_box();
  p.roughness.rough = true;
  p.gravity = {0.0, -1.0, 0.0};
  p.walls = {false, true, false};
  GlobalDiagnostics<2> diagnostics(p, 1, 1);
  diagnostics.restart_interval(0.0, 0);
  diagnostics.on_surface_hit(wall_hit(1, 0, {0.25, -1.0}, 0.5));
  const DiagnosticsSample written = diagnostics.sample(spinning_disks(), 2.0, 0, 0.0, 0.0);
  const std::string header = timeseries_header(written);
  EXPECT_EQ(header, timeseries_header(diagnostics.layout()));
  EXPECT_NE(header.find(",rotational_temperature,rotational_temperature_ratio,potential_energy,total_energy,"
                        "wall_y0_pressure,wall_y0_shear_stress,wall_y0_heat_input,wall_y0_collisions,wall_y1_pressure"),
            std::string::npos)
      << header;
  const std::string path = ::testing::TempDir() + "granule_spin_wall_timeseries.csv";
  write_timeseries(path, {written});
  const std::vector<DiagnosticsSample> read = read_timeseries(path);
  std::remove(path.c_str());
  ASSERT_EQ(read.size(), 1u);
  ASSERT_TRUE(read[0].rotation && read[0].gravity && read[0].walls[2] && read[0].walls[3]);
  EXPECT_FALSE(read[0].walls[0].has_value());
  EXPECT_DOUBLE_EQ(read[0].rotation->rotational_temperature, 7.5 / 800.0);
  EXPECT_DOUBLE_EQ(read[0].walls[2]->pressure, 1.0 / 4.0);
  EXPECT_DOUBLE_EQ(read[0].walls[2]->heat_input, 0.5 / 4.0);
  EXPECT_DOUBLE_EQ(read[0].gravity->potential_energy, 0.5);
}

TEST(TimeseriesColumns, UnknownColumnsAreRefused) {
  EXPECT_FALSE(diagnostics_layout_of({"t", "c"}).has_value());
  std::vector<std::string> names;
  const DiagnosticsSample layout = diagnostics_layout(disks_in_unit_box());
  for_each_column(layout, [&](const char* name, const double&) { names.emplace_back(name); });
  EXPECT_TRUE(diagnostics_layout_of(names).has_value());
  names.emplace_back("wall_q0_pressure");
  EXPECT_FALSE(diagnostics_layout_of(names).has_value());
}

}  // namespace
}  // namespace granule
