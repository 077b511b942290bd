// portable_exp and portable_root (src/init/portable_exp.hpp) against the C library, within 2 ulp
// over the ranges where they are used (log-normal diameters, diameters solved from a packing
// fraction).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "init/portable_exp.hpp"
#include "init/random.hpp"

namespace granule {
namespace {

double ulps_apart(double a, double b) { return std::fabs(a - b) / (std::nextafter(std::fabs(b), INFINITY) - std::fabs(b)); }

TEST(PortableExp, WithinTwoUlpOfStdExp) {
  Random rng(5);
  double worst = 0.0;
  for (int i = 0; i < 200000; ++i) {
    const double x = (2.0 * rng.uniform() - 1.0) * (i % 2 ? 700.0 : 5.0);
    worst = std::max(worst, ulps_apart(portable_exp(x), std::exp(x)));
  }
  std::printf("portable_exp: worst %.2f ulp\n", worst);
  EXPECT_LE(worst, 2.0);
  EXPECT_EQ(portable_exp(0.0), 1.0);
}

// The cube root's error against the exact ∛x, (y³ − x)/(3y²) evaluated in long double (y³ to
// 2⁻⁶⁴ relative on x86), in units of y's ulp: within one ulp (the C library's cbrt is not correctly
// rounded either, so it is no reference).
TEST(PortableRoot, CubeRootWithinOneUlpAndSquareRootExact) {
  Random rng(6);
  double worst = 0.0;
  for (int i = 0; i < 200000; ++i) {
    const double x = std::ldexp(0.5 + rng.uniform(), static_cast<int>(rng.below(400)) - 200);
    const double y = portable_root(x, 3);
    const long double r = y;
    const long double error = (r * r * r - static_cast<long double>(x)) / (3.0L * r * r);
    worst = std::max(worst, static_cast<double>(std::fabs(error)) / (std::nextafter(y, INFINITY) - y));
    EXPECT_EQ(portable_root(x, 2), std::sqrt(x));
  }
  std::printf("portable_root(x, 3): worst %.3f ulp from the exact cube root\n", worst);
  EXPECT_LE(worst, 1.0);
  EXPECT_EQ(portable_root(27.0, 3), 3.0);
  EXPECT_EQ(portable_root(0.125, 3), 0.5);
}

}  // namespace
}  // namespace granule
