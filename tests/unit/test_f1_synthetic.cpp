// Unit tier: the cumulative sampling algorithm of thesis §5.2 (src/distribution) on samples
// drawn from known distributions with fixed seeds.  Tolerances are multiples of the bootstrap
// errors the tool itself reports; test_f1_sampling_variance.cpp checks the isotropic Maxwellian
// (the elastic reference), the angular harmonics and the bootstrap itself against analytic
// sampling variances.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "distribution/f1_analysis.hpp"

namespace granule::distribution {
namespace {

// `snapshots` groups of `per_snapshot` samples from `draw(random, vx, vy)`.
template <typename Draw>
WindowSamples synthetic(int snapshots, int per_snapshot, std::uint64_t seed, Draw draw) {
  WindowSamples w;
  std::mt19937_64 random(seed);
  for (int k = 0; k < snapshots; ++k) {
    for (int i = 0; i < per_snapshot; ++i) {
      double vx = 0.0, vy = 0.0;
      draw(random, vx, vy);
      w.vx.push_back(vx);
      w.vy.push_back(vy);
    }
    w.snapshot_end.push_back(w.vx.size());
    w.selected_area.push_back(1.0);
    w.temperature_weighted.push_back(0.0);
  }
  return w;
}

F1Options fast_options() {
  F1Options o;
  o.bootstrap = 12;
  o.speed_bins = 48;
  o.angle_bins = 48;
  return o;
}

void expect_converged(const WindowResult& r) {
  EXPECT_TRUE(r.estimate.once.speed.report.converged) << r.estimate.once.speed.report.status;
  EXPECT_TRUE(r.estimate.once.angular.report.converged) << r.estimate.once.angular.report.status;
  EXPECT_TRUE(r.estimate.series.report.converged) << r.estimate.series.report.status;
}

// Deviation allowed for an estimate with bootstrap error `sigma`: four standard deviations
// (each test checks ~20 coefficients at once; 4σ keeps chance failures below 0.2%).
void expect_within(double estimate, double truth, double sigma, const char* what) {
  EXPECT_LE(std::abs(estimate - truth), 4.0 * sigma) << what << ": " << estimate << " vs " << truth << " (bootstrap error " << sigma << ")";
}

// Anisotropic Gaussian with a shear-like K: −log f = log(2π√det K) + ½ v·K⁻¹·v, so b^(1) = 0,
// b^(0) is constant and b^(2)(θ) has the single harmonic 2θ, with mean, amplitude and phase
// given in closed form by (5.32)–(5.34).
TEST(F1Synthetic, AnisotropicGaussianHasOnlyTheSecondHarmonic) {
  const SecondMoment k{1.3, -0.35, 0.8};
  const double lxx = std::sqrt(k.xx), lyx = k.xy / lxx, lyy = std::sqrt(k.yy - lyx * lyx);  // Cholesky
  std::normal_distribution<double> gauss(0.0, 1.0);
  const WindowSamples w = synthetic(40, 5000, 11, [&](auto& g, double& vx, double& vy) {
    const double a = gauss(g), c = gauss(g);
    vx = lxx * a;
    vy = lyx * a + lyy * c;
  });
  const WindowResult r = analyse_window(w, fast_options());
  ASSERT_TRUE(r.analysed) << r.warning;
  expect_converged(r);
  const JenkinsRichman truth = jenkins_richman(k);
  const SineSeries& b = r.estimate.series;
  const SineSeries& e = r.errors.series;
  expect_within(b.mean[0], truth.b0, e.mean[0], "b0^(0)");
  expect_within(b.mean[1], 0.0, e.mean[1], "b0^(1)");
  expect_within(b.mean[2], truth.b2_mean, e.mean[2], "b0^(2)");
  expect_within(b.amplitude[0][2], truth.b2_amplitude, e.amplitude[0][2], "b2^(2)");
  expect_within(b.phase[0], truth.phase, e.phase[0], "epsilon_2");
  expect_within(b.amplitude[0][0], 0.0, e.amplitude[0][0], "b2^(0)");
  expect_within(b.amplitude[0][1], 0.0, e.amplitude[0][1], "b2^(1)");
  for (int j = 1; j < SineSeries::kHarmonics; ++j)
    for (int i = 0; i < 3; ++i) expect_within(b.amplitude[j][i], 0.0, e.amplitude[j][i], "higher harmonic");
  EXPECT_NEAR(r.estimate.once_integrals.moment.trace() / r.estimate.direct.trace(), 1.0, 0.01);
  EXPECT_NEAR(r.estimate.once_integrals.moment.xy / r.estimate.direct.xy, 1.0, 0.03);
}

// A constructed f̃ = exp(−b^(0)(θ) − b^(1)(θ) v − b^(2)(θ) v²) with harmonics 2θ and 4θ.  The
// once-fitted form (5.21) has one phase β for all harmonics, so it represents distributions
// symmetric about the axis θ = −β: the construction uses cos 2j(θ + β) = sin 2j(θ + β + π/4j).
struct Constructed {
  static constexpr double kBeta = 0.3;
  // b_2j^(i) for j = 1, 2 (the means are below; b_0^(0) follows from normalisation).
  double amplitude[2][3] = {{0.1, 0.25, 0.2}, {0.0, 0.08, 0.05}};
  double mean[3] = {0.0, 0.4, 0.8};

  double b(int i, double theta) const {
    return mean[i] + amplitude[0][i] * std::cos(2.0 * (theta + kBeta)) + amplitude[1][i] * std::cos(4.0 * (theta + kBeta));
  }
  double unnormalised(double v, double theta) const { return std::exp(-(b(0, theta) + v * (b(1, theta) + v * b(2, theta)))); }
};

TEST(F1Synthetic, ConstructedExponentIsRecoveredWithinItsBootstrapError) {
  Constructed f;
  // Normalisation (5.12) by plain midpoint quadrature; it fixes the true b_0^(0).
  double z = 0.0;
  const int angles = 256, speeds = 4000;
  const double v_max = 12.0;
  for (int l = 0; l < angles; ++l)
    for (int k = 0; k < speeds; ++k) {
      const double v = (k + 0.5) * v_max / speeds;
      z += f.unnormalised(v, (l + 0.5) * 2.0 * M_PI / angles) * v;
    }
  z *= (v_max / speeds) * (2.0 * M_PI / angles);
  // Rejection from θ uniform and the Rayleigh-like density ∝ v exp(−c v²), c = min b^(2):
  // with b^(1) ≥ 0 the acceptance exp(−b^(0) − b^(1) v − (b^(2) − c) v² + min b^(0)) ≤ 1.
  const double c = f.mean[2] - f.amplitude[0][2] - f.amplitude[1][2];
  const double b0_min = -f.amplitude[0][0];
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  const WindowSamples w = synthetic(40, 6000, 13, [&](auto& g, double& vx, double& vy) {
    for (;;) {
      const double theta = 2.0 * M_PI * uniform(g);
      const double v = std::sqrt(-std::log(1.0 - uniform(g)) / c);
      const double accept = std::exp(-(f.b(0, theta) - b0_min) - f.b(1, theta) * v - (f.b(2, theta) - c) * v * v);
      if (uniform(g) < accept) {
        vx = v * std::cos(theta);
        vy = v * std::sin(theta);
        return;
      }
    }
  });
  F1Options options = fast_options();
  const WindowResult r = analyse_window(w, options);
  ASSERT_TRUE(r.analysed) << r.warning;
  expect_converged(r);
  SineSeries b = r.estimate.series;
  const SineSeries& e = r.errors.series;
  expect_within(b.mean[0], std::log(z), e.mean[0], "b0^(0)");
  expect_within(b.mean[1], f.mean[1], e.mean[1], "b0^(1)");
  expect_within(b.mean[2], f.mean[2], e.mean[2], "b0^(2)");
  for (int j = 1; j <= SineSeries::kHarmonics; ++j) {
    if (j <= 2) {
      align_phase(b, j, Constructed::kBeta + M_PI / (4.0 * j));
      expect_within(b.phase[j - 1], Constructed::kBeta + M_PI / (4.0 * j), e.phase[j - 1], "epsilon");
    }
    for (int i = 0; i < 3; ++i)
      expect_within(b.amplitude[j - 1][i], j <= 2 ? f.amplitude[j - 1][i] : 0.0, e.amplitude[j - 1][i], "amplitude");
  }
}

}  // namespace
}  // namespace granule::distribution
