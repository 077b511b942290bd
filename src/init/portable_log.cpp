#include "init/portable_log.hpp"

#include <array>
#include <cmath>

namespace granule {

namespace {

// ln 2 split so that k · kLn2High is exact for every binary exponent k of a double (fdlibm's
// split: the high part has 21 trailing zero bits) and kLn2Low carries the rest.
constexpr double kLn2High = 6.93147180369123816490e-01;  // 0x3fe62e42fee00000
constexpr double kLn2Low = 1.90821492927058770002e-10;   // 0x3dea39ef35793c76
constexpr double kSqrtHalf = 0.70710678118654752440;

// Taylor coefficients 2/(2k+1), k = 1 … 10, of R(z) = 2 atanh(s)/s − 2, z = s².  With
// |s| ≤ 3 − 2√2 ≈ 0.1716 after the range reduction, the first omitted term changes ln by less
// than 10⁻¹⁸ relative.  Each quotient is correctly rounded at compile time.
constexpr std::array<double, 10> kSeries = {2.0 / 3.0,  2.0 / 5.0,  2.0 / 7.0,  2.0 / 9.0,  2.0 / 11.0,
                                            2.0 / 13.0, 2.0 / 15.0, 2.0 / 17.0, 2.0 / 19.0, 2.0 / 21.0};

}  // namespace

double portable_log(double x) {
  // x = m · 2^k with m ∈ [√½, √2): frexp and the doubling are exact.
  int k = 0;
  double m = std::frexp(x, &k);
  if (m < kSqrtHalf) {
    m = 2.0 * m;
    --k;
  }
  // ln m = ln(1 + f) = 2 atanh(s), s = f / (2 + f); f is exact (Sterbenz).
  const double f = m - 1.0;
  const double s = f / (2.0 + f);
  const double z = s * s;
  double series = kSeries.back();
  for (std::size_t j = kSeries.size() - 1; j-- > 0;) series = kSeries[j] + z * series;  // Horner, fixed order
  const double r = z * series;
  // ln(1 + f) = f − f²/2 + s (f²/2 + R), arranged as in fdlibm so that the large terms are
  // added last and the result is within about one ulp.
  const double half_f_squared = 0.5 * f * f;
  const double dk = static_cast<double>(k);
  return dk * kLn2High - ((half_f_squared - (s * (half_f_squared + r) + dk * kLn2Low)) - f);
}

}  // namespace granule
