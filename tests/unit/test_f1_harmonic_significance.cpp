// Unit tier: the score test that decides which harmonics of (5.21) get their own speed dependence
// (src/distribution/harmonic_significance.hpp).  Without harmonic 2p in the distribution its
// statistic must follow χ² with 6 degrees of freedom — whatever the other harmonics do — so that
// a harmonic of pure noise is taken as resolved once in a thousand windows; the harmonics of an
// anisotropic Gaussian of 2·10⁵ samples must be resolved.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "distribution/harmonic_significance.hpp"
#include "init/random.hpp"
#include "unit/chi_square.hpp"

namespace granule::distribution {
namespace {

using granule::test_statistics::chi_square_quantile;
using granule::test_statistics::kNormal9995;

constexpr int kHarmonics = 4;

// The statistics of `samples` velocities from `draw(random, speed, angle)` on 32 × 32 bins.
template <typename Draw>
std::vector<double> statistics(std::uint64_t seed, int samples, Draw draw) {
  Random random(seed);
  std::vector<double> speed(static_cast<std::size_t>(samples)), angle(speed.size());
  double largest = 0.0;
  for (std::size_t i = 0; i < speed.size(); ++i) {
    draw(random, speed[i], angle[i]);
    largest = std::max(largest, speed[i]);
  }
  const PolarGrid grid{32, 32, largest * (1.0 + 1e-9)};
  const double n = static_cast<double>(samples);
  return harmonic_chi_square(cumulative_function(polar_counts(speed.data(), angle.data(), speed.size(), grid), n, grid),
                             kHarmonics);
}

// A Rayleigh speed (unit Maxwellian) and an angle of density ∝ 1 + a cos 2θ, independent of it:
// only the harmonic p = 1 is present (none if a = 0).
void draw_with_second_harmonic(Random& random, double a, double& speed, double& angle) {
  speed = std::hypot(random.normal(), random.normal());
  do angle = 2.0 * M_PI * random.uniform();
  while (random.uniform() * (1.0 + a) > 1.0 + a * std::cos(2.0 * angle));
}

TEST(F1HarmonicSignificance, WithoutTheHarmonicTheStatisticIsChiSquareWithSixDof) {
  constexpr int kSeeds = 100, kSamples = 20000;
  for (const double a : {0.0, 0.3}) {
    const int first_null = a == 0.0 ? 1 : 2;  // harmonics p ≥ first_null are absent
    double pooled = 0.0;
    int terms = 0, resolved = 0;
    for (int seed = 1; seed <= kSeeds; ++seed) {
      const std::vector<double> chi = statistics(static_cast<std::uint64_t>(seed), kSamples, [&](Random& g, double& v, double& t) {
        draw_with_second_harmonic(g, a, v, t);
      });
      for (int p = first_null; p <= kHarmonics; ++p) {
        pooled += chi[static_cast<std::size_t>(p - 1)];
        resolved += chi[static_cast<std::size_t>(p - 1)] > kResolvedChiSquare;
        ++terms;
      }
    }
    const double dof = 6.0 * terms, low = chi_square_quantile(dof, -kNormal9995), high = chi_square_quantile(dof, kNormal9995);
    std::printf("angle density 1 + %.1f cos 2θ: statistics of the absent harmonics pooled over %d: χ² %.0f for %.0f dof "
                "(99.9%% range %.0f–%.0f); %d taken as resolved (expected %.1f)\n",
                a, terms, pooled, dof, low, high, resolved, 1e-3 * terms);
    EXPECT_GT(pooled, low);
    EXPECT_LT(pooled, high);
    EXPECT_LE(resolved, 3);  // Poisson with mean 0.3 or 0.4: P(> 3) < 10⁻³
  }
}

TEST(F1HarmonicSignificance, HarmonicsOfAnAnisotropicGaussianAreResolved) {
  // K = [[1.3, −0.35], [−0.35, 0.8]]: the angle's harmonics fall off as 0.21^p (0.21, 0.046, 0.010).
  const double lxx = std::sqrt(1.3), lyx = -0.35 / lxx, lyy = std::sqrt(0.8 - lyx * lyx);
  const std::vector<double> chi = statistics(7, 200000, [&](Random& g, double& v, double& t) {
    const double a = g.normal(), b = g.normal();
    const double vx = lxx * a, vy = lyx * a + lyy * b;
    v = std::hypot(vx, vy);
    t = std::atan2(vy, vx) + (vy < 0.0 ? 2.0 * M_PI : 0.0);
  });
  std::printf("anisotropic Gaussian, 2·10⁵ samples: statistics %.0f, %.0f, %.0f, %.1f (resolved above %.1f)\n", chi[0], chi[1],
              chi[2], chi[3], kResolvedChiSquare);
  for (int p = 1; p <= 3; ++p) EXPECT_GT(chi[static_cast<std::size_t>(p - 1)], kResolvedChiSquare) << "p = " << p;
}

}  // namespace
}  // namespace granule::distribution
