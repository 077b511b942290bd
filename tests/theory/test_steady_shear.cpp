// Steady simple-shear temperature (thesis (3.1), (3.2), (4.5)) and the clustering time scales of
// §4.2, checked against an independent kinetic-theory balance and against each other.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "theory/shear_stability.hpp"
#include "theory/shear_time_scales.hpp"
#include "theory/steady_shear.hpp"

namespace {

using std::numbers::pi;
namespace th = granule::theory;

constexpr double kGamma = 100.0, kSigma = 5.64e-4, kNu = 0.05;

TEST(SteadyShear, JenkinsRichmanTendsToTheBoltzmannBalanceNearElastic) {
  // Dilute disks: viscous heating η γ² with Gass's viscosity η = (1/2σ)√(T/π) (unit mass)
  // balances the collisional loss n ε T ω/2, ω = 2nσ√(πT) (n = 4ν/πσ²). (3.2) must approach
  // the balance as ẽ → 1, with a relative correction O(1 − ẽ): 1e-3 at ẽ = 0.9999.
  const double e = 0.9999;
  const double eps = 1 - e * e;
  const double n = 4 * kNu / (pi * kSigma * kSigma);
  // (1/2σ)√(T/π) γ² = n ε T · nσ√(πT)  ⇒  T = γ² / (2σ² n² ε π)
  const double T_balance = kGamma * kGamma / (2 * kSigma * kSigma * n * n * eps * pi);
  EXPECT_NEAR(th::steady_shear_temperature_jenkins_richman(e, kGamma, kSigma, kNu) / T_balance, 1.0,
              1e-3);
  // (4.5) is half of it: (4.1) dissipates 8/√π ν²ε T^{3/2}/σ, twice the balance above
  // (docs/theory.md, discrepancy list).
  EXPECT_NEAR(th::steady_shear_temperature_kinetic(e, kGamma, kSigma, kNu) / T_balance, 0.5, 1e-3);
}

TEST(SteadyShear, KineticT0BalancesHeatingAndDissipationOfEquation41) {
  // (4.1)'s third and fourth terms for v = (γy, 0): Tr D̂² = 2γ² by (4.4), so
  // (√π/16)σ√T·2γ² = (8/√π)(ν²/σ)ε T^{3/2}  ⇒  T = πσ²γ²/(64 ν² ε). Exact arithmetic.
  for (double e : {0.3, 0.8, 0.99}) {
    const double eps = 1 - e * e;
    const double T = pi * kSigma * kSigma * kGamma * kGamma / (64 * kNu * kNu * eps);
    EXPECT_NEAR(th::steady_shear_temperature_kinetic(e, kGamma, kSigma, kNu) / T, 1.0, 1e-13);
  }
}

TEST(SteadyShear, FitAndJenkinsRichmanAreCloseNearElastic) {
  // "(3.1) and (3.2) yield close results as ẽ approaches unity" (§3.1.1): within 20 % for
  // ẽ ≥ 0.9 (the ẽ → 1 ratio is 32A/π = 0.815), and both diverge like 1/(1 − ẽ).
  for (double e : {0.9, 0.95, 0.99, 0.999}) {
    const double ratio = th::steady_shear_temperature_tan_fit(e, kGamma, kSigma, kNu) /
                         th::steady_shear_temperature_jenkins_richman(e, kGamma, kSigma, kNu);
    EXPECT_NEAR(ratio, 1.0, 0.2) << e;
  }
  // Fig. 3.1 and Fig. 3.3: T̄ ∝ γ² and ∝ (σ/ν̄)² at fixed ẽ.
  const double base = th::steady_shear_temperature_tan_fit(0.8, kGamma, kSigma, kNu);
  EXPECT_NEAR(th::steady_shear_temperature_tan_fit(0.8, 2 * kGamma, kSigma, kNu), 4 * base,
              1e-12 * base);
  EXPECT_NEAR(th::steady_shear_temperature_jenkins_richman(0.8, kGamma, 3 * kSigma, 3 * kNu) /
                  th::steady_shear_temperature_jenkins_richman(0.8, kGamma, kSigma, kNu),
              1.0, 1e-12);
  // The thesis's Fig. 3.1 system: N = 200000 disks in a unit box at ν̄ = 0.05.
  EXPECT_NEAR(th::diameter_for_area_fraction(0.05, 200000, 1.0, 1.0), kSigma, 1e-6);
}

TEST(ShearTimeScales, WindowEdgesAreWhereTheTimeScalesCross) {
  // (4.37)'s lower edge is τm = τc ((4.36) vs (4.6)); (4.39)'s is τ′m = τc ((4.41)); the upper
  // edge kl = √ε is where the linear growth time 1/s3 equals 1/γ ((4.38)). Rounding only.
  const double eps = 0.36, l = 0.01, gamma = 50.0;
  for (double h : {500.0, 5.0}) {
    const bool hot = h > gamma;
    const auto w =
        hot ? th::clustering_window_hot(eps, gamma, h) : th::clustering_window_cold(eps, gamma, h);
    const double k = w.lower / l;
    const double tau = hot ? th::mass_motion_time_hot(k, l, eps, h)
                           : th::mass_motion_time_cold(k, l, eps, h, gamma);
    EXPECT_NEAR(tau * gamma, 1.0, 1e-12);
    EXPECT_NEAR(th::linear_growth_time(w.upper / l, l, eps, gamma) * gamma, 1.0, 1e-12);
    // "(4.39) and (4.40) cannot be satisfied simultaneously" when γ/h > 1; (4.37) is open
    // when γ/h < 1.
    EXPECT_EQ(w.open(), hot);
  }
}

TEST(ShearTimeScales, LinearGrowthTimeIsTheInverseOfEquation423) {
  // 1/s3 in time units: s3 = b δ̄ γ with δ̄ = kl/√ε (δ̄ = δ*k̃, (4.12)); at θ = 0, sin 2θ = 0 and
  // b = 1, so γ s3 · linear_growth_time = 1 at small δ̄ (δ̄ = 1e-3: O(δ̄) relative error).
  const double eps = 0.5, l = 0.002, L = 1.0, gamma = 10.0;
  const int n = 1;
  const double k = 2 * pi * n / L;
  const double d = th::shear_delta_bar_of_mode(n, l, L, eps);
  EXPECT_NEAR(d, k * l / std::sqrt(eps), 1e-15);
  const double small = 1e-3;
  const double s3 = th::shear_small_delta_roots_thesis(small, 0.0, std::sqrt(eps)).s3;
  const double k_small = small * std::sqrt(eps) / l;
  EXPECT_NEAR(s3 * th::linear_growth_time(k_small, l, eps, gamma) * gamma, 1.0, 1e-12);
  EXPECT_NEAR(th::largest_shear_growth_rate(small, 0.0, std::sqrt(eps)).real() / s3, 1.0, 5e-3);
}

}  // namespace
