#include "theory/free_gas_stability.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

namespace granule::theory {

namespace {

// Coefficients of the linearised equations (2.23)–(2.25) in the rescaled units.
constexpr double longitudinal_viscosity = 5.0 / 9.0;  // (5/6)(1/2 + 1/6), (2.27)
constexpr double heat_diffusivity = 25.0 / 24.0;      // (2.24)
constexpr double shear_viscosity = 5.0 / 12.0;        // (5/6)(1/2), (2.26)

}  // namespace

Eigen::Matrix3d free_gas_stability_matrix(double K, double eps) {
  const double K2 = K * K;
  Eigen::Matrix3d m;
  // rows: ξ_s, q_s, h_s; columns: ξ, q, h.
  m << -eps - longitudinal_viscosity * K2, K2, K2,  //
      -1.0, -2.0 * eps, 0.0,                        //
      -2.0 / 3.0, -2.0 * eps, -heat_diffusivity * K2 - 3.0 * eps;
  return m;
}

std::array<std::complex<double>, 3> free_gas_eigenvalues(double K, double eps) {
  const Eigen::EigenSolver<Eigen::Matrix3d> solver(free_gas_stability_matrix(K, eps),
                                                   /*computeEigenvectors=*/false);
  const auto& values = solver.eigenvalues();
  std::array<std::complex<double>, 3> out{values(0), values(1), values(2)};
  std::sort(out.begin(), out.end(), [](std::complex<double> a, std::complex<double> b) {
    return a.real() != b.real() ? a.real() > b.real() : a.imag() > b.imag();
  });
  return out;
}

std::array<double, 4> free_gas_characteristic_polynomial(double K, double eps) {
  const double K2 = K * K;
  // (λ + a)(λ + b)(λ + c) + (5/3)K²(λ + d), expanded.
  const double a = eps + longitudinal_viscosity * K2;
  const double b = 2.0 * eps;
  const double c = 3.0 * eps + heat_diffusivity * K2;
  const double d = 7.0 * eps / 5.0 + 5.0 * K2 / 8.0;
  const double g = 5.0 / 3.0 * K2;
  return {1.0, a + b + c, a * b + b * c + a * c + g, a * b * c + g * d};
}

double free_gas_shear_eigenvalue(double K, double eps) { return -eps - shear_viscosity * K * K; }

FreeGasLongWaveModes free_gas_long_wave_eigenvalues(double K, double eps) {
  const double r = K * K / eps;
  return {-eps - r / 3.0, -2.0 * eps - r, -3.0 * eps + 4.0 * r / 3.0};
}

FreeGasShortWaveModes free_gas_short_wave_eigenvalues(double K, double eps) {
  const double K2 = K * K;
  const double heat = -7.0 * eps / 5.0 - 5.0 * K2 / 8.0;
  const std::complex<double> sound{-35.0 * K2 / 72.0 - 23.0 * eps / 10.0, std::sqrt(5.0 / 3.0) * K};
  return {heat, sound};
}

double free_gas_growth_exponent(FreeGasField field, double lambda, double eps) {
  const double p = lambda / eps;  // exp(λs) = (1 + t/t0)^(λ/ε), (2.19)
  switch (field) {
    case FreeGasField::density:  // δρ = ρ0 q T0(0)/T0(t), (2.20)
      return 2.0 + p;
    case FreeGasField::divergence:  // v = u T0(0)/√T0(t), (2.21)
    case FreeGasField::vorticity:
      return 1.0 + p;
    case FreeGasField::temperature:  // δT = T0(0) h, (2.22)
      return p;
  }
  return p;
}

double shear_mode_outlives_cooling_bound(double eps) { return 12.0 * eps / 5.0; }

double heat_conduction_negligible_bound(double eps) { return 48.0 * eps / 25.0; }

}  // namespace granule::theory
