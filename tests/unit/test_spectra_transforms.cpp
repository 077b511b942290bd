// Transforms (3.4)–(3.5) of configurations with analytic spectra, by both methods: a single particle,
// a square lattice, and the Lees–Edwards image lattice, whose power must sit only at the allowed
// wavevectors (3.10)–(3.12) — and not on the rectangular lattice of a periodic box.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "spectra/exact_mode_sums.hpp"
#include "spectra/spectral_transforms.hpp"
#include "unit/test_spectra_configurations.hpp"

namespace granule::spectra {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
// Fast method (kernel width 8): errors ~1e−6 of the ideal-gas magnitude; 1e−5 leaves a margin.
constexpr double kTolerance = 1e-5;

class SpectraTransforms : public ::testing::TestWithParam<SpectralMethod> {
 protected:
  TransformOptions options(int max_mode, bool subtract = false) const {
    TransformOptions o;
    o.max_mode = max_mode;
    o.method = GetParam();
    o.subtract_shear_profile = subtract;
    return o;
  }
};

TEST_P(SpectraTransforms, SingleParticleIsAPlaneWaveOfAmplitudeOneOverTwoPi) {
  ParticleState state;
  state.x = {0.3};
  state.y = {0.7};
  state.vx = {1.5};
  state.vy = {-0.5};
  const ShearFrame frame{2.0, 1.0, 0.0};
  const auto t = transform_fields(state, frame, 0.0, options(10));
  for (int m = -10; m <= 10; ++m) {
    for (int l = -10; l <= 10; ++l) {
      const std::size_t i = t.modes.index(l, m);
      const double phase = kTwoPi * (l * 0.3 / 2.0 + m * 0.7);
      const std::complex<double> wave = std::polar(1.0 / kTwoPi, phase);
      EXPECT_LT(std::abs(t.density[i] - wave), kTolerance / kTwoPi) << l << "," << m;
      EXPECT_LT(std::abs(t.momentum_x[i] - 1.5 * wave), 1.5 * kTolerance / kTwoPi);
      EXPECT_LT(std::abs(t.momentum_y[i] + 0.5 * wave), 0.5 * kTolerance / kTwoPi);
    }
  }
}

TEST_P(SpectraTransforms, SquareLatticeHasPowerOnlyAtMultiplesOfItsReciprocalVector) {
  const int n = 8;
  const double dx = 0.013, dy = 0.041;  // the lattice is offset from the origin: the peaks get a phase
  ParticleState state;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      state.x.push_back(dx + static_cast<double>(i) / n);
      state.y.push_back(dy + static_cast<double>(j) / n);
      state.vx.push_back(0.0);
      state.vy.push_back(0.0);
    }
  }
  const int max_mode = 20;
  const auto t = transform_fields(state, ShearFrame{1.0, 1.0, 0.0}, 0.0, options(max_mode));
  const double peak = n * n / kTwoPi;
  for (int m = -max_mode; m <= max_mode; ++m) {
    for (int l = -max_mode; l <= max_mode; ++l) {
      const std::complex<double> expected =
          l % n == 0 && m % n == 0 ? std::polar(peak, kTwoPi * (l * dx + m * dy)) : std::complex<double>(0.0);
      EXPECT_LT(std::abs(t.density[t.modes.index(l, m)] - expected), kTolerance * peak) << l << "," << m;
    }
  }
}

// Lees–Edwards: Δ = 1.1 in a 1.5 × 1 box, i.e. the thesis's [γt] = 1.1 ∈ (0, L_x/L_y); the lattice is
// built with the equivalent tilt −0.4, so this also checks that relabelling.
TEST_P(SpectraTransforms, LeesEdwardsImageLatticeHasPowerOnlyAtAllowedWavevectors) {
  const double lx = 1.5, ly = 1.0, offset = 1.1;
  const int n = 6, max_mode = 14;
  const ParticleState state = testing::sheared_lattice(n, lx, ly, offset / ly);
  const ShearFrame frame{lx, ly, 3.0};
  const auto t = transform_fields(state, frame, offset, options(max_mode));
  EXPECT_NEAR(t.lattice.tilt, -0.4, 1e-15);
  const double peak = n * n / kTwoPi;
  for (int m = -max_mode; m <= max_mode; ++m) {
    for (int l = -max_mode; l <= max_mode; ++l) {
      const double expected = l % n == 0 && m % n == 0 ? peak : 0.0;
      EXPECT_NEAR(std::abs(t.density[t.modes.index(l, m)]), expected, kTolerance * peak) << l << "," << m;
    }
  }
  // The rectangular lattice of a periodic box misses the peaks: along l = n its modes fall between
  // them (the best, m = 2, reaches |Σ_j e^{2πij·6.4/6}|/6 = 0.76 of the peak).
  const auto wrong = transform_fields(state, ShearFrame{lx, ly, 0.0}, 0.0, options(max_mode));
  for (int m = -max_mode; m <= max_mode; ++m) EXPECT_LT(std::abs(wrong.density[wrong.modes.index(n, m)]), 0.8 * peak);
}

// (3.16): the linear profile u(y) x̂ shows in p̃_x only on the k_y axis (l = 0); p̃′ (3.17) removes it.
TEST_P(SpectraTransforms, ShearProfileShowsOnlyOnTheKyAxisAndSubtractsExactly) {
  const double lx = 1.0, ly = 1.0, offset = 0.3;
  const int n = 16, max_mode = 12;  // max_mode < n: the lattice's own peaks are only at l = m = 0
  const ParticleState state = testing::sheared_lattice(n, lx, ly, offset / ly);
  const ShearFrame frame{lx, ly, 1.0};  // γ = 1: the velocities are exactly u(y)
  const auto lab = transform_fields(state, frame, offset, options(max_mode));
  const auto peculiar = transform_fields(state, frame, offset, options(max_mode, true));
  const double scale = n * n * 0.5 / kTwoPi;  // N |u|max / 2π
  double on_axis = 0.0;
  for (int m = -max_mode; m <= max_mode; ++m) {
    for (int l = -max_mode; l <= max_mode; ++l) {
      const std::size_t i = lab.modes.index(l, m);
      if (l == 0) {
        on_axis = std::max(on_axis, std::abs(lab.momentum_x[i]));
      } else {
        EXPECT_LT(std::abs(lab.momentum_x[i]), kTolerance * scale) << l << "," << m;
      }
      EXPECT_LT(std::abs(peculiar.momentum_x[i]), kTolerance * scale) << l << "," << m;
    }
  }
  EXPECT_GT(on_axis, 0.1 * scale);
}

INSTANTIATE_TEST_SUITE_P(BothMethods, SpectraTransforms,
                         ::testing::Values(SpectralMethod::exact, SpectralMethod::fast),
                         [](const auto& test_case) { return test_case.param == SpectralMethod::exact ? "exact" : "fast"; });

// Any image of a particle gives the same transform on the allowed lattice (k·a1, k·a2 ∈ 2πZ).
TEST(SpectraLattice, ExactSumsDoNotDependOnWhichImageOfAParticleIsUsed) {
  const double lx = 1.3, ly = 0.9;
  const ReciprocalLattice lattice = lattice_for_frame(ShearFrame{lx, ly, 2.0}, 0.47);
  ParticleState state = testing::uniform_gas(50, lx, ly, 7);
  ParticleState moved = state;
  for (std::size_t j = 0; j < moved.size(); j += 2) {  // half the particles to the image a2 − a1, a few to −a2
    const int up = j % 4 == 0 ? 1 : -1;
    moved.x[j] += up * 0.47 - lx;
    moved.y[j] += up * ly;
  }
  const auto a = exact_mode_sums(WeightedPoints{state.x, state.y, {{}}}, lattice, 6);
  const auto b = exact_mode_sums(WeightedPoints{moved.x, moved.y, {{}}}, lattice, 6);
  for (std::size_t i = 0; i < a[0].size(); ++i) EXPECT_LT(std::abs(a[0][i] - b[0][i]), 1e-11);
}

TEST(SpectraLattice, LeesEdwardsBasisSatisfiesKDotAEqualsTwoPiIntegers) {
  const double offset = 1.7;  // a1 = (L_x, 0), a2 = (Δ, L_y) (3.6)–(3.7) with L_x = 2, L_y = 1
  const ReciprocalLattice lattice = lattice_for_frame(ShearFrame{2.0, 1.0, 5.0}, offset);
  EXPECT_NEAR(lattice.tilt, -0.3, 1e-15);  // [γt] = 1.7 relabelled into [−1, 1)
  for (int l = -3; l <= 3; ++l) {
    for (int m = -3; m <= 3; ++m) {
      EXPECT_NEAR(lattice.phase(l, m, 2.0, 0.0), kTwoPi * l, 1e-12);
      const double turns = lattice.phase(l, m, offset, 1.0) / kTwoPi;
      EXPECT_NEAR(turns, std::round(turns), 1e-12) << l << "," << m;
    }
  }
}

}  // namespace
}  // namespace granule::spectra
