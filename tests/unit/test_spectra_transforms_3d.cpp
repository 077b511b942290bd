// 3D transforms (3.4)–(3.5) of configurations with analytic spectra, by both methods: a single particle
// (a plane wave on the sheared 3D lattice), the 3D Lees–Edwards image lattice, whose power must sit only
// at the allowed wavevectors k = l k1 + m k2 + n k3 — and not on the rectangular lattice of a periodic
// box — and the shear profile, which shows in p̃_x only on the k_y axis (l = n = 0).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <tuple>
#include <numbers>

#include "spectra/dominant_mode.hpp"
#include "spectra/exact_mode_sums.hpp"
#include "spectra/spectral_transforms.hpp"
#include "unit/test_spectra_configurations_3d.hpp"

namespace granule::spectra {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr double kTolerance = 1e-5;  // fast method: ~1e−6 of the ideal-gas magnitude (fast_vs_exact_3d)

class SpectraTransforms3d : public ::testing::TestWithParam<SpectralMethod> {
 protected:
  TransformOptions options(int max_mode, bool subtract = false) const { return {max_mode, GetParam(), subtract, {}}; }
};

// One particle of mass 2 at r in a sheared 2 × 1 × 1.5 box (Δ = 0.7): ρ̃(k) = 2 e^{ik·r}/2π with
// k = (2πl/L_x, 2π(m/L_y − l Δ/(L_x L_y)), 2πn/L_z) written out here, not taken from the lattice.
TEST_P(SpectraTransforms3d, SingleParticleIsAPlaneWaveOnTheSheared3dLattice) {
  const double lx = 2.0, ly = 1.0, lz = 1.5, offset = 0.7;
  ParticleState state;
  state.dimension = 3;
  state.x = {0.3};
  state.y = {0.7};
  state.z = {1.1};
  state.vx = {1.5};
  state.vy = {-0.5};
  state.vz = {0.25};
  state.mass = {2.0};
  const ShearFrame frame{lx, ly, 1.0};
  const auto t = transform_fields(state, frame, lattice_for_frame(frame, offset, 3, lz), options(6));
  for (int n = -6; n <= 6; ++n) {
    for (int m = -6; m <= 6; ++m) {
      for (int l = -6; l <= 6; ++l) {
        const std::size_t i = t.modes.index(l, m, n);
        const double phase = kTwoPi * (l * 0.3 / lx + (m / ly - l * offset / (lx * ly)) * 0.7 + n * 1.1 / lz);
        const std::complex<double> wave = std::polar(2.0 / kTwoPi, phase);
        EXPECT_LT(std::abs(t.density[i] - wave), 2.0 * kTolerance / kTwoPi) << l << "," << m << "," << n;
        EXPECT_LT(std::abs(t.momentum_x[i] - 1.5 * wave), 3.0 * kTolerance / kTwoPi);
        EXPECT_LT(std::abs(t.momentum_y[i] + 0.5 * wave), kTolerance / kTwoPi);
        EXPECT_LT(std::abs(t.momentum_z[i] - 0.25 * wave), kTolerance / kTwoPi);
      }
    }
  }
  // Ideal-gas levels Σ m²/4π² and Σ m² v_a²/4π².
  EXPECT_DOUBLE_EQ(t.ideal_density, 4.0 / (kTwoPi * kTwoPi));
  EXPECT_DOUBLE_EQ(t.ideal_momentum_axes[2], 4.0 * 0.0625 / (kTwoPi * kTwoPi));
}

// Δ = 0.9375 in a 1.5 × 1 × 0.8 box: the lattice is built with the equivalent tilt −0.5625.
TEST_P(SpectraTransforms3d, LeesEdwardsImageLatticeHasPowerOnlyAtAllowedWavevectors) {
  const testing::Box3 box{1.5, 1.0, 0.8};
  const double offset = 0.9375;
  const int n = 4, max_mode = 9;
  const ParticleState state = testing::sheared_lattice_3d(n, box, offset / box.y);
  const ShearFrame frame{box.x, box.y, 3.0};
  const auto t = transform_fields(state, frame, lattice_for_frame(frame, offset, 3, box.z), options(max_mode));
  EXPECT_NEAR(t.lattice.tilt, -0.5625, 1e-15);
  const double peak = n * n * n / kTwoPi;
  for (int k = -max_mode; k <= max_mode; ++k) {
    for (int m = -max_mode; m <= max_mode; ++m) {
      for (int l = -max_mode; l <= max_mode; ++l) {
        const double expected = l % n == 0 && m % n == 0 && k % n == 0 ? peak : 0.0;
        EXPECT_NEAR(std::abs(t.density[t.modes.index(l, m, k)]), expected, kTolerance * peak) << l << "," << m << "," << k;
      }
    }
  }
  // The rectangular lattice of a periodic box misses the peaks off the l = 0 plane: at l = n its modes
  // sum e^{2πi j (nΔ/L_x + m)/n} over the n rows j, and nΔ/L_x = 2.5 puts every m half a step off
  // (the best reaches |Σ_j e^{iπj/4}|/4 = 0.65 of the peak).
  const ShearFrame periodic{box.x, box.y, 0.0};
  const auto wrong = transform_fields(state, periodic, lattice_for_frame(periodic, 0.0, 3, box.z), options(max_mode));
  for (int m = -max_mode; m <= max_mode; ++m) EXPECT_LT(std::abs(wrong.density[wrong.modes.index(n, m, 0)]), 0.8 * peak);
}

// (3.16) in 3D: u(y) x̂ depends on y alone, so p̃_x carries it only at l = n = 0; p̃′ (3.17) removes it.
TEST_P(SpectraTransforms3d, ShearProfileShowsOnlyOnTheKyAxisAndSubtractsExactly) {
  const testing::Box3 box{1.0, 1.0, 1.0};
  const double offset = 0.3;
  const int n = 10, max_mode = 8;  // max_mode < n: the lattice's own peaks are only at k = 0
  const ParticleState state = testing::sheared_lattice_3d(n, box, offset / box.y);
  const ShearFrame frame{box.x, box.y, 1.0};  // γ = 1: the velocities are exactly u(y)
  const ReciprocalLattice lattice = lattice_for_frame(frame, offset, 3, box.z);
  const auto lab = transform_fields(state, frame, lattice, options(max_mode));
  const auto peculiar = transform_fields(state, frame, lattice, options(max_mode, true));
  const double scale = n * n * n * 0.5 / kTwoPi;  // N |u|max / 2π
  double on_axis = 0.0;
  for (int k = -max_mode; k <= max_mode; ++k) {
    for (int m = -max_mode; m <= max_mode; ++m) {
      for (int l = -max_mode; l <= max_mode; ++l) {
        const std::size_t i = lab.modes.index(l, m, k);
        if (l == 0 && k == 0) {
          on_axis = std::max(on_axis, std::abs(lab.momentum_x[i]));
        } else {
          EXPECT_LT(std::abs(lab.momentum_x[i]), kTolerance * scale) << l << "," << m << "," << k;
        }
        EXPECT_LT(std::abs(peculiar.momentum_x[i]), kTolerance * scale) << l << "," << m << "," << k;
      }
    }
  }
  EXPECT_GT(on_axis, 0.1 * scale);
  // --exclude-ky-axis leaves out exactly those modes: NaN at l = n = 0, a number elsewhere.
  const PowerMaps maps = power_maps(lab, true);
  EXPECT_TRUE(std::isnan(maps.momentum_x[maps.modes.index(0, 3, 0)]));
  EXPECT_FALSE(std::isnan(maps.momentum_x[maps.modes.index(0, 3, 1)]));
  EXPECT_FALSE(std::isnan(maps.momentum_x[maps.modes.index(1, 3, 0)]));
}

INSTANTIATE_TEST_SUITE_P(BothMethods, SpectraTransforms3d,
                         ::testing::Values(SpectralMethod::exact, SpectralMethod::fast),
                         [](const auto& test_case) { return test_case.param == SpectralMethod::exact ? "exact" : "fast"; });

TEST(SpectraLattice3d, BasisSatisfiesKDotAEqualsTwoPiIntegers) {
  const double offset = 1.7, lz = 0.6;  // a1 = (2, 0, 0), a2 = (Δ, 1, 0), a3 = (0, 0, L_z)
  const ReciprocalLattice lattice = lattice_for_frame(ShearFrame{2.0, 1.0, 5.0}, offset, 3, lz);
  for (int l = -3; l <= 3; ++l) {
    for (int m = -3; m <= 3; ++m) {
      for (int n = -3; n <= 3; ++n) {
        for (const auto& [x, y, z] : {std::tuple{2.0, 0.0, 0.0}, {offset, 1.0, 0.0}, {0.0, 0.0, lz}}) {
          const double turns = lattice.phase(l, m, n, x, y, z) / kTwoPi;
          EXPECT_NEAR(turns, std::round(turns), 1e-12) << l << "," << m << "," << n;
        }
      }
    }
  }
  // The complete radius bounds from below every |k| with max(|l|, |m|, |n|) > M (brute force over a
  // wider window), and closely: here the k_x and k_z bounds are both near the nearest such mode.
  for (const double depth : {lz, 2.5}) {
    const ReciprocalLattice deep = lattice_for_frame(ShearFrame{2.0, 1.0, 5.0}, offset, 3, depth);
    const int max_mode = 5;
    double nearest = 1e300;
    for (int l = -3 * max_mode; l <= 3 * max_mode; ++l) {
      for (int m = -3 * max_mode; m <= 3 * max_mode; ++m) {
        for (int n = -3 * max_mode; n <= 3 * max_mode; ++n) {
          if (std::max({std::abs(l), std::abs(m), std::abs(n)}) <= max_mode) continue;
          nearest = std::min(nearest, std::hypot(deep.kx(l), deep.ky(l, m), deep.kz(n)));
        }
      }
    }
    EXPECT_LE(deep.complete_radius(max_mode), nearest);
    EXPECT_GT(deep.complete_radius(max_mode), 0.95 * nearest) << depth;
  }
}

TEST(SpectraTransforms3dInput, AConfigurationOfAnotherDimensionIsRefused) {
  const ParticleState state = testing::uniform_gas_3d(5, {}, 1);
  EXPECT_THROW(transform_fields(state, ShearFrame{}, 0.0, TransformOptions{}), std::invalid_argument);
}

// L0 = l/√(1 − ẽ²) with l = 1/(√2 π n σ²) for spheres (the Boltzmann mean free path), l = L_x L_y/(2Nσ)
// for disks (§3.1.2).
TEST(ClusterLength3d, UsesTheSphereMeanFreePath) {
  SystemParams spheres;
  spheres.dimension = 3;
  spheres.particles = 1000;
  spheres.diameter = 0.02;
  spheres.length_x = 1.0;
  spheres.length_y = 2.0;
  spheres.length_z = 0.5;
  spheres.restitution = 0.6;
  const double l = 1.0 / (std::sqrt(2.0) * std::numbers::pi * 1000.0 * 0.02 * 0.02);
  EXPECT_NEAR(mean_free_path(spheres), l, 1e-12 * l);
  EXPECT_NEAR(cluster_length(spheres), l / 0.8, 1e-12 * l);
  SystemParams disks = spheres;
  disks.dimension = 2;
  EXPECT_DOUBLE_EQ(mean_free_path(disks), 2.0 / (2.0 * 1000.0 * 0.02));
}

}  // namespace
}  // namespace granule::spectra
