// The significance of a dominant Fourier mode (spectra/mode_significance.hpp), tested against what it
// claims: for uncorrelated positions (and velocities independent of them) "significant at level α" must
// happen in a fraction α of configurations, for every field — the mass R, one momentum component P_x,
// and P = P_x + P_y, whose per-mode null is the hypoexponential law of its two components (with a plain
// e^{−s} tail P would almost never be significant: a wrong null fails here).  A striped configuration
// must be significant.  The counts are binomial: 400 independent gases (fixed seeds) at α = 0.05 give
// 20 ± 4.4 false alarms; the bounds are 3.5 binomial sd.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "spectra/dominant_mode.hpp"
#include "spectra/mode_significance.hpp"
#include "spectra/power_spectra.hpp"
#include "unit/test_spectra_configurations.hpp"

namespace granule::spectra {
namespace {

constexpr int kGases = 400;
constexpr std::size_t kParticles = 2000;
constexpr int kMaxMode = 12;  // 625 modes, K = 312 independent ones

struct Case {
  const char* name;
  double shear_offset;  // Δ of a Lees–Edwards frame (0: periodic)
  bool exclude_ky_axis;
};

PowerMaps maps_of(const ParticleState& state, const Case& c) {
  TransformOptions options;
  options.max_mode = kMaxMode;
  const ShearFrame frame{1.0, 1.0, c.shear_offset > 0.0 ? 1.0 : 0.0};
  return power_maps(transform_fields(state, frame, c.shear_offset, options), c.exclude_ky_axis);
}

void expect_binomial(int count, double rate, const char* what) {
  const double mean = kGases * rate, sd = std::sqrt(kGases * rate * (1.0 - rate));
  EXPECT_NEAR(count, mean, 3.5 * sd) << what << ": " << count << " of " << kGases << " at nominal rate " << rate;
}

class NoiseFalseAlarm : public ::testing::TestWithParam<Case> {};

TEST_P(NoiseFalseAlarm, HappensAtTheNominalRate) {
  const Case c = GetParam();
  struct Field {
    const char* name;
    const std::vector<double> PowerMaps::*map;
    ModeNoise (*noise)(const PowerMaps&);
    int at_5_percent = 0, at_50_percent = 0;
  };
  Field fields[] = {{"R", &PowerMaps::density, [](const PowerMaps& p) { return p.density_noise(); }},
                    {"Px", &PowerMaps::momentum_x, [](const PowerMaps& p) { return p.momentum_component_noise(0); }},
                    {"P", &PowerMaps::momentum, [](const PowerMaps& p) { return p.momentum_noise(); }}};
  for (int gas = 0; gas < kGases; ++gas) {
    const PowerMaps maps = maps_of(testing::uniform_gas(kParticles, 1.0, 1.0, 1000 + static_cast<std::uint64_t>(gas)), c);
    for (Field& field : fields) {
      const DominantMode d = dominant_mode(maps, maps.*field.map, field.noise(maps), 0.05);
      field.at_5_percent += d.significant ? 1 : 0;
      field.at_50_percent += d.noise_p_value < 0.5 ? 1 : 0;
    }
  }
  for (const Field& field : fields) {
    std::printf("[ %s %s ] false alarms: %d / %d at 5 %% (expected %.0f ± %.1f), %d at 50 %%\n", c.name, field.name,
                field.at_5_percent, kGases, 0.05 * kGases, std::sqrt(kGases * 0.05 * 0.95), field.at_50_percent);
    expect_binomial(field.at_5_percent, 0.05, field.name);
    expect_binomial(field.at_50_percent, 0.5, field.name);
  }
}

INSTANTIATE_TEST_SUITE_P(Frames, NoiseFalseAlarm,
                         ::testing::Values(Case{"periodic", 0.0, false}, Case{"lees_edwards", 0.3, true}),
                         [](const auto& test_case) { return std::string(test_case.param.name); });

// Stripes of density 1 + a cos(k0·r) and a transverse velocity wave b sin(k0·r) along k0 = 2π(3, 2):
// the peak is N a²/4 + 1 times the noise level for R (46 for N = 2000, a = 0.3), far above the
// threshold ln(K/α) ≈ 8.7 of K = 312 modes at α = 0.05.
TEST(StripedConfiguration, IsSignificantAtItsWavevector) {
  const double a = 0.3, b = 1.0, kx = 2.0 * std::numbers::pi * 3.0, ky = 2.0 * std::numbers::pi * 2.0;
  Random random(5);
  ParticleState state;
  state.resize(kParticles);
  for (std::size_t j = 0; j < kParticles;) {
    const double x = random.uniform(), y = random.uniform();
    if (random.uniform() * (1.0 + a) > 1.0 + a * std::cos(kx * x + ky * y)) continue;  // rejection
    state.x[j] = x;
    state.y[j] = y;
    state.vx[j] = random.normal() + b * std::sin(kx * x + ky * y);
    state.vy[j] = random.normal();
    ++j;
  }
  const Case periodic{"periodic", 0.0, false};
  const PowerMaps maps = maps_of(state, periodic);
  for (const auto& [name, d] : {std::pair{"R", dominant_mode(maps, maps.density, maps.density_noise())},
                                std::pair{"P", dominant_mode(maps, maps.momentum, maps.momentum_noise())}}) {
    std::printf("[ stripes %s ] dominant (%d, %d): %.1f × noise, threshold %.2f, p = %.1e\n", name, d.l, d.m,
                d.power_over_ideal_gas, d.noise_threshold, d.noise_p_value);
    EXPECT_TRUE(d.significant) << name;
    EXPECT_LT(d.noise_p_value, 1e-10) << name;
    EXPECT_EQ(std::abs(d.l), 3) << name;
    EXPECT_EQ(std::abs(d.m), 2) << name;
  }
}

}  // namespace
}  // namespace granule::spectra
