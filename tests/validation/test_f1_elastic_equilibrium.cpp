// Validation tier: the cumulative sampling algorithm (thesis §5.2) on snapshots of an elastic
// hard-disk gas in equilibrium, whose single-particle distribution is the Maxwellian: the
// thesis's reference 2T b_0^(2) = 1, √(2T) b_0^(1) = 0, b_0^(0) = log(2πT), no harmonics, and the
// kinetic stresses of f̃*, f̃** equal to the direct one (Fig 5.7) within the thesis's 1% and 5%.
// The bootstrap errors used as tolerances must themselves be of the size the Cramér–Rao bound
// for independent Maxwellian samples sets (unit/maxwellian_cramer_rao.hpp), so that a broken
// replicate cannot widen them.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>

#include "cells/cell_grid.hpp"
#include "distribution/f1_analysis.hpp"
#include "engine/simulation.hpp"
#include "init/initial_state.hpp"
#include "unit/maxwellian_cramer_rao.hpp"

namespace granule {
namespace {

using namespace granule::distribution;

TEST(F1ElasticEquilibrium, MaxwellianIsRecovered) {
  SystemParams p;
  p.particles = 4000;
  p.diameter = std::sqrt(4.0 * 0.05 / (M_PI * static_cast<double>(p.particles)));
  p.restitution = 1.0;
  const auto grid = choose_cell_grid({p.length_x, p.length_y, p.diameter, p.particles, false, 1.0, std::nullopt});
  const auto init = make_initial_state(p, 1.0, 21, Placement::kAuto);
  ASSERT_TRUE(init.error.empty()) << init.error;
  Simulation<2> sim(p, *grid.grid, init.state);
  const double inf = std::numeric_limits<double>::infinity();
  std::int64_t collisions = 5 * p.particles;  // forget the initial state
  sim.run(inf, collisions);

  // Every cell qualifies: one window wide enough for all densities and temperatures, so the
  // whole gas is the sample (cells of ~20 disks as in §1.4.3).
  std::vector<WindowSamples> windows(1);
  windows[0].density = {0.0, 1e12};
  windows[0].temperature = {0.0, 1e12};
  SamplingOptions sampling;
  sampling.grid.nx = sampling.grid.ny = 14;
  const ShearFrame frame{p.length_x, p.length_y, 0.0};
  for (int k = 0; k < 50; ++k) {
    collisions += p.particles;  // one collision per particle between snapshots, as in §5.2
    sim.run(inf, collisions);
    sample_configuration(sim.state(), frame, sampling, windows);
  }
  F1Options options;
  options.bootstrap = 40;
  options.speed_bins = options.angle_bins = 48;
  const WindowResult r = analyse_window(windows[0], options);
  ASSERT_TRUE(r.analysed) << r.warning;  // the three fits of the estimate converged
  EXPECT_EQ(r.errors.converged_replicates, r.errors.replicates);
  const SineSeries& b = r.estimate.series;
  const SineSeries& e = r.errors.series;
  const double s = r.speed_scale, t = r.temperature;
  // Five bootstrap standard deviations.  Errors from B = 40 replicates of m = 50 snapshots carry
  // ν = 2/(2/(B − 1) + 2/(m − 1)) ≈ 22 degrees of freedom, so a deviation in bootstrap errors follows
  // Student's t: P(|t₂₂| > 5) = 5·10⁻⁵ per number, and the 21 numbers below fail by chance in 0.1% of
  // seeds (four errors from 12 replicates, ν ≈ 9, failed 3 of 40 seeds by chance).  Snapshots one
  // collision per particle apart are positively correlated, so the bootstrap slightly
  // underestimates the spread; the fluctuating velocities relative to cell means of n ≈ 20 disks
  // are a mixture of Gaussians of variances ∝ (1 − 1/n), whose departure from one Gaussian is
  // O(var(1/n)) ≈ 0.1%, far below the statistical error of 2·10⁵ samples (~1%).
  constexpr double kErrors = 5.0;
  EXPECT_LE(std::abs(s * b.mean[1]), kErrors * s * e.mean[1]) << "sqrt(2T) b0^(1) = " << s * b.mean[1];
  EXPECT_LE(std::abs(2.0 * t * b.mean[2] - 1.0), kErrors * 2.0 * t * e.mean[2]) << "2T b0^(2) = " << 2.0 * t * b.mean[2];
  EXPECT_LE(std::abs(b.mean[0] - std::log(2.0 * M_PI * t)), kErrors * e.mean[0]) << "b0^(0) = " << b.mean[0];
  // When no harmonic of (5.21) is resolved (as expected here), each has the speed dependence of φ*:
  // f̃* is f̃*(v)·g(θ), and the harmonics of b^(1), b^(2) vanish up to round-off, as do their errors.
  const double round_off = 1e-12 * std::abs(b.mean[0]);
  for (int j = 0; j < SineSeries::kHarmonics; ++j)
    for (int i = 0; i < 3; ++i)
      EXPECT_LE(std::abs(b.amplitude[j][i]), kErrors * e.amplitude[j][i] + round_off) << "j " << j + 1 << " i " << i;
  EXPECT_NEAR(r.estimate.once_integrals.moment.trace() / r.estimate.direct.trace(), 1.0, 0.01);
  EXPECT_NEAR(r.estimate.twice_integrals.moment.trace() / r.estimate.direct.trace(), 1.0, 0.05);

  // The bound for independent samples is a lower bound here too (snapshots one collision per
  // particle apart are positively correlated).  Bootstrap errors from 40 replicates scatter by
  // ~15%; the estimator's variance is ≤ 1.5 × the bound (unit tier) and snapshot correlation can
  // add as much again: errors within [0.4, 2.5] × the bound.
  const Eigen::Matrix2d bound = test_statistics::maxwellian_means_bound_times_n() / static_cast<double>(r.samples);
  const struct {
    const char* name;
    double deviation, error, sigma;
  } means[] = {{"sqrt(2T) b0^(1)", s * b.mean[1], s * e.mean[1], std::sqrt(bound(0, 0))},
               {"2T b0^(2) - 1", 2.0 * t * b.mean[2] - 1.0, 2.0 * t * e.mean[2], std::sqrt(bound(1, 1))},
               {"b0^(0) - log(2 pi T)", b.mean[0] - std::log(2.0 * M_PI * t), e.mean[0], std::sqrt(bound(1, 1))}};
  for (const auto& m : means) {
    std::printf("%zu samples: %s = %.5f, bootstrap error %.5f, Cramér–Rao σ %.5f (z %.2f; error / σ %.2f)\n", r.samples,
                m.name, m.deviation, m.error, m.sigma, m.deviation / m.sigma, m.error / m.sigma);
    EXPECT_GT(m.error, 0.4 * m.sigma) << m.name;
    EXPECT_LT(m.error, 2.5 * m.sigma) << m.name;
  }
}

}  // namespace
}  // namespace granule
