// Transient linear stability of dilute simple shear flow without convection (thesis §4.1,
// (4.16)–(4.24)). Dimensionless: time in units of 1/γ, the perturbation wavevector
// k = k(cos θ, sin θ) in units of 1/L, δ* = l/(L√ε) (4.12), δ̄ = δ*k, θ in radians from the
// streamwise (x) axis, sqrt_eps = √(1 − ẽ²).
#pragma once

#include <Eigen/Core>
#include <array>
#include <complex>

namespace granule::theory {

// The coefficient of the pressure gradient −∂j(δν + δT) in the momentum equation (4.17).
// thesis: δ*², as printed in (4.17) and (4.19); Figs 4.1–4.4 and (4.22)–(4.24) follow from it.
// consistent: δ*²/π, what (4.2) gives with T0 = l²γ²/(πε) (4.5), δ* = l/(L√ε) (4.12) and the
// very scalings that produce the printed viscous, conduction and heating coefficients.
enum class ShearPressureScaling { thesis, consistent };

// The 4×4 matrix of (4.19) acting on (δv1, δv2, δν, δT) for a mode exp(ik·r̃ + s t̃). Its
// eigenvalues depend on δ* and k only through δ̄ = δ*k (a diagonal similarity).
Eigen::Matrix4cd shear_stability_matrix(
    double delta_star, double k, double theta, double sqrt_eps,
    ShearPressureScaling scaling = ShearPressureScaling::thesis);

// The four growth rates s of (4.19) for δ̄ = δ*k, computed by Eigen, ordered by decreasing real
// part (ties: larger imaginary part first). They are real or come in conjugate pairs.
std::array<std::complex<double>, 4> shear_growth_rates(
    double delta_bar, double theta, double sqrt_eps,
    ShearPressureScaling scaling = ShearPressureScaling::thesis);

// s_m, the root with the largest real part (Figs 4.1–4.4).
std::complex<double> largest_shear_growth_rate(
    double delta_bar, double theta, double sqrt_eps,
    ShearPressureScaling scaling = ShearPressureScaling::thesis);

// Coefficients {1, a3, a2, a1, a0} of s⁴ + a3 s³ + a2 s² + a1 s + a0, the characteristic
// polynomial of (4.19) derived from the matrix (the printed (4.20) has two slips:
// docs/theory.md). With P the pressure coefficient (1 for thesis, 1/π for consistent) and
// S = sin 2θ:
//   a3 = √ε + 6√ε δ̄²/π
//   a2 = δ̄²[2P − (2P + 1/(2π))√ε S + 3ε/π] + 9ε δ̄⁴/π²
//   a1 = δ̄²[εS/π − P√ε] + δ̄⁴[2ε^{3/2}/π² + 6P√ε/π − (2P/π + 1/(2π²)) ε S] + 4ε^{3/2}δ̄⁶/π³
//   a0 = δ̄⁴[ε^{3/2} S/π² − (Pε/π) S²] + 4Pε δ̄⁶/π²
std::array<double, 5> shear_characteristic_polynomial(
    double delta_bar, double theta, double sqrt_eps,
    ShearPressureScaling scaling = ShearPressureScaling::thesis);

// Small-δ̄ roots. thesis: (4.22)–(4.24) with s1 = 0 (a root of the truncated (4.21)):
//   s2 = −√ε + [3P/√ε − 3√ε/π − (2P + 3/(2π)) S] δ̄²,  s3,4 = ±√(P − √ε S/π) δ̄.
// corrected (derived here from the full polynomial): s1 = A0 δ̄²/(√ε b²) and
// s3,4 = ±b δ̄ + c δ̄² with b² = P − √ε S/π, c = −(b⁴ + B b² + A0)/(2√ε b²), where B is the δ̄²
// coefficient of a2 and A0 the δ̄⁴ coefficient of a0: the printed O(δ̄³) error of (4.23)–(4.24)
// is really O(δ̄²). Valid while δ̄ ≪ min(1, b, √ε).
struct ShearSmallDeltaRoots {
  double s1;
  double s2;
  double s3;  // the transiently growing mode
  double s4;
};
ShearSmallDeltaRoots shear_small_delta_roots_thesis(
    double delta_bar, double theta, double sqrt_eps,
    ShearPressureScaling scaling = ShearPressureScaling::thesis);
ShearSmallDeltaRoots shear_small_delta_roots_corrected(
    double delta_bar, double theta, double sqrt_eps,
    ShearPressureScaling scaling = ShearPressureScaling::thesis);

// The direction θ ∈ [0, π) of largest Re s_m at fixed δ̄ and √ε, found on a grid of
// `angle_steps` angles (θ and θ + π are equivalent).
double most_unstable_direction(double delta_bar, double sqrt_eps, int angle_steps = 720,
                               ShearPressureScaling scaling = ShearPressureScaling::thesis);

// The smallest δ̄ in (0, delta_bar_max] where Re s_m(δ̄, θ) changes sign from growth to decay,
// located on a scan of `steps` points and refined by bisection; NaN when Re s_m stays positive.
double marginal_delta_bar(double theta, double sqrt_eps, double delta_bar_max = 4.0,
                          int steps = 400,
                          ShearPressureScaling scaling = ShearPressureScaling::thesis);

}  // namespace granule::theory
