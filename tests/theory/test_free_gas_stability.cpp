// Linear stability of the cooling gas (thesis §2.4.2): the numerical eigenvalues of (2.28)
// against the asymptotic forms (2.30)–(2.34), the elastic Navier–Stokes modes and the
// characteristic polynomial (2.29).
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>

#include "theory/free_gas_stability.hpp"

namespace {

using std::numbers::pi;
namespace th = granule::theory;
using cd = std::complex<double>;

struct Split {
  cd heat;   // the real eigenvalue
  cd sound;  // the eigenvalue with positive imaginary part
};

Split split_modes(double K, double eps) {
  Split out{};
  for (cd z : th::free_gas_eigenvalues(K, eps)) {
    if (z.imag() == 0.0) out.heat = z;
    if (z.imag() > 0.0) out.sound = z;
  }
  return out;
}

TEST(FreeGasStability, LongWaveEigenvaluesApproachEquations230To232) {
  // For K² ≪ ε² the eigenvalues are −ε, −2ε, −3ε shifted by O(K²/ε); the expansion drops O(K²)
  // terms (diagonal entries up to 25K²/24) and O(K⁴/ε³) second-order terms, hence the bound.
  for (double eps : {0.1, 0.01}) {
    for (double ratio : {1e-3, 1e-2}) {
      const double K = ratio * eps;
      const auto num = th::free_gas_eigenvalues(K, eps);
      const auto asym = th::free_gas_long_wave_eigenvalues(K, eps);
      const double tol = 2.0 * K * K + 4.0 * std::pow(K, 4) / std::pow(eps, 3);
      EXPECT_NEAR(num[0].real(), asym.lambda1, tol) << "eps " << eps << " K " << K;
      EXPECT_NEAR(num[1].real(), asym.lambda2, tol) << "eps " << eps << " K " << K;
      EXPECT_NEAR(num[2].real(), asym.lambda3, tol) << "eps " << eps << " K " << K;
    }
  }
}

TEST(FreeGasStability, SecondModeShiftIsMinusKSquaredOverEpsNotAThird) {
  // The thesis prints λ2 = −2ε − K²/(3ε) (2.31). The trace of (2.28) has no K²/ε term, so the
  // three shifts −1/3, c2, +4/3 must sum to zero: c2 = −1. Measured at K = 1e-3 ε, where the
  // neglected O(K²) part contributes O(ε) = 1 % to the coefficient.
  const double eps = 0.01;
  const double K = 1e-3 * eps;
  const double coefficient =
      (th::free_gas_eigenvalues(K, eps)[1].real() + 2.0 * eps) * eps / (K * K);
  EXPECT_NEAR(coefficient, -1.0, 0.02);
}

TEST(FreeGasStability, ShortWaveEigenvaluesApproachEquations233To234) {
  // For ε² ≪ K² ≪ 1: next terms are O(K⁴) and O(ε³/K²) in the real parts, O(K³) and O(ε²/K) in
  // the frequency; unit coefficients bound them (measured coefficients are 0.01–0.25), while an
  // error of even 1 % in 35/72, 5/8, 7/5 or 23/10 would exceed the bound by orders of magnitude.
  for (double eps : {1e-4, 1e-6}) {
    for (double K : {3e-2, 1e-2}) {
      const auto num = split_modes(K, eps);
      const auto asym = th::free_gas_short_wave_eigenvalues(K, eps);
      const double tol_re = std::pow(K, 4) + std::pow(eps, 3) / (K * K);
      const double tol_im = std::pow(K, 3) + eps * eps / K;
      EXPECT_NEAR(num.heat.real(), asym.heat, tol_re) << "eps " << eps << " K " << K;
      EXPECT_NEAR(num.sound.real(), asym.sound.real(), tol_re) << "eps " << eps << " K " << K;
      EXPECT_NEAR(num.sound.imag(), asym.sound.imag(), tol_im) << "eps " << eps << " K " << K;
    }
  }
}

TEST(FreeGasStability, ElasticLimitGivesNavierStokesSoundAndHeatModes) {
  // ε = 0: a dilute monatomic hard-sphere gas. From Chapman–Enskog, η = (5/16σ²)√(mT/π) and
  // κ = (75/64σ²)√(T/(πm)) (per unit of T = kT/m), with n = 6ν/(πσ³) and lengths in units of
  // l0 = (√π/8)σ/ν (2.13), time in l0/√T: kinematic viscosity ν_η = η/(nm), thermal diffusivity
  // χ = κ/(n c_p) with c_p = 5/2. Navier–Stokes then gives sound ±i√(5/3)K − ΓK² with
  // Γ = ½[(4/3)ν_η + (γ − 1)χ], γ = 5/3, and a heat mode −χK².
  const double sigma = 1.0, nu = 0.01, T = 1.0;  // any values: they cancel in reduced units
  const double n = 6.0 * nu / (pi * sigma * sigma * sigma);
  const double l0 = std::sqrt(pi) / 8.0 * sigma / nu;
  const double eta = 5.0 / (16.0 * sigma * sigma) * std::sqrt(T / pi);
  const double kappa = 75.0 / (64.0 * sigma * sigma) * std::sqrt(T / pi);
  const double nu_eta = eta / n / (l0 * std::sqrt(T));
  const double chi = kappa / (n * 2.5) / (l0 * std::sqrt(T));
  const double gamma_ad = 5.0 / 3.0;
  const double Gamma = 0.5 * (4.0 / 3.0 * nu_eta + (gamma_ad - 1.0) * chi);
  const double K = 1e-3;
  const auto modes = split_modes(K, 0.0);
  // corrections are relative O(K²) = 1e-6: tolerance 1e-5 of each term
  EXPECT_NEAR(modes.sound.imag() / K, std::sqrt(gamma_ad), 1e-5);
  EXPECT_NEAR(modes.sound.real() / (K * K), -Gamma, 1e-5);
  EXPECT_NEAR(modes.heat.real() / (K * K), -chi, 1e-5);
  // the decoupled shear mode (2.35) diffuses vorticity with ν_η
  EXPECT_NEAR(th::free_gas_shear_eigenvalue(K, 0.0) / (K * K), -nu_eta, 1e-12);
}

TEST(FreeGasStability, CharacteristicPolynomialVanishesAtTheEigenvalues) {
  // The corrected (2.29), with heat diffusion 25/24, vanishes at Eigen's eigenvalues to rounding
  // (1e-12 of the largest term). The printed 24/25 does not: its residual
  // (25/24 − 24/25)K²(λ + ε + 5K²/9)(λ + 2ε) stays 10⁴ times above that rounding bound.
  for (double eps : {0.3, 0.05}) {
    for (double K : {0.05, 0.4, 2.0}) {
      const auto c = th::free_gas_characteristic_polynomial(K, eps);
      const double printed_c = 3.0 * eps + 24.0 / 25.0 * K * K;
      for (cd z : th::free_gas_eigenvalues(K, eps)) {
        const cd value = ((c[0] * z + c[1]) * z + c[2]) * z + c[3];
        const double scale =
            std::abs(z * z * z) + std::abs(c[1] * z * z) + std::abs(c[2] * z) + std::abs(c[3]);
        EXPECT_LT(std::abs(value), 1e-12 * scale);
        const cd printed = (z + eps + 5.0 / 9.0 * K * K) * (z + 2.0 * eps) * (z + printed_c) +
                           5.0 / 3.0 * K * K * (z + 7.0 / 5.0 * eps + 5.0 / 8.0 * K * K);
        EXPECT_GT(std::abs(printed), 1e-8 * scale);
      }
    }
  }
}

TEST(FreeGasStability, DensityGrowsForLongWavesAndShearModeOutlivesCooling) {
  // (2.36): the leading density mode grows, δρ ∝ (1 + t/t0)^{1 − K²/(3ε²)} for K² ≪ ε².
  const double eps = 0.05;
  const double K = 1e-3 * eps;
  const double lead = th::free_gas_eigenvalues(K, eps)[0].real();
  EXPECT_NEAR(th::free_gas_growth_exponent(th::FreeGasField::density, lead, eps),
              1.0 - K * K / (3.0 * eps * eps), 1e-6);
  // After (2.35): the shear mode decays more slowly than T0 ∝ exp(−2εs) iff K² < 12ε/5.
  const double K2 = th::shear_mode_outlives_cooling_bound(eps);
  EXPECT_GT(th::free_gas_shear_eigenvalue(std::sqrt(0.99 * K2), eps), -2.0 * eps);
  EXPECT_LT(th::free_gas_shear_eigenvalue(std::sqrt(1.01 * K2), eps), -2.0 * eps);
}

}  // namespace
