// Uncorrelated positions are the ideal-gas level of the spectra (thesis §2.2: "equipartition"): for
// N uniform independent positions ⟨|Σ_j e^{ik·r_j}|²⟩ = N and ⟨|Σ_j v_j e^{ik·r_j}|²⟩ = Σ_j v_j² at
// every k ≠ 0, so ⟨R⟩ = N/4π², ⟨P⟩ = Σv²/4π², and the annulus sums grow linearly in k (∝ the number
// of lattice modes in a ring, ≈ 2πk Δk / (Δk_x Δk_y)).  Each |S(k)|²/N is exponentially distributed
// (mean 1, sd 1) and S(−k) = S(k)*, so a sum over c modes has relative sd √(2/c): tolerances below
// are 5 of those standard deviations.  Fixed seed; fast method (its accuracy is tested in unit/).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "spectra/power_spectra.hpp"
#include "unit/test_spectra_configurations.hpp"

namespace granule::spectra {
namespace {

constexpr double kFourPiSquared = 4.0 * std::numbers::pi * std::numbers::pi;

struct IdealGas {
  ParticleState state;
  PowerMaps maps;
  double kinetic_sum = 0.0;  // Σ v_j²
};

IdealGas ideal_gas(double length_x, double length_y, double shear_offset, int max_mode) {
  IdealGas gas{testing::uniform_gas(20000, length_x, length_y, 31), {}, 0.0};
  TransformOptions options;
  options.max_mode = max_mode;
  const ShearFrame frame{length_x, length_y, shear_offset > 0.0 ? 1.0 : 0.0};
  gas.maps = power_maps(transform_fields(gas.state, frame, shear_offset, options), false);
  for (std::size_t j = 0; j < gas.state.size(); ++j) gas.kinetic_sum += gas.state.vx[j] * gas.state.vx[j] + gas.state.vy[j] * gas.state.vy[j];
  return gas;
}

class SpectraIdealGas : public ::testing::TestWithParam<double> {};  // parameter: Lees–Edwards offset Δ

TEST_P(SpectraIdealGas, EveryModeCarriesTheIdealGasLevelOnAverage) {
  const IdealGas gas = ideal_gas(1.0, 1.0, GetParam(), 32);
  const double n = static_cast<double>(gas.state.size());
  double density = 0.0, momentum = 0.0;
  std::size_t modes = 0;
  for (std::size_t i = 0; i < gas.maps.modes.count(); ++i) {
    if (i == gas.maps.modes.index(0, 0)) continue;
    density += gas.maps.density[i];
    momentum += gas.maps.momentum[i];
    ++modes;
  }
  const double tolerance = 5.0 * std::sqrt(2.0 / static_cast<double>(modes));  // 5 sd of the mean
  std::printf("[ ideal gas ] <R>/(N/4π²) = %.4f, <P>/(Σv²/4π²) = %.4f, tolerance %.3f\n",
              density / static_cast<double>(modes) / (n / kFourPiSquared),
              momentum / static_cast<double>(modes) / (gas.kinetic_sum / kFourPiSquared), tolerance);
  EXPECT_NEAR(density / static_cast<double>(modes) / (n / kFourPiSquared), 1.0, tolerance);
  // P = P_x + P_y adds two independent exponentials per mode: a smaller sd, so the same bound holds.
  EXPECT_NEAR(momentum / static_cast<double>(modes) / (gas.kinetic_sum / kFourPiSquared), 1.0, tolerance);
  // k = 0 is the total mass N/2π exactly.
  EXPECT_NEAR(gas.maps.density[gas.maps.modes.index(0, 0)], n * n / kFourPiSquared, 1e-6 * n * n / kFourPiSquared);
}

TEST_P(SpectraIdealGas, AnnulusSumsGrowLinearlyInK) {
  const IdealGas gas = ideal_gas(1.0, 1.0, GetParam(), 48);
  const double level = static_cast<double>(gas.state.size()) / kFourPiSquared;
  const AnnulusSpectrum annulus =
      annulus_sums(gas.maps, default_annulus_width(gas.maps.lattice), gas.maps.lattice.complete_radius(48));
  ASSERT_GE(annulus.k.size(), 20u);
  // Each ring against its own mode count (5 sd) …
  double sum_kr = 0.0, sum_kc = 0.0, sum_kk = 0.0, variance = 0.0;
  for (std::size_t b = 0; b < annulus.k.size(); ++b) {
    const auto count = static_cast<double>(annulus.modes[b]);
    EXPECT_NEAR(annulus.density[b] / level, count, 5.0 * std::sqrt(2.0 * count)) << "ring " << b;
    sum_kr += annulus.k[b] * annulus.density[b] / level;
    sum_kc += annulus.k[b] * count;
    sum_kk += annulus.k[b] * annulus.k[b];
    variance += annulus.k[b] * annulus.k[b] * 2.0 * count;
  }
  // … and linear growth: the least-squares slope through the origin of R(k)/level equals that of the
  // mode counts (within 5 sd), which is the ring circumference 2πk over the area Δk² per mode
  // (Δk = 2π/L), up to the lattice's departure from a circle (Gauss's circle problem, < 3% here).
  const double slope = sum_kr / sum_kk, slope_counts = sum_kc / sum_kk, sd = std::sqrt(variance) / sum_kk;
  const double circumference_slope = 2.0 * std::numbers::pi / annulus.dk;
  std::printf("[ ideal gas ] annulus slope %.3f, mode-count slope %.3f (sd %.3f), 2π/Δk = %.3f over %zu rings\n", slope,
              slope_counts, sd, circumference_slope, annulus.k.size());
  EXPECT_NEAR(slope, slope_counts, 5.0 * sd);
  EXPECT_NEAR(slope_counts / circumference_slope, 1.0, 0.03);
}

INSTANTIATE_TEST_SUITE_P(PeriodicAndLeesEdwards, SpectraIdealGas, ::testing::Values(0.0, 0.37));

}  // namespace
}  // namespace granule::spectra
