// Cell fields and collisional transfer of rough grains against hand-computed values:
// the mean spin Ω(r) = Σ Iω / Σ I and T_rot(r) = Σ I|ω − Ω|² / (d_rot · count) per cell, and the
// full collisional stress τ_ab = Σ σ k̂_a P_b / (V t) of collisions with a tangential impulse, with
// the translational energy they carry; fields.h5 holds the new datasets only for rough runs.
#include <gtest/gtest.h>

#include <filesystem>

#include "analysis/cell_fields.hpp"
#include "observers/collisional_stress.hpp"
#include "io/fields_file.hpp"
#include "io/hdf5_util.hpp"
#include "unit/particle_rows.hpp"

namespace granule {
namespace {

constexpr double kSigma = 0.1;
const SpinInertia kDiskInertia{0.5, kSigma};  // I = ½ σ²/4 = 1/800 for unit masses

// Box 2 × 1, cells 2 × 1: three disks spinning at 1, 2, 6 in the left cell, none in the right.
ParticleState spinning_left_cell() {
  ParticleState s = particles_from_rows({{0.2, 0.5, 1.0, 0.0}, {0.7, 0.3, 0.0, 1.0}, {0.5, 0.8, 0.0, 0.0}});
  s.wz = {1.0, 2.0, 6.0};
  return s;
}

TEST(RoughCellFields, MeanSpinAndRotationalTemperatureOfDisks) {
  const FieldGrid grid{2, 1, 2.0, 1.0};
  const ShearFrame frame{2.0, 1.0, 0.0};
  CellMoments m(grid, kDiskInertia);
  m.add(spinning_left_cell(), frame, false);
  const CellFields f = fields_from_moments(m, frame, 0.0, false);
  ASSERT_TRUE(f.rough);
  EXPECT_DOUBLE_EQ(f.spin_z[0], 3.0);
  // I Σ(ω − Ω)² / 3 = (4 + 1 + 9)/800/3.
  EXPECT_NEAR(f.rotational_temperature[0], 14.0 / 2400.0, 1e-17);
  EXPECT_EQ(f.spin_z[1], 0.0);
  EXPECT_EQ(f.rotational_temperature[1], 0.0);
  EXPECT_TRUE(f.spin_x.empty());  // disks spin about z only
  std::vector<std::string> names;
  for_each_field(f, [&](const char* name, const std::vector<double>&) { names.emplace_back(name); });
  EXPECT_EQ(names.back(), "rotational_temperature");
  EXPECT_EQ(names[names.size() - 2], "spin_z");
}

TEST(RoughCellFields, SpheresOfUnequalInertiaAreWeightedByIt) {
  const FieldGrid grid{1, 1, 1.0, 1.0, 1, 1.0, 3};
  const ShearFrame frame{1.0, 1.0, 0.0};
  ParticleState s;
  s.dimension = 3;
  s.x = {0.2, 0.7};
  s.y = s.z = {0.5, 0.5};
  s.vx = s.vy = s.vz = {0.0, 0.0};
  s.diameter = {0.1, 0.2};
  s.mass = {1.0, 8.0};
  s.wx = {4.0, 1.0};
  s.wy = {0.0, 0.0};
  s.wz = {-3.0, 0.0};
  CellMoments m(grid, SpinInertia{0.4, 0.2});
  m.add(s, frame, false);
  const CellFields f = fields_from_moments(m, frame, 0.0, false);
  // I₁ = 0.4 · 0.01/4 = 0.001, I₂ = 0.4 · 8 · 0.04/4 = 0.032: Ω = (0.004 + 0.032, 0, −0.003)/0.033.
  EXPECT_NEAR(f.spin_x[0], 0.036 / 0.033, 1e-15);
  EXPECT_EQ(f.spin_y[0], 0.0);
  EXPECT_NEAR(f.spin_z[0], -0.003 / 0.033, 1e-15);
  // Σ I|ω − Ω|² directly, over d_rot = 3 and 2 spheres.
  const double ox = 0.036 / 0.033, oz = -0.003 / 0.033;
  const double direct = 0.001 * ((4.0 - ox) * (4.0 - ox) + (-3.0 - oz) * (-3.0 - oz)) + 0.032 * ((1.0 - ox) * (1.0 - ox) + oz * oz);
  EXPECT_NEAR(f.rotational_temperature[0], direct / 6.0, 1e-15);
}

TEST(RoughCellFields, SpinMomentsSurviveACheckpointAndAreIgnoredWithoutInertia) {
  const FieldGrid grid{2, 1, 2.0, 1.0};
  const ShearFrame frame{2.0, 1.0, 0.0};
  CellMoments m(grid, kDiskInertia);
  m.add(spinning_left_cell(), frame, false);
  StateArchive archive;
  m.save(archive, "m/");
  CellMoments restored(grid, kDiskInertia);
  restored.restore(archive, "m/");
  EXPECT_EQ(restored.spin_z, m.spin_z);
  EXPECT_EQ(restored.spin_square, m.spin_square);
  EXPECT_EQ(restored.inertia_sum, m.inertia_sum);

  CellMoments without(grid);  // an analysis that needs no spin (e.g. f1 windows)
  without.add(spinning_left_cell(), frame, false);
  EXPECT_FALSE(without.rough());
  EXPECT_FALSE(fields_from_moments(without, frame, 0.0, false).rough);
}

// One rough collision of unit-mass disks 1 → 2 along k̂ with normal impulse J and tangential P_t.
CollisionRecord<2> rough_record(Vec2 v1, Vec2 v2, Vec2 k, double impulse, Vec2 tangential) {
  CollisionRecord<2> r;
  r.first_position = {0.4, 0.4};
  r.contact_point = r.first_position + 0.5 * kSigma * k;
  r.contact_normal = k;
  r.contact_distance = kSigma;
  r.first_velocity_before = v1;
  r.second_velocity_before = v2;
  r.relative_velocity = v1 - v2;
  r.impulse = impulse;
  r.tangential_impulse = tangential;
  const Vec2 p = impulse * k + tangential;
  r.first_velocity_after = v1 - p;
  r.second_velocity_after = v2 + p;
  return r;
}

TEST(RoughCollisionalStress, FullTensorAndTranslationalEnergyOfOneCollision) {
  const Vec2 v1{2.0, 0.5}, v2{-1.0, 0.3}, k{0.6, 0.8}, tangential{-0.4, 0.3}, reference{0.4, -0.2};
  const double impulse = 1.2, t = 2.5;
  const FieldGrid grid{1, 1, 1.0, 1.0};
  CollisionalStressField<2> field(grid, kSigma, true);
  field.restart(0.0);
  const CollisionRecord<2> r = rough_record(v1, v2, k, impulse, tangential);
  field.on_collision(r);
  const CollisionalStress stress = field.stress(t);
  ASSERT_TRUE(stress.full());
  const Vec2 p = impulse * k + tangential;
  for (int a = 0; a < 2; ++a) {
    for (int b = 0; b < 2; ++b) EXPECT_NEAR(stress.component(a, b)[0], kSigma * k[a] * p[b] / t, 1e-15) << a << b;
  }
  EXPECT_NE(stress.xy[0], stress.yx[0]);
  EXPECT_NEAR(stress.pressure(0), kSigma * impulse / (2.0 * t), 1e-15);  // P_t ⊥ k̂ leaves the trace
  // q^(c) = σ/(A t) k̂ (ΔE₂ − ΔE₁)/2 with the translational energies about `reference`.
  const HeatFlux q = collisional_heat_flux(stress, {reference.x}, {reference.y});
  const auto energy = [&](Vec2 v) { return 0.5 * dot(v - reference, v - reference); };
  const double de1 = energy(r.first_velocity_after) - energy(v1);
  const double de2 = energy(r.second_velocity_after) - energy(v2);
  const double carried = 0.5 * (de2 - de1) * kSigma / t;
  EXPECT_NEAR(q.x[0], carried * k.x, 1e-15);
  EXPECT_NEAR(q.y[0], carried * k.y, 1e-15);
}

TEST(RoughCollisionalStress, SmoothFieldsKeepTheSymmetricTensor) {
  const FieldGrid grid{1, 1, 1.0, 1.0};
  CollisionalStressField<2> field(grid, kSigma);
  field.restart(0.0);
  field.on_collision(rough_record({1.0, 0.0}, {-1.0, 0.0}, {1.0, 0.0}, 1.0, {0.0, 0.0}));
  const CollisionalStress stress = field.stress(1.0);
  EXPECT_FALSE(stress.full());
  EXPECT_EQ(&stress.component(1, 0), &stress.component(0, 1));
}

TEST(RoughFieldsFile, HoldsSpinFieldsAndTheFullStressOnlyForRoughRuns) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "granule_test_rough_fields";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const FieldGrid grid{2, 1, 2.0, 1.0};
  const ShearFrame frame{2.0, 1.0, 0.0};
  for (const bool rough : {false, true}) {
    SystemParams system;
    system.roughness.rough = rough;
    const std::string path = (dir / (rough ? "rough.h5" : "smooth.h5")).string();
    {
      FieldsWriter writer(path, grid, FieldsMetadata{system, "periodic", false, "run", "test"}, true);
      CellMoments m(grid, kDiskInertia);
      ParticleState state = spinning_left_cell();
      if (!rough) state.wz.clear();
      m.add(state, frame, false);
      FieldsFrame f;
      f.instant = f.average = fields_from_moments(m, frame, 0.0, false);
      CollisionalStressField<2> field(grid, kSigma, rough);
      field.on_collision(rough_record({1.0, 0.0}, {-1.0, 0.0}, {1.0, 0.0}, 1.0, {0.0, rough ? 0.5 : 0.0}));
      f.collisional = field.stress(1.0);
      f.heat_flux_collisional = collisional_heat_flux(*f.collisional, f.average, frame, false);
      writer.append(f);
      writer.finish();
    }
    h5::Handle file = h5::open_file(path);
    for (const char* name : {"/instant/spin_z", "/average/rotational_temperature", "/average/collisional_yx", "/average/total_yx"}) {
      EXPECT_EQ(h5::has_link(file.get(), name), rough) << name;
    }
    if (rough) {
      const auto frame0 = [&](const char* name) { return h5::read_frame_values(file.get(), name, 0, h5::frame_row(file.get(), name)); };
      const std::vector<double> t_rot = frame0("/average/rotational_temperature");
      const std::vector<double> yx = frame0("/average/collisional_yx");
      EXPECT_NEAR(t_rot[0], 14.0 / 2400.0, 1e-17);
      // k̂ = x̂ at the contact (0.45, 0.4), in cell 0: τ_yx = σ k_y P_x = 0, τ_xy = σ k_x P_y = σ · 0.5.
      EXPECT_EQ(yx[0], 0.0);
      const std::vector<double> xy = frame0("/average/collisional_xy");
      EXPECT_NEAR(xy[0], kSigma * 0.5 / grid.cell_area(), 1e-16);
    }
    file.close();
    FieldsWriter resumed(path, -1);  // a resumed writer finds what the file holds
    EXPECT_EQ(resumed.frames(), 1);
  }
}

}  // namespace
}  // namespace granule
