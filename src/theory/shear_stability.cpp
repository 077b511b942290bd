#include "theory/shear_stability.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace granule::theory {

using std::numbers::pi;

namespace {

double pressure_coefficient(ShearPressureScaling scaling) {
  return scaling == ShearPressureScaling::thesis ? 1.0 : 1.0 / pi;
}

struct SmallDeltaCoefficients {
  double b2;  // s3,4 ≈ ±√b2 δ̄
  double B;   // δ̄² coefficient of a2
  double A0;  // δ̄⁴ coefficient of a0
  double a;   // δ̄² coefficient of s2
};

SmallDeltaCoefficients small_delta_coefficients(double theta, double r, double P) {
  const double S = std::sin(2.0 * theta);
  SmallDeltaCoefficients c{};
  c.b2 = P - r * S / pi;
  c.B = 2.0 * P - (2.0 * P + 1.0 / (2.0 * pi)) * r * S + 3.0 * r * r / pi;
  c.A0 = r * r * r * S / (pi * pi) - P * r * r * S * S / pi;
  c.a = 3.0 * P / r - 3.0 * r / pi - (2.0 * P + 3.0 / (2.0 * pi)) * S;
  return c;
}

}  // namespace

Eigen::Matrix4cd shear_stability_matrix(double delta_star, double k, double theta, double sqrt_eps,
                                        ShearPressureScaling scaling) {
  using C = std::complex<double>;
  const C i{0.0, 1.0};
  const double r = sqrt_eps;
  const double c = std::cos(theta);
  const double s = std::sin(theta);
  const double d2 = delta_star * delta_star;
  const double p = pressure_coefficient(scaling) * d2;
  const double viscous = -r / pi * d2 * k * k;           // (√ε/π)δ*²Δ, (4.17)
  const double conduction = -4.0 / pi * r * d2 * k * k;  // (4√ε/π)δ*²Δ, (4.16)
  const double shear_stress = r * d2 / (2.0 * pi);       // (√ε δ*²/2π) ∂δT term of (4.17)
  Eigen::Matrix4cd m;
  // rows/columns: δv1, δv2, δν, δT
  m << viscous, 0.0, -i * p * k * c, i * k * (shear_stress * s - p * c),  //
      0.0, viscous, -i * p * k * s, i * k * (shear_stress * c - p * s),   //
      -i * k * c, -i * k * s, 0.0, 0.0,                                   // δν̇ = −div δv
      i * k * (2.0 * r * s - c), i * k * (2.0 * r * c - s), -2.0 * r, -r + conduction;
  return m;
}

std::array<std::complex<double>, 4> shear_growth_rates(double delta_bar, double theta,
                                                       double sqrt_eps,
                                                       ShearPressureScaling scaling) {
  // δ* = 1, k = δ̄ is similar to any (δ*, k) with δ*k = δ̄.
  const Eigen::ComplexEigenSolver<Eigen::Matrix4cd> solver(
      shear_stability_matrix(1.0, delta_bar, theta, sqrt_eps, scaling),
      /*computeEigenvectors=*/false);
  const auto& values = solver.eigenvalues();
  std::array<std::complex<double>, 4> out{values(0), values(1), values(2), values(3)};
  std::sort(out.begin(), out.end(), [](std::complex<double> a, std::complex<double> b) {
    return a.real() != b.real() ? a.real() > b.real() : a.imag() > b.imag();
  });
  return out;
}

std::complex<double> largest_shear_growth_rate(double delta_bar, double theta, double sqrt_eps,
                                               ShearPressureScaling scaling) {
  return shear_growth_rates(delta_bar, theta, sqrt_eps, scaling)[0];
}

std::array<double, 5> shear_characteristic_polynomial(double delta_bar, double theta,
                                                      double sqrt_eps,
                                                      ShearPressureScaling scaling) {
  const double P = pressure_coefficient(scaling);
  const double r = sqrt_eps;
  const double e = r * r;
  const double S = std::sin(2.0 * theta);
  const double d2 = delta_bar * delta_bar;
  const double d4 = d2 * d2;
  const double d6 = d4 * d2;
  const double pi2 = pi * pi;
  const double a3 = r + 6.0 * r * d2 / pi;
  const double a2 =
      d2 * (2.0 * P - (2.0 * P + 1.0 / (2.0 * pi)) * r * S + 3.0 * e / pi) + 9.0 * e * d4 / pi2;
  const double a1 =
      d2 * (e * S / pi - P * r) +
      d4 * (2.0 * e * r / pi2 + 6.0 * P * r / pi - (2.0 * P / pi + 1.0 / (2.0 * pi2)) * e * S) +
      4.0 * e * r * d6 / (pi2 * pi);
  const double a0 = d4 * (e * r * S / pi2 - P * e * S * S / pi) + 4.0 * P * e * d6 / pi2;
  return {1.0, a3, a2, a1, a0};
}

ShearSmallDeltaRoots shear_small_delta_roots_thesis(double delta_bar, double theta, double sqrt_eps,
                                                    ShearPressureScaling scaling) {
  const auto c = small_delta_coefficients(theta, sqrt_eps, pressure_coefficient(scaling));
  const double d = delta_bar;
  const double s3 = std::sqrt(c.b2) * d;
  return {0.0, -sqrt_eps + c.a * d * d, s3, -s3};
}

ShearSmallDeltaRoots shear_small_delta_roots_corrected(double delta_bar, double theta,
                                                       double sqrt_eps,
                                                       ShearPressureScaling scaling) {
  const auto c = small_delta_coefficients(theta, sqrt_eps, pressure_coefficient(scaling));
  const double r = sqrt_eps;
  const double d = delta_bar;
  const double b = std::sqrt(c.b2);
  const double second_order = -(c.b2 * c.b2 + c.B * c.b2 + c.A0) / (2.0 * r * c.b2);
  return {c.A0 * d * d / (r * c.b2), -r + c.a * d * d, b * d + second_order * d * d,
          -b * d + second_order * d * d};
}

double most_unstable_direction(double delta_bar, double sqrt_eps, int angle_steps,
                               ShearPressureScaling scaling) {
  double best_theta = 0.0;
  double best_rate = -std::numeric_limits<double>::infinity();
  for (int j = 0; j < angle_steps; ++j) {
    const double theta = pi * j / angle_steps;
    const double rate = largest_shear_growth_rate(delta_bar, theta, sqrt_eps, scaling).real();
    if (rate > best_rate) {
      best_rate = rate;
      best_theta = theta;
    }
  }
  return best_theta;
}

double marginal_delta_bar(double theta, double sqrt_eps, double delta_bar_max, int steps,
                          ShearPressureScaling scaling) {
  auto rate = [&](double d) {
    return largest_shear_growth_rate(d, theta, sqrt_eps, scaling).real();
  };
  double lo = delta_bar_max / steps;
  if (rate(lo) <= 0.0) return std::numeric_limits<double>::quiet_NaN();
  for (int j = 2; j <= steps; ++j) {
    double hi = delta_bar_max * j / steps;
    if (rate(hi) <= 0.0) {
      for (int it = 0; it < 60; ++it) {  // bisection to double precision
        const double mid = 0.5 * (lo + hi);
        if (rate(mid) > 0.0) {
          lo = mid;
        } else {
          hi = mid;
        }
      }
      return 0.5 * (lo + hi);
    }
    lo = hi;
  }
  return std::numeric_limits<double>::quiet_NaN();
}

}  // namespace granule::theory
