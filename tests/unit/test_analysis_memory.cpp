// The memory estimates the analyses are refused by (cell_moments_bytes, cell_fields_bytes,
// spectra_bytes) against counts made independently: the arrays a CellMoments and a CellFields
// really hold once configurations are added, and the spectra's phases added up by hand from
// what transform_fields, fast_mode_sums and power_maps allocate.
#include <gtest/gtest.h>

#include <vector>

#include "analysis/cell_fields.hpp"
#include "spectra/fast_mode_sums.hpp"
#include "spectra/spectra_memory.hpp"

namespace granule {
namespace {

double held_bytes(const std::vector<const std::vector<double>*>& arrays) {
  double values = 0.0;
  for (const std::vector<double>* array : arrays) values += static_cast<double>(array->size());
  return 8.0 * values;
}

// Every array of CellMoments, whatever it holds.
double held_bytes(const CellMoments& m) {
  return held_bytes({&m.count, &m.px, &m.py, &m.pxx, &m.pxy, &m.pyy, &m.energy_flux_x, &m.energy_flux_y, &m.pz, &m.pxz,
                     &m.pyz, &m.pzz, &m.energy_flux_z, &m.mass, &m.inertia_sum, &m.spin_x, &m.spin_y, &m.spin_z,
                     &m.spin_square});
}

// Every array of CellFields.
double held_bytes(const CellFields& f) {
  return held_bytes({&f.count, &f.density, &f.velocity_x, &f.velocity_y, &f.temperature, &f.kinetic_xx, &f.kinetic_xy,
                     &f.kinetic_yy, &f.pressure_kinetic, &f.vorticity, &f.heat_flux_kinetic_x, &f.heat_flux_kinetic_y,
                     &f.velocity_z, &f.kinetic_xz, &f.kinetic_yz, &f.kinetic_zz, &f.heat_flux_kinetic_z, &f.spin_x,
                     &f.spin_y, &f.spin_z, &f.rotational_temperature});
}

// Two particles in the box [0, 1)^d, with masses and spins when asked.
ParticleState two_particles(int dimension, bool masses, bool rough) {
  ParticleState s;
  s.dimension = dimension;
  s.x = {0.25, 0.75};
  s.y = {0.5, 0.25};
  s.vx = {1.0, -1.0};
  s.vy = {0.5, 2.0};
  if (dimension == 3) {
    s.z = {0.5, 0.75};
    s.vz = {-0.5, 1.0};
  }
  if (masses) {
    s.diameter = {1e-3, 2e-3};
    s.mass = {1.0, 8.0};
  }
  if (rough) {
    s.make_rough();
    s.wz = {3.0, -1.0};
  }
  return s;
}

TEST(AnalysisMemory, CellGridsCountWhatTheyHold) {
  for (const int dimension : {2, 3}) {
    for (const bool masses : {false, true}) {
      for (const bool rough : {false, true}) {
        const FieldGrid grid = dimension == 3 ? FieldGrid{3, 4, 1.0, 1.0, 5, 1.0, 3} : FieldGrid{3, 4, 1.0, 1.0};
        const ShearFrame frame{1.0, 1.0, 0.0};
        CellMoments moments(grid, rough ? SpinInertia{0.4, 1e-3} : SpinInertia{});
        moments.add(two_particles(dimension, masses, rough), frame, false);
        const CellFields fields = fields_from_moments(moments, frame, 0.0, false);
        SCOPED_TRACE(testing::Message() << dimension << "D, masses " << masses << ", rough " << rough);
        EXPECT_EQ(cell_moments_bytes(grid, masses, rough), held_bytes(moments));
        EXPECT_EQ(cell_fields_bytes(grid, rough), held_bytes(fields));
      }
    }
  }
}

TEST(AnalysisMemory, SpectraPhasesByHand) {
  using spectra::SpectralMethod;
  using spectra::TransformOptions;
  // 2D, exact, M = 10: 21² = 441 modes.  The sums: 3 fields × 16 B × 441 = 21168; the maps beside
  // them: 6 arrays × 8 B × 441 = 21168; the weights of N = 100: 2 × 8 × 100 = 1600.
  TransformOptions exact;
  exact.max_mode = 10;
  exact.method = SpectralMethod::exact;
  EXPECT_EQ(spectra::spectra_bytes(100, 2, exact, 0.0), 21168.0 + 21168.0);
  // 10^6 rings beside the maps: 7 arrays of 8 B, and as much again for the caller.
  EXPECT_EQ(spectra::spectra_bytes(100, 2, exact, 1e6), 21168.0 + 2 * 7 * 8 * 1e6);

  // 2D, fast, M = 10: n = 45 (the first 2^a 3^b 5^c ≥ 2·21), w = 8.  Depositing: the padded grid of
  // 3 fields, 3 × 8 B × (45 + 16)² = 89304, folded into 2 complex grids, 2 × 16 B × 45² = 64800;
  // the sums and a packed pair after it (4 × 16 B × 441 = 28224) are smaller; + the weights.
  TransformOptions fast_2d;
  fast_2d.max_mode = 10;
  ASSERT_EQ(spectra::fft_grid_size(10, fast_2d.gridding), 45);
  EXPECT_EQ(spectra::spectra_bytes(100, 2, fast_2d, 0.0), 1600.0 + 64800.0 + 89304.0);

  // 3D, fast, M = 4: 9³ = 729 modes, n = 18.  The sums (4 fields × 16 B × 729 = 46656), the complex
  // n³ grid (16 B × 5832 = 93312), its planes' kept modes (18 × 81 × 16 B = 23328) and a packed pair
  // (729 × 16 B = 11664), beside the weights of N = 1000 (3 × 8 B × 1000 = 24000).
  TransformOptions fast_3d;
  fast_3d.max_mode = 4;
  ASSERT_EQ(spectra::fft_grid_size(4, fast_3d.gridding), 18);
  EXPECT_EQ(spectra::spectra_bytes(1000, 3, fast_3d, 0.0), 24000.0 + 46656.0 + 93312.0 + 23328.0 + 11664.0);
}

}  // namespace
}  // namespace granule
