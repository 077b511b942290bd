// Cramér–Rao bounds for the coefficients of (5.27, 5.29) estimated from n samples of an isotropic
// 2D Maxwellian, in the dimensionless units √2T b^(1), 2T b^(2) (derivation: the header comment of
// test_f1_sampling_variance.cpp).
#pragma once

#include <Eigen/Dense>
#include <array>
#include <cmath>

namespace granule::test_statistics {

// n × the bound on the covariance of (√2T b_0^(1), 2T b_0^(2)): the inverse of the Fisher matrix
// [[Var u, Cov(u, u²)], [Cov(u, u²), Var u²]] of the Rayleigh speed u (2T = 1).  Element (1, 1) is
// also n × the bound on Var b_0^(0).
inline Eigen::Matrix2d maxwellian_means_bound_times_n() {
  Eigen::Matrix2d fisher;
  fisher << 1.0 - M_PI / 4.0, std::sqrt(M_PI) / 4.0, std::sqrt(M_PI) / 4.0, 1.0;
  return fisher.inverse();
}

// √n × the bound on σ of one (cos or sin) component of a harmonic of b^(i), i = 0, 1, 2:
// √(2 [M⁻¹]_ii) with M_ab = ⟨u^{a+b}⟩.
inline std::array<double, 3> maxwellian_harmonic_bound_times_root_n() {
  const double mu1 = std::sqrt(M_PI) / 2.0, mu3 = 3.0 * std::sqrt(M_PI) / 4.0;
  Eigen::Matrix3d moments;
  moments << 1.0, mu1, 1.0, mu1, 1.0, mu3, 1.0, mu3, 2.0;
  const Eigen::Matrix3d inverse = moments.inverse();
  return {std::sqrt(2.0 * inverse(0, 0)), std::sqrt(2.0 * inverse(1, 1)), std::sqrt(2.0 * inverse(2, 2))};
}

}  // namespace granule::test_statistics
