#include "init/portable_exp.hpp"

#include <array>
#include <cmath>

namespace granule {

namespace {

// ln 2 split as in portable_log.cpp: k · kLn2High is exact for |k| < 2^21.
constexpr double kLn2High = 6.93147180369123816490e-01;  // 0x3fe62e42fee00000
constexpr double kLn2Low = 1.90821492927058770002e-10;   // 0x3dea39ef35793c76
constexpr double kInverseLn2 = 1.44269504088896338700e+00;

// 1/k!, k = 1 … 14: with |r| ≤ ½ ln 2 the first omitted term is below 10⁻¹⁸ relative.  Each
// quotient is rounded once, at compile time.
constexpr std::array<double, 14> inverse_factorials() {
  std::array<double, 14> out{};
  double factorial = 1.0;
  for (std::size_t k = 0; k < out.size(); ++k) {
    factorial *= static_cast<double>(k + 1);  // exact up to 14! < 2^53
    out[k] = 1.0 / factorial;
  }
  return out;
}
constexpr std::array<double, 14> kSeries = inverse_factorials();

}  // namespace

double portable_exp(double x) {
  // x = k ln 2 + r, |r| ≤ ½ ln 2 (round is exact; r carries the low part of ln 2 separately).
  const double k = std::round(x * kInverseLn2);
  const double r = (x - k * kLn2High) - k * kLn2Low;
  // e^r = 1 + r Σ_j r^j/(j+1)!: Horner over the Taylor coefficients, in a fixed order.
  double series = kSeries.back();
  for (std::size_t j = kSeries.size() - 1; j-- > 0;) series = kSeries[j] + r * series;
  return std::ldexp(1.0 + r * series, static_cast<int>(k));
}

double portable_root(double x, int d) {
  if (d == 2) return std::sqrt(x);
  // x = m · 2^(3q), m ∈ [½, 4): frexp and the shift of the exponent are exact.
  int exponent = 0;
  double m = std::frexp(x, &exponent);
  const int shift = ((exponent % 3) + 3) % 3;
  m = std::ldexp(m, shift);
  exponent -= shift;
  // Newton's iteration y ← y − (y − m/y²)/3 from y = 1: the first step lands within 26% of ∛m
  // on [½, 4), and quadratic convergence reaches full precision by the seventh; the count is
  // fixed so that the rounding sequence is the same everywhere.  Written as a correction, the
  // last steps round only the small term (within one ulp of the exact root, tested).
  double y = 1.0;
  for (int step = 0; step < 8; ++step) y -= (y - m / (y * y)) / 3.0;
  return std::ldexp(y, exponent / 3);
}

}  // namespace granule
