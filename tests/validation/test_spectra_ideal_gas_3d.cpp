// 3D spectra against exact statistical laws.
// (1) Uncorrelated positions (an ideal gas): the shell-averaged structure factor S(k) = ⟨|Σ_j e^{ik·r_j}|²⟩/N
// is 1 at every k ≠ 0, and likewise the momentum spectrum over Σ_j |v_j|²/4π²; each mode's power over its
// mean is exponential (mean 1, sd 1) and S(−k) = S(k)*, so the average over the c modes of a shell has
// sd √(2/c) — the band the file reports (for the momentum, a sum of three components, √(2/c) times the
// spread of shell_structure_factor.hpp, ≈ 1/√3).  Checked per shell (5 sd), and as a whole over
// independent gases: z_b = (S_b − 1)/sd_b has ⟨z²⟩ = 1, with Var z² = 2 + 6 sd_b² for the Gamma law of a
// shell average (shape 1/sd_b²), so Σ z² over the B ≥ 250 shells of 20 gases must equal B within 5 of its
// sd, 5√(2.1 B) < B/2 — which fails if the band is off by √2 either way (Σ z² → 2B or B/2).
// (2) A planted plane wave, density ∝ 1 + a cos(k0·r), along one axis and along a sheared wavevector of
// an offset box: its power stands at N a²/4 times the uncorrelated level at ±k0 and only there (all other
// modes stay below the noise maximum); the dominant mode is k0 and its noise p-value vanishes, while an
// ideal gas's dominant mode is not significant.  Fixed seeds; fast method (its accuracy: unit/).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "spectra/dominant_mode.hpp"
#include "spectra/shell_structure_factor.hpp"
#include "unit/test_spectra_configurations_3d.hpp"

namespace granule::spectra {
namespace {

PowerMaps maps_of(const ParticleState& state, const ReciprocalLattice& lattice, int max_mode) {
  TransformOptions options;
  options.max_mode = max_mode;
  return power_maps(transform_fields(state, ShearFrame{lattice.length_x, lattice.length_y, 1.0}, lattice, options), false);
}

class ShellStructureFactorOfAnIdealGas : public ::testing::TestWithParam<double> {};  // parameter: Δ

TEST_P(ShellStructureFactorOfAnIdealGas, IsOneWithinItsStatisticalBandAtEveryShell) {
  const int max_mode = 16, gases = 20;
  const testing::Box3 box{1.0, 1.0, 1.0};
  const ShearFrame frame{box.x, box.y, 1.0};
  const ReciprocalLattice lattice = lattice_for_frame(frame, GetParam(), 3, box.z);
  const double radius = lattice.complete_radius(max_mode);
  double chi_square[2] = {0.0, 0.0}, variance[2] = {0.0, 0.0}, mean_sum[2] = {0.0, 0.0};
  std::size_t shells = 0, modes = 0;
  for (int g = 0; g < gases; ++g) {
    const ParticleState gas = testing::uniform_gas_3d(5000, box, 100 + static_cast<std::uint64_t>(g));
    const PowerMaps maps = maps_of(gas, lattice, max_mode);
    const AnnulusSpectrum sums = annulus_sums(maps, default_annulus_width(lattice), radius);
    const ShellStructureFactor s = shell_structure_factor(sums, maps);
    ASSERT_GE(s.density.size(), 10u);
    for (std::size_t b = 0; b < s.density.size(); ++b) {
      const auto c = static_cast<double>(sums.modes[b]);
      ASSERT_EQ(sums.momentum_modes[b], sums.modes[b]);  // nothing excluded
      EXPECT_DOUBLE_EQ(s.density_sd[b], std::sqrt(2.0 / c));
      EXPECT_NEAR(s.density[b], 1.0, 5.0 * s.density_sd[b]) << "gas " << g << " shell " << b;
      EXPECT_NEAR(s.momentum[b], 1.0, 5.0 * s.momentum_sd[b]) << "gas " << g << " shell " << b;
      for (int field = 0; field < 2; ++field) {
        const double value = field == 0 ? s.density[b] : s.momentum[b];
        const double sd = field == 0 ? s.density_sd[b] : s.momentum_sd[b];
        chi_square[field] += (value - 1.0) * (value - 1.0) / (sd * sd);
        variance[field] += 2.0 + 6.0 * sd * sd;
        mean_sum[field] += value * c;
      }
      ++shells;
      modes += sums.modes[b];
    }
  }
  const double mean_band = 5.0 * std::sqrt(2.0 / static_cast<double>(modes));
  std::printf("[ ideal gas 3D, offset %.2f ] %zu shells of %d gases: sum z^2 = %.1f (R, expected %zu ± %.1f), %.1f (P, "
              "± %.1f; 5 sd); mode-weighted mean S = %.4f (R), %.4f (P) ± %.4f (5 sd)\n",
              GetParam(), shells, gases, chi_square[0], shells, 5.0 * std::sqrt(variance[0]), chi_square[1],
              5.0 * std::sqrt(variance[1]), mean_sum[0] / static_cast<double>(modes),
              mean_sum[1] / static_cast<double>(modes), mean_band);
  for (int field = 0; field < 2; ++field) {
    ASSERT_LT(5.0 * std::sqrt(variance[field]), 0.5 * static_cast<double>(shells));  // the test can see a √2
    EXPECT_NEAR(chi_square[field], static_cast<double>(shells), 5.0 * std::sqrt(variance[field]));
    EXPECT_NEAR(mean_sum[field] / static_cast<double>(modes), 1.0, mean_band);
  }
}

INSTANTIATE_TEST_SUITE_P(PeriodicAndLeesEdwards, ShellStructureFactorOfAnIdealGas, ::testing::Values(0.0, 0.2));

struct PlantedWave {
  const char* name;
  double shear_offset;
  int l, m, n;
};

class PlantedPlaneWave3d : public ::testing::TestWithParam<PlantedWave> {};

TEST_P(PlantedPlaneWave3d, PeaksAtThePlantedModeAndOnlyThere) {
  const PlantedWave p = GetParam();
  const int max_mode = 10;
  const double amplitude = 0.3;
  const std::size_t particles = 20000;
  const ShearFrame frame{1.0, 1.0, 1.0};
  const ReciprocalLattice lattice = lattice_for_frame(frame, p.shear_offset, 3, 1.0);
  const PowerMaps maps = maps_of(testing::planted_wave_3d(particles, lattice, p.l, p.m, p.n, amplitude, 7), lattice, max_mode);
  const DominantMode d = dominant_mode(maps, maps.density, maps.ideal_density);
  const bool same = d.l == p.l && d.m == p.m && d.n == p.n;
  const bool opposite = d.l == -p.l && d.m == -p.m && d.n == -p.n;
  EXPECT_TRUE(same || opposite) << "dominant (" << d.l << ", " << d.m << ", " << d.n << ")";
  EXPECT_NEAR(d.k, std::hypot(lattice.kx(p.l), lattice.ky(p.l, p.m), lattice.kz(p.n)), 1e-12 * d.k);
  // The peak: N a²/4 + 1 − a²/4 times the uncorrelated level on average; its own fluctuation is
  // Gaussian-like: |S|² = |μ + ε|² with μ = Na/2 and Re ε of variance ≈ N/2, so sd |S|² ≈ 2μ√(N/2) and
  // the relative sd is 2μ√(N/2)/μ² = √8/(a√N) (the amplitude's shot noise); 5 sd allowed.
  const double expected = 1.0 + (static_cast<double>(particles) - 1.0) * amplitude * amplitude / 4.0;
  const double relative_sd = std::sqrt(8.0) / (amplitude * std::sqrt(static_cast<double>(particles)));
  EXPECT_NEAR(d.power_over_ideal_gas / expected, 1.0, 5.0 * relative_sd);
  EXPECT_LT(d.noise_p_value, 1e-100);
  // Every other mode is noise: below s* with K e^{−s*} = 1e−4 for the K = count/2 independent modes.
  const double threshold = std::log(0.5 * static_cast<double>(maps.modes.count()) / 1e-4);
  double runner_up = 0.0;
  for (std::size_t i = 0; i < maps.modes.count(); ++i) {
    const double ratio = maps.density[i] / maps.ideal_density;
    if (i != maps.modes.index(0, 0) && ratio < 0.5 * d.power_over_ideal_gas) runner_up = std::max(runner_up, ratio);
  }
  std::printf("[ planted %s ] dominant (%d, %d, %d): %.1f × uncorrelated level (expected %.1f), p = %.1e; "
              "largest other mode %.2f (threshold %.2f)\n",
              p.name, d.l, d.m, d.n, d.power_over_ideal_gas, expected, d.noise_p_value, runner_up, threshold);
  EXPECT_LT(runner_up, threshold);
  // Exactly two modes (±k0) above the threshold.
  std::size_t peaks = 0;
  for (std::size_t i = 0; i < maps.modes.count(); ++i) {
    if (i != maps.modes.index(0, 0) && maps.density[i] / maps.ideal_density > threshold) ++peaks;
  }
  EXPECT_EQ(peaks, 2u);
}

INSTANTIATE_TEST_SUITE_P(Waves, PlantedPlaneWave3d,
                         ::testing::Values(PlantedWave{"along_x", 0.0, 3, 0, 0}, PlantedWave{"along_z", 0.0, 0, 0, 5},
                                           PlantedWave{"sheared_lxz", 0.29, 2, 1, -3},
                                           PlantedWave{"sheared_l_only", 0.41, 4, 0, 0}),
                         [](const auto& test_case) { return std::string(test_case.param.name); });

// The offset box's planted wave is seen only on its own (sheared) lattice: on the rectangular lattice of
// a periodic box no mode reaches the peak.  k0 = 4 k1 with [γt] = 0.375 has k_y = −2π · 1.5: half a step
// from the rectangular lattice's k_y = 2πm, where the overlap is sinc²(π/2) = (2/π)² = 0.41 of the peak.
TEST(PlantedPlaneWave3dLattice, TheRectangularLatticeMissesAShearedWave) {
  const ShearFrame frame{1.0, 1.0, 1.0};
  const ReciprocalLattice sheared = lattice_for_frame(frame, 0.375, 3, 1.0);
  const ParticleState state = testing::planted_wave_3d(20000, sheared, 4, 0, 0, 0.3, 7);
  const PowerMaps right = maps_of(state, sheared, 10);
  const PowerMaps wrong = maps_of(state, lattice_for_frame(frame, 0.0, 3, 1.0), 10);
  const double peak = dominant_mode(right, right.density, right.ideal_density).power_over_ideal_gas;
  const double best_wrong = dominant_mode(wrong, wrong.density, wrong.ideal_density).power_over_ideal_gas;
  std::printf("[ planted sheared wave ] peak on the sheared lattice %.1f, best on the rectangular one %.1f\n", peak, best_wrong);
  EXPECT_LT(best_wrong, 0.5 * peak);
}

// An ideal gas's largest mode is what K independent exponentials give: not significant.
TEST(IdealGasDominantMode3d, IsNotSignificant) {
  const ReciprocalLattice lattice = lattice_for_frame(ShearFrame{}, 0.0, 3, 1.0);
  const PowerMaps maps = maps_of(testing::uniform_gas_3d(20000, {}, 41), lattice, 10);
  const DominantMode d = dominant_mode(maps, maps.density, maps.ideal_density);
  std::printf("[ ideal gas 3D ] dominant mode %.2f × uncorrelated level, noise p = %.3f\n", d.power_over_ideal_gas,
              d.noise_p_value);
  EXPECT_GT(d.noise_p_value, 1e-3);
}

}  // namespace
}  // namespace granule::spectra
