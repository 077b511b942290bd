// Linear stability of the homogeneous cooling state: the dilute, three-dimensional
// Jenkins–Richman equations linearised about Haff cooling (thesis §2.4.2, (2.16)–(2.39)).
// Everything here is dimensionless: K = k l0 is the wavenumber in units of the effective mean
// free path l0 (2.13), λ is a growth rate per unit of the stretched time s (2.19), ε = 1 − ẽ².
#pragma once

#include <Eigen/Core>
#include <array>
#include <complex>

namespace granule::theory {

// The 3×3 matrix of (2.28) acting on (ξ, q, h) = (div u, density, temperature) for a mode
// exp(iK·r'), derived from (2.24), (2.25) and (2.27). Heat diffusion enters as 25/24 (not the
// 24/25 printed in (2.29)).
Eigen::Matrix3d free_gas_stability_matrix(double K, double eps);

// The eigenvalues of (2.28) computed by Eigen, ordered by decreasing real part (a complex pair
// with the positive imaginary part first).
std::array<std::complex<double>, 3> free_gas_eigenvalues(double K, double eps);

// Coefficients {1, c2, c1, c0} of the characteristic polynomial λ³ + c2λ² + c1λ + c0 of (2.28):
// (λ + ε + 5K²/9)(λ + 2ε)(λ + 3ε + 25K²/24) + (5/3)K²(λ + 7ε/5 + 5K²/8), (2.29) corrected.
std::array<double, 4> free_gas_characteristic_polynomial(double K, double eps);

// The decoupled shear (vorticity) mode λΩ = −ε − (5/12)K², (2.35), for all K.
double free_gas_shear_eigenvalue(double K, double eps);

// Asymptotic eigenvalues for K² ≪ ε², (2.30)–(2.32), each up to O(K²): λ1 = −ε − K²/(3ε),
// λ2 = −2ε − K²/ε (the thesis prints −K²/(3ε); the trace and the matrix give −K²/ε),
// λ3 = −3ε + (4/3)K²/ε.
struct FreeGasLongWaveModes {
  double lambda1;
  double lambda2;
  double lambda3;
};
FreeGasLongWaveModes free_gas_long_wave_eigenvalues(double K, double eps);

// Asymptotic eigenvalues for ε² ≪ K² ≪ 1, (2.33)–(2.34): the heat mode −7ε/5 − 5K²/8 and the
// sound pair ±i√(5/3)K − 35K²/72 − 23ε/10 (sound holds the + branch).
struct FreeGasShortWaveModes {
  double heat;
  std::complex<double> sound;
};
FreeGasShortWaveModes free_gas_short_wave_eigenvalues(double K, double eps);

// Which physical field an eigenvalue is read from; the rescalings (2.20)–(2.22) turn a mode
// exp(λs) of (q, ξ, h, Ω) into a power (1 + t/t0)^p of the physical field.
enum class FreeGasField { density, divergence, temperature, vorticity };

// The exponent p of (1 + t/t0)^p, (2.36)–(2.39): p = 2 + λ/ε for δρ, 1 + λ/ε for div v and
// curl v, λ/ε for δT. A density mode with p > 0 grows: the clustering instability.
double free_gas_growth_exponent(FreeGasField field, double lambda, double eps);

// K² below which the shear mode decays more slowly than the homogeneous temperature
// (−2ε < λΩ): K² < 12ε/5 (discussion after (2.35)).
double shear_mode_outlives_cooling_bound(double eps);

// K² below which heat conduction is negligible against dissipation in the nonlinear analysis:
// K² < 48ε/25 (§2.4.3, after (2.47)).
double heat_conduction_negligible_bound(double eps);

}  // namespace granule::theory
