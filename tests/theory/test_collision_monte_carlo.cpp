// Monte Carlo over Maxwellian collision configurations (fixed seeds) against the closed forms of
// homogeneous_cooling.hpp and enskog_mixture.hpp: the energy lost per collision, the Sonine
// corrections to the collision frequency and the dissipation, and the collision frequency of
// unequal masses. The samples are velocities of two particles and a contact direction k uniform
// on the circle or sphere; a configuration collides at a rate ∝ (g·k)₊ with g = v1 − v2, and
// since k and −k are equally likely the weight |g·k| over all samples is the same average.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <vector>

#include "theory/enskog_mixture.hpp"
#include "theory/homogeneous_cooling.hpp"

namespace {

using std::numbers::pi;
namespace th = granule::theory;

struct Estimate {
  double mean;
  double standard_error;
};

// Running sums of w and w wᵀ over samples w = (a, b, c_1, …, c_K), enough to estimate the ratio
// E[a]/E[b] with control variates c_k whose true means are zero: the residual r = a − r0 b
// (r0 = ā/b̄, the delta method) is regressed on the c_k, and subtracting the fitted multiple of
// their sample means keeps the estimate unbiased (to O(1/N)) while removing the share of the
// variance they explain. A plain mean of a is the ratio with b = 1.
class ControlVariateRatio {
 public:
  explicit ControlVariateRatio(int controls)
      : sum_(Eigen::VectorXd::Zero(controls + 2)),
        outer_(Eigen::MatrixXd::Zero(controls + 2, controls + 2)) {}

  void add(const Eigen::VectorXd& w) {
    sum_ += w;
    outer_.noalias() += w * w.transpose();
    count_ += 1.0;
  }

  Estimate estimate() const {
    const Eigen::Index k = sum_.size() - 2;
    const Eigen::VectorXd mean = sum_ / count_;
    const Eigen::MatrixXd cov =
        (outer_ / count_ - mean * mean.transpose()) * (count_ / (count_ - 1.0));
    const double r0 = mean(0) / mean(1);
    const double var_r = cov(0, 0) - 2.0 * r0 * cov(0, 1) + r0 * r0 * cov(1, 1);
    const Eigen::VectorXd cov_rc = cov.block(2, 0, k, 1) - r0 * cov.block(2, 1, k, 1);
    const Eigen::VectorXd beta = cov.block(2, 2, k, k).ldlt().solve(cov_rc);
    const double correction = -beta.dot(mean.tail(k));  // the mean of r is 0 by choice of r0
    const double var_residual = var_r - cov_rc.dot(beta);
    return {r0 + correction / mean(1), std::sqrt(var_residual / count_) / mean(1)};
  }

 private:
  Eigen::VectorXd sum_;
  Eigen::MatrixXd outer_;
  double count_ = 0.0;
};

using Vec = Eigen::Vector3d;  // the third component stays 0 in 2D

struct Sampler {
  std::mt19937_64 rng;
  std::normal_distribution<double> gauss{0.0, 1.0};
  std::uniform_real_distribution<double> uniform{-1.0, 1.0};

  // Maxwellian velocity: each of the d components N(0, T/m).
  Vec velocity(int d, double T, double m) {
    const double s = std::sqrt(T / m);
    return {s * gauss(rng), s * gauss(rng), d == 3 ? s * gauss(rng) : 0.0};
  }
  // Uniform direction on the circle (d = 2), or on the sphere (d = 3: by Archimedes, the axial
  // component of a uniform direction is uniform on [−1, 1]).
  Vec direction(int d) {
    const double azimuth = pi * uniform(rng);
    const double axial = d == 3 ? uniform(rng) : 0.0;
    const double radial = std::sqrt(1.0 - axial * axial);
    return {radial * std::cos(azimuth), radial * std::sin(azimuth), axial};
  }
};

TEST(CollisionMonteCarlo, MaxwellianEnergyLossPerCollision) {
  // ΔE = (1 − e²)(μ/2)(g·k)² with μ = m/2, weighted by |g·k|, over the pair's mean energy d·T.
  // The relative velocity g of two Maxwellian particles is Maxwellian with the reduced mass μ.
  // Controls: x = g·k is Gaussian of variance T/μ, so x² − T/μ and x⁴ − 3(T/μ)² have mean zero;
  // they remove ~97 % of the variance. 1.5·10⁶ samples put the standard error near 2.4·10⁻⁴; the
  // 10⁻³ tolerance is ≥ 4 of them, and the test requires the error to be that small.
  const double e = 0.8, T = 1.3, mu = 2.0 / 2.0;
  const int samples = 1500000;
  for (int d : {2, 3}) {
    Sampler sampler{std::mt19937_64(2024 + static_cast<unsigned>(d))};
    ControlVariateRatio accumulator(2);
    Eigen::VectorXd w(4);
    for (int s = 0; s < samples; ++s) {
      const Vec g = sampler.velocity(d, T, mu);
      const double x = g.dot(sampler.direction(d));
      const double loss = (1.0 - e * e) * 0.5 * mu * x * x;
      const double variance = T / mu;
      w << std::abs(x) * loss, std::abs(x), x * x - variance,
          x * x * x * x - 3.0 * variance * variance;
      accumulator.add(w);
    }
    const Estimate loss = accumulator.estimate();
    const double fraction = loss.mean / (d * T);
    const double expected = th::energy_loss_per_collision(d, e, 0.0);
    std::printf("d = %d: energy lost per collision / (d T) = %.6f ± %.6f, closed form %.6f\n", d,
                fraction, loss.standard_error / (d * T), expected);
    EXPECT_LT(loss.standard_error / (d * T) / expected, 2.5e-4);
    EXPECT_NEAR(fraction / expected, 1.0, 1e-3) << "d = " << d;
  }
}

TEST(CollisionMonteCarlo, SonineCorrectionsOfCollisionFrequencyAndDissipation) {
  // For f = f_M(1 + a2 S2(c²)), c = v/√(2T/m), S2(u) = u²/2 − (d + 2)u/2 + d(d + 2)/8, the
  // first-order change of ⟨|g|^p⟩ over two independent particles is a2 κ_p ⟨|g|^p⟩_M with
  // κ_p = ⟨(S2(c1²) + S2(c2²))|g|^p⟩_M/⟨|g|^p⟩_M. The library's factors claim κ1 = −1/16
  // (frequency) and κ3 = 3/16 (dissipation) in any d. Controls: S2(c1²), S2(c2²) (mean zero).
  // 10⁶ samples: standard errors near 0.0013 (p = 1) and 0.007 (p = 3); tolerances 4.5 of them,
  // enough to tell 3/16 from 1/16 or 0.
  const int samples = 1000000;
  for (int d : {2, 3}) {
    Sampler sampler{std::mt19937_64(77 + static_cast<unsigned>(d))};
    auto S2 = [d](double u) { return u * u / 2.0 - (d + 2) * u / 2.0 + d * (d + 2) / 8.0; };
    ControlVariateRatio frequency(2), dissipation(2);
    Eigen::VectorXd w(4);
    for (int s = 0; s < samples; ++s) {
      // thermal units 2T/m = 1: components N(0, 1/2)
      const Vec c1 = sampler.velocity(d, 0.5, 1.0);
      const Vec c2 = sampler.velocity(d, 0.5, 1.0);
      const double g = (c1 - c2).norm();
      const double s1 = S2(c1.squaredNorm()), s2 = S2(c2.squaredNorm());
      w << (s1 + s2) * g, g, s1, s2;
      frequency.add(w);
      w << (s1 + s2) * g * g * g, g * g * g, s1, s2;
      dissipation.add(w);
    }
    const Estimate kappa1 = frequency.estimate();
    const Estimate kappa3 = dissipation.estimate();
    const double a2 = 0.1;
    std::printf("d = %d: kappa1 = %.4f ± %.4f (factor %.4f), kappa3 = %.4f ± %.4f (factor %.4f)\n",
                d, kappa1.mean, kappa1.standard_error,
                (th::sonine_collision_frequency_factor(a2) - 1.0) / a2, kappa3.mean,
                kappa3.standard_error, (th::sonine_cooling_rate_factor(a2) - 1.0) / a2);
    EXPECT_NEAR(kappa1.mean, (th::sonine_collision_frequency_factor(a2) - 1.0) / a2, 0.006);
    EXPECT_NEAR(kappa3.mean, (th::sonine_cooling_rate_factor(a2) - 1.0) / a2, 0.03);
  }
}

TEST(CollisionMonteCarlo, CollisionFrequencyOfUnequalMasses) {
  // ω_ij = n_j g_ij σ_ij^{d−1} ∫dk (g·k)₊ = n_j g_ij σ_ij^{d−1} (S_d/2) ⟨|g·k|⟩ with S_d = 2π, 4π
  // the measure of directions, the two velocities drawn with their own masses (1 and 8). Control:
  // (g·k)² − T(1/m_i + 1/m_j). 10⁶ samples: standard error ≈ 3·10⁻⁴; tolerance 1.5·10⁻³.
  const double T = 0.9;
  const std::vector<th::MixtureSpecies> mix = {{1.0, 1.0, 0.05}, {2.0, 8.0, 0.01}};
  const int samples = 1000000;
  for (int d : {2, 3}) {
    Sampler sampler{std::mt19937_64(31 + static_cast<unsigned>(d))};
    ControlVariateRatio accumulator(1);
    Eigen::VectorXd w(3);
    for (int s = 0; s < samples; ++s) {
      const Vec g = sampler.velocity(d, T, mix[0].mass) - sampler.velocity(d, T, mix[1].mass);
      const double x = g.dot(sampler.direction(d));
      w << std::abs(x), 1.0, x * x - T * (1.0 / mix[0].mass + 1.0 / mix[1].mass);
      accumulator.add(w);
    }
    const Estimate mean_speed = accumulator.estimate();
    const double sigma = 1.5;
    const double directions = d == 2 ? 2.0 * pi : 4.0 * pi;
    const double prefactor = mix[1].number_density * th::mixture_contact_value(d, mix, 0, 1) *
                             std::pow(sigma, d - 1) * directions / 2.0;
    const double omega = th::species_pair_collision_frequency(d, mix, 0, 1, T);
    std::printf("d = %d: omega_01 Monte Carlo %.6f ± %.6f, Enskog %.6f\n", d,
                prefactor * mean_speed.mean, prefactor * mean_speed.standard_error, omega);
    EXPECT_LT(mean_speed.standard_error / mean_speed.mean, 4e-4);
    EXPECT_NEAR(prefactor * mean_speed.mean / omega, 1.0, 1.5e-3) << "d = " << d;
  }
}

}  // namespace
