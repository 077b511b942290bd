// Haff cooling (thesis (2.9)–(2.15)) against direct integration of the cooling equations and a
// Monte Carlo estimate of the kinetic-theory ingredients (collision frequency, loss per
// collision).
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <random>

#include "theory/free_gas_stability.hpp"
#include "theory/haff.hpp"
#include "theory/kinetic_scales.hpp"

namespace {

using std::numbers::pi;
namespace th = granule::theory;

// Classical fourth-order Runge–Kutta for y' = f(y) (autonomous), n steps of size h.
std::vector<double> rk4(std::vector<double> y, double h, int n,
                        const std::function<std::vector<double>(const std::vector<double>&)>& f) {
  auto axpy = [](const std::vector<double>& a, double s, const std::vector<double>& b) {
    std::vector<double> out(a.size());
    for (std::size_t j = 0; j < a.size(); ++j) out[j] = a[j] + s * b[j];
    return out;
  };
  for (int i = 0; i < n; ++i) {
    const auto k1 = f(y);
    const auto k2 = f(axpy(y, h / 2, k1));
    const auto k3 = f(axpy(y, h / 2, k2));
    const auto k4 = f(axpy(y, h, k3));
    for (std::size_t j = 0; j < y.size(); ++j)
      y[j] += h / 6 * (k1[j] + 2 * k2[j] + 2 * k3[j] + k4[j]);
  }
  return y;
}

constexpr double kRestitution = 0.8;
constexpr double kArea = 0.05;
constexpr double kDiameter = 1e-3;
constexpr double kT0 = 2.0;

// dT/dt and dc/dt of a dilute Maxwellian disk gas built from first principles here: number
// density n = 4ν/(πσ²), a disk sweeps a strip 2σ wide at the mean relative speed √(πT), so it
// collides at ω = 2nσ√(πT); each collision removes (1 − ẽ²)T on average and c grows at ω/2.
std::vector<double> disk_gas_rates(const std::vector<double>& y) {
  const double T = y[0];
  const double n = 4.0 * kArea / (pi * kDiameter * kDiameter);
  const double omega = 2.0 * n * kDiameter * std::sqrt(pi * T);
  const double eps = 1.0 - kRestitution * kRestitution;
  return {-0.5 * omega * eps * T, 0.5 * omega};
}

TEST(Haff, TemperatureLawIntegratesTheDiskCoolingEquation) {
  const double t0 = th::haff_time_disks(kT0, kRestitution, kDiameter, kArea);
  // 4000 RK4 steps over 4 t0: the global error ~ (h/t0)⁴ ~ 1e-12, far below the 1e-9 tolerance.
  const int steps = 4000;
  const double t_end = 4.0 * t0;
  const auto y = rk4({kT0, 0.0}, t_end / steps, steps, disk_gas_rates);
  EXPECT_NEAR(y[0] / th::haff_temperature(t_end, kT0, t0), 1.0, 1e-9);
  EXPECT_NEAR(y[1] / th::haff_collisions_per_particle(t_end, t0, kRestitution), 1.0, 1e-9);
  // and the collision-count form T(c) = T0 exp(−εc) along the same trajectory
  EXPECT_NEAR(y[0] / th::haff_temperature_after_collisions(y[1], kT0, kRestitution), 1.0, 1e-9);
}

TEST(Haff, TemperatureDecaysAsInverseSquareTimeAtLateTimes) {
  // (2.10): "it decays as 1/t² for t ≫ t0"; at t = 1e6 t0 the relative correction is 2e-6.
  const double t0 = 0.3;
  const double t = 1e6 * t0;
  EXPECT_NEAR(th::haff_temperature(t, 5.0, t0) * t * t / (5.0 * t0 * t0), 1.0, 3e-6);
}

TEST(Haff, ThesisJenkinsRichmanTimeSolvesEquation29) {
  // (2.9): (3/2)ρ0 Ṫ = −(dρs/σ) T^{3/2} with d = (24/√π) ε ν² (2.7) and ρ0 = ρs ν, written out
  // here independently of the library.
  const double nu = 0.1;
  const double sigma = 0.01;
  const double eps = 1.0 - kRestitution * kRestitution;
  const double d = 24.0 / std::sqrt(pi) * eps * nu * nu;
  auto rate = [&](const std::vector<double>& y) {
    return std::vector<double>{-(2.0 / 3.0) * d / (nu * sigma) * std::pow(y[0], 1.5)};
  };
  const double t0 = th::jenkins_richman_haff_time(kT0, kRestitution, sigma, nu);
  const int steps = 4000;  // as above: RK4 error ~1e-12
  const auto y = rk4({kT0}, 3.0 * t0 / steps, steps, rate);
  EXPECT_NEAR(y[0] / th::haff_temperature(3.0 * t0, kT0, t0), 1.0, 1e-9);
  // (2.14) t0 = l0/(ε√T0) and (2.15) l0 = (3/4)√π l: exact identities, rounding only.
  const double l0 = th::effective_mean_free_path(sigma, nu);
  EXPECT_NEAR(t0, l0 / (eps * std::sqrt(kT0)), 1e-12 * t0);
  EXPECT_NEAR(l0, 0.75 * std::sqrt(pi) * th::sphere_mean_free_path(sigma, nu), 1e-12 * l0);
}

TEST(Haff, TemperaturePerturbationDecaysLikeTheHeatModeAtZeroWavenumber) {
  // A uniform temperature perturbation is the K = 0 eigenmode h of (2.28) with λ = −3ε, so by
  // (2.38) δT ∝ (1 + t/t0)^{−3}. Here δT is the derivative of Haff's law with respect to T0
  // (t0 ∝ 1/√T0), taken by a central difference: the two code paths are independent.
  const double eps = 0.19;
  const auto lambdas = th::free_gas_eigenvalues(0.0, eps);
  const double p =
      th::free_gas_growth_exponent(th::FreeGasField::temperature, lambdas[2].real(), eps);
  const double t0_of_unit_T = 0.7;
  auto T_of = [&](double t, double T0) {
    return th::haff_temperature(t, T0, t0_of_unit_T / std::sqrt(T0));
  };
  const double dT0 = 1e-5;
  for (double x : {0.5, 3.0, 40.0}) {
    const double t = x * t0_of_unit_T;
    const double dT = (T_of(t, 1.0 + dT0) - T_of(t, 1.0 - dT0)) / (2 * dT0);
    // central-difference error ~ dT0² ~ 1e-10 relative
    EXPECT_NEAR(dT / std::pow(1.0 + x, p), 1.0, 1e-8) << "t/t0 = " << x;
  }
}

TEST(Haff, MonteCarloCollisionFrequencyAndEnergyLoss) {
  // Sample pairs of Maxwellian disks (each velocity component N(0, T)) and collision normals k
  // uniform on the circle; a configuration collides at a rate ∝ (g·k)₊ (g = v1 − v2), so
  // ω = nσ ∫dθ (g·k)₊ = 2π nσ ⟨(g·k)₊⟩ and the flux-weighted mean of the energy removed by the
  // collision rule (1.2) is the loss per collision. Fixed seed; 10⁶ samples put the statistical
  // error near 0.2 %, the 1 % tolerance is ≥ 4 standard errors.
  std::mt19937_64 rng(12345);
  std::normal_distribution<double> gauss(0.0, std::sqrt(kT0));
  std::uniform_real_distribution<double> angle(0.0, 2 * pi);
  const int samples = 1000000;
  double flux = 0.0, weighted_loss = 0.0;
  for (int i = 0; i < samples; ++i) {
    const double v1x = gauss(rng), v1y = gauss(rng), v2x = gauss(rng), v2y = gauss(rng);
    const double a = angle(rng);
    const double kx = std::cos(a), ky = std::sin(a);
    const double approach = (v1x - v2x) * kx + (v1y - v2y) * ky;
    if (approach <= 0.0) continue;
    const double J = 0.5 * (1.0 + kRestitution) * approach;  // (1.2)
    const double w1x = v1x - J * kx, w1y = v1y - J * ky, w2x = v2x + J * kx, w2y = v2y + J * ky;
    const double before = 0.5 * (v1x * v1x + v1y * v1y + v2x * v2x + v2y * v2y);
    const double after = 0.5 * (w1x * w1x + w1y * w1y + w2x * w2x + w2y * w2y);
    flux += approach;
    weighted_loss += approach * (before - after);
  }
  const double n = 4.0 * kArea / (pi * kDiameter * kDiameter);
  const double omega_mc = 2 * pi * n * kDiameter * flux / samples;
  EXPECT_NEAR(omega_mc / th::disk_collision_frequency(kT0, kDiameter, kArea), 1.0, 0.01);
  const double loss_per_collision = weighted_loss / flux;
  EXPECT_NEAR(loss_per_collision / (th::inelasticity(kRestitution) * kT0), 1.0, 0.01);
  // the Boltzmann free path ⟨|v|⟩/ω with ⟨|v|⟩ = √(πT/2) for a 2D Maxwellian
  EXPECT_NEAR(std::sqrt(pi * kT0 / 2) / omega_mc / th::boltzmann_mean_free_path(kDiameter, kArea),
              1.0, 0.01);
}

TEST(KineticScales, HendersonContactValueHasTheExactThirdVirialSlope) {
  // For hard disks Z = 1 + 2νχ and Z = 1 + B2 n + B3 n² + …, with B3/B2² = 4/3 − √3/π, so
  // χ = 1 + 2(4/3 − √3/π)ν + O(ν²) = 1 + 1.5640ν; Henderson's 25/16 = 1.5625 is within 0.2 %.
  const double nu = 1e-6;
  const double slope = (th::henderson_contact_value(nu) - 1.0) / nu;
  EXPECT_NEAR(slope / (2.0 * (4.0 / 3.0 - std::sqrt(3.0) / pi)), 1.0, 2e-3);
}

TEST(KineticScales, ClusterSeparationFollowsEquation11) {
  // L0 ≈ l/√(1 − ẽ²), l = πσ/8ν: for ẽ = 0.6, 1 − ẽ² = 0.64 and L0 = l/0.8 (exact arithmetic).
  const double l = pi * 2e-3 / (8 * 0.05);
  EXPECT_NEAR(th::cluster_separation(0.6, 2e-3, 0.05), l / 0.8, 1e-14);
}

}  // namespace
