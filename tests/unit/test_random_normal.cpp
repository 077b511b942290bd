// The platform-independent Gaussian generator (src/init/random.hpp) and its logarithm
// (src/init/portable_log.hpp): the logarithm against libm to a few ulp, the variates against the
// normal law (moments to their sampling error, Kolmogorov–Smirnov), and a golden sequence.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <vector>

#include "init/portable_log.hpp"
#include "init/random.hpp"

namespace granule {
namespace {

// Distance in units in the last place between two finite doubles of the same sign.
std::int64_t ulps_apart(double a, double b) {
  if (a == b) return 0;
  if ((a < 0.0) != (b < 0.0)) return INT64_MAX;
  const auto ia = std::bit_cast<std::int64_t>(a), ib = std::bit_cast<std::int64_t>(b);
  return ia > ib ? ia - ib : ib - ia;
}

TEST(PortableLog, ExactAtOneAndPowersOfTwo) {
  EXPECT_EQ(portable_log(1.0), 0.0);
  for (int k = -1074; k <= 1023; ++k) {
    const double x = std::ldexp(1.0, k);
    EXPECT_LE(ulps_apart(portable_log(x), std::log(x)), 1) << "x = 2^" << k;
  }
}

// Log-uniform over the whole positive range (subnormals included), and 1 ± tiny, where ln x ≈ x − 1
// is small and a careless formula loses all relative accuracy.
TEST(PortableLog, WithinTwoUlpOfLibmEverywhere) {
  Random random(2024);
  std::int64_t worst = 0;
  double worst_x = 1.0;
  const auto check = [&](double x) {
    const std::int64_t d = ulps_apart(portable_log(x), std::log(x));
    if (d > worst) {
      worst = d;
      worst_x = x;
    }
  };
  for (int i = 0; i < 1'000'000; ++i) check(std::exp2(-1074.0 + 2097.0 * random.uniform()));
  for (int i = 0; i < 200'000; ++i) {
    const double tiny = std::exp2(-52.0 * random.uniform());
    check(1.0 + tiny);
    check(1.0 - 0.5 * tiny);
  }
  for (int i = 0; i < 200'000; ++i) check(random.uniform() + DBL_MIN);  // the generator's range (0, 1)
  check(DBL_MAX);
  check(std::nextafter(0.0, 1.0));
  std::printf("portable_log: largest difference from std::log %lld ulp (at x = %.17g)\n",
              static_cast<long long>(worst), worst_x);
  EXPECT_LE(worst, 2);
}

std::vector<double> normal_draws(std::uint64_t seed, std::size_t n) {
  Random random(seed);
  std::vector<double> z(n);
  for (double& v : z) v = random.normal();
  return z;
}

// Sample moments of 10⁶ draws against N(0, 1), each within 4 standard errors: √(1/n) for the
// mean, √(2/n) for the variance, √(6/n) for the skewness, √(24/n) for the kurtosis (3).
TEST(RandomNormal, MomentsOfTheStandardNormal) {
  const std::size_t n = 1'000'000;
  const std::vector<double> z = normal_draws(1, n);
  double m1 = 0, m2 = 0, m3 = 0, m4 = 0;
  for (double v : z) m1 += v;
  m1 /= static_cast<double>(n);
  for (double v : z) {
    const double d = v - m1, d2 = d * d;
    m2 += d2;
    m3 += d2 * d;
    m4 += d2 * d2;
  }
  m2 /= static_cast<double>(n);
  m3 /= static_cast<double>(n);
  m4 /= static_cast<double>(n);
  const double skewness = m3 / std::pow(m2, 1.5), kurtosis = m4 / (m2 * m2);
  const double se = 1.0 / std::sqrt(static_cast<double>(n));
  std::printf("normal, 10^6 draws: mean %.5f (±%.4f), variance %.5f (±%.4f), skewness %.5f (±%.4f), "
              "kurtosis %.5f (±%.4f)\n", m1, se, m2, std::sqrt(2.0) * se, skewness, std::sqrt(6.0) * se,
              kurtosis, std::sqrt(24.0) * se);
  EXPECT_NEAR(m1, 0.0, 4.0 * se);
  EXPECT_NEAR(m2, 1.0, 4.0 * std::sqrt(2.0) * se);
  EXPECT_NEAR(skewness, 0.0, 4.0 * std::sqrt(6.0) * se);
  EXPECT_NEAR(kurtosis, 3.0, 4.0 * std::sqrt(24.0) * se);
}

// Kolmogorov–Smirnov distance of sorted samples from a continuous law F.
template <typename Cdf>
double ks_distance(std::vector<double> samples, Cdf cdf) {
  std::sort(samples.begin(), samples.end());
  const double n = static_cast<double>(samples.size());
  double d = 0.0;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const double f = cdf(samples[i]);
    d = std::max({d, f - static_cast<double>(i) / n, static_cast<double>(i + 1) / n - f});
  }
  return d;
}

// √n D < 1.63 is the 1% critical value of the Kolmogorov distribution.
TEST(RandomNormal, KolmogorovSmirnovAgainstTheNormalLaw) {
  const std::vector<double> z = normal_draws(2, 1'000'000);
  const double d = ks_distance(z, [](double x) { return 0.5 * std::erfc(-x / std::sqrt(2.0)); });
  const double scaled = d * std::sqrt(static_cast<double>(z.size()));
  std::printf("normal, 10^6 draws: KS sqrt(n) D = %.3f (1%% critical value 1.63)\n", scaled);
  EXPECT_LT(scaled, 1.63);
}

// The two variates of a pair are independent standard normals: their squared norm is χ² with two
// degrees of freedom (P(r² ≤ q) = 1 − e^{−q/2}) and their correlation vanishes.
TEST(RandomNormal, PairsAreIndependent) {
  const std::vector<double> z = normal_draws(3, 1'000'000);
  std::vector<double> r2(z.size() / 2);
  double product = 0.0;
  for (std::size_t k = 0; k < r2.size(); ++k) {
    r2[k] = z[2 * k] * z[2 * k] + z[2 * k + 1] * z[2 * k + 1];
    product += z[2 * k] * z[2 * k + 1];
  }
  const double pairs = static_cast<double>(r2.size());
  const double correlation = product / pairs;  // the standard error of this mean is 1/√pairs
  const double scaled = ks_distance(r2, [](double q) { return -std::expm1(-0.5 * q); }) * std::sqrt(pairs);
  std::printf("normal pairs: correlation %.5f (±%.4f), KS of r^2 against chi^2_2 sqrt(n) D = %.3f\n",
              correlation, 1.0 / std::sqrt(pairs), scaled);
  EXPECT_NEAR(correlation, 0.0, 4.0 / std::sqrt(pairs));
  EXPECT_LT(scaled, 1.63);
}

// Golden values: the first variates of seed 1, bit for bit.  They must be the same on every
// platform and compiler (that is what the generator is for); a change here changes every
// trajectory of every seed.
TEST(RandomNormal, GoldenSequenceOfSeedOne) {
  Random random(1);
  const double expected[] = {0x1.e267c87ac62ebp+0, 0x1.84abd879d0e18p-3, 0x1.4d55c9633557cp+0, -0x1.e8d0b0399ee9cp+0};
  for (double e : expected) EXPECT_EQ(random.normal(), e);
}

}  // namespace
}  // namespace granule
