// Quantiles of the chi-square distribution for the statistical tests of the unit tier, by the
// Wilson–Hilferty cube-root normal approximation (relative error below 1% in the tails used here,
// k ≥ 8 degrees of freedom, standard-normal quantiles |z| ≤ 3.3).
#pragma once

#include <cmath>

namespace granule::test_statistics {

// Standard-normal quantiles of the two-sided levels the tests use.
inline constexpr double kNormal999 = 3.090232;   // Φ⁻¹(0.999)
inline constexpr double kNormal9995 = 3.290527;  // Φ⁻¹(0.9995)

// χ²_k quantile at the level whose standard-normal quantile is z.
inline double chi_square_quantile(double k, double z) {
  const double a = 2.0 / (9.0 * k);
  const double cube_root = 1.0 - a + z * std::sqrt(a);
  return k * cube_root * cube_root * cube_root;
}

}  // namespace granule::test_statistics
