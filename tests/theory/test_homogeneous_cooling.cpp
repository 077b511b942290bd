// Homogeneous cooling in d dimensions (homogeneous_cooling.hpp) against the printed d = 2 and
// d = 3 forms of the Sonine coefficient, its exact zeros, the 2D Haff functions the thesis's
// analysis uses (haff.hpp), and the cooling equations differentiated numerically. The Maxwellian
// and Sonine averages themselves are checked by Monte Carlo in test_collision_monte_carlo.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "theory/haff.hpp"
#include "theory/hard_spheres.hpp"
#include "theory/homogeneous_cooling.hpp"
#include "theory/kinetic_scales.hpp"

namespace {

namespace th = granule::theory;

TEST(HomogeneousCooling, SonineCoefficientMatchesThePrintedTwoAndThreeDimensionalForms) {
  // d = 3: a2 = 16(1 − e)(1 − 2e²)/(81 − 17e + 30e²(1 − e)); d = 2: the same with 57 − 25e
  // (Brilliantov and Pöschel, Kinetic Theory of Granular Gases (2004), and van Noije and Ernst
  // (1998) at d = 3 and 2).
  std::printf("e      a2(d=2)     a2(d=3)\n");
  for (double e : {0.0, 0.3, 0.5, 0.7, 0.8, 0.9, 0.95, 0.99}) {
    const double num = 16.0 * (1.0 - e) * (1.0 - 2.0 * e * e);
    const double tail = 30.0 * e * e * (1.0 - e);
    std::printf("%.2f  %+.6f  %+.6f\n", e, th::sonine_a2(e, 2), th::sonine_a2(e, 3));
    EXPECT_NEAR(th::sonine_a2(e, 3), num / (81.0 - 17.0 * e + tail), 1e-15) << "e = " << e;
    EXPECT_NEAR(th::sonine_a2(e, 2), num / (57.0 - 25.0 * e + tail), 1e-15) << "e = " << e;
  }
  EXPECT_NEAR(th::sonine_a2(0.0, 3), 16.0 / 81.0, 1e-15);
}

TEST(HomogeneousCooling, SonineCoefficientVanishesWhereTheTheorySaysItMust) {
  // Elastic gas: Maxwellian, a2 = 0. At e = 1/√2 the factor 1 − 2e² vanishes: the fourth
  // moment's collisional production matches the cooling with a Maxwellian. To first order in
  // 1 − e, a2 ≈ −(1 − e)/(2(d − 1)) (denominator 32(d − 1) at e = 1): negative, so the
  // quasi-elastic distribution is flatter than a Maxwellian.
  for (int d : {2, 3}) {
    EXPECT_EQ(th::sonine_a2(1.0, d), 0.0);
    EXPECT_NEAR(th::sonine_a2(1.0 / std::sqrt(2.0), d), 0.0, 1e-16);
    const double eps = 1e-6;
    EXPECT_NEAR(th::sonine_a2(1.0 - eps, d) / (-eps / (2.0 * (d - 1))), 1.0, 1e-5);
    EXPECT_GT(th::sonine_a2(0.5, d), 0.0);
    EXPECT_LT(th::sonine_a2(0.9, d), 0.0);
  }
  EXPECT_THROW(th::sonine_a2(0.9, 4), std::invalid_argument);
}

TEST(HomogeneousCooling, TwoDimensionalMaxwellianCaseIsTheThesisHaffLaw) {
  // d = 2 with a2 = 0 must reproduce the functions the 2D analysis already uses.
  const double e = 0.8, sigma = 1e-3, nu = 0.05, T0 = 2.0;
  const double n = th::number_density(2, nu, sigma);
  const double omega0 = th::hard_sphere_collision_frequency(2, n, sigma, 1.0, T0, 1.0);
  const double t0 = th::homogeneous_cooling_time(2, e, omega0, 0.0);
  EXPECT_NEAR(t0 / th::haff_time_disks(T0, e, sigma, nu), 1.0, 1e-14);
  for (double x : {0.1, 1.0, 10.0}) {
    EXPECT_NEAR(th::collisions_per_particle(2, x * t0, t0, e, 0.0) /
                    th::haff_collisions_per_particle(x * t0, t0, e),
                1.0, 1e-14);
    EXPECT_NEAR(th::temperature_after_collisions(2, x, T0, e, 0.0) /
                    th::haff_temperature_after_collisions(x, T0, e),
                1.0, 1e-14);
  }
  EXPECT_NEAR(th::energy_loss_per_collision(2, e, 0.0), th::inelasticity(e) / 2.0, 1e-16);
}

TEST(HomogeneousCooling, SpheresCoolAtTheRateTheCollisionsImply) {
  // 3D with its Sonine coefficient: Haff's law T(t) = T0/(1 + t/t0)² with t0 from ω(T0) must
  // satisfy dT/dt = −ζ(T)T with ζ ∝ ω_M(T) ∝ √T, the collision count must grow at
  // dc/dt = ω(T)/2 with the Sonine-corrected ω = ω_M(1 − a2/16), and T(c(t)) = T(t). The
  // derivatives are central differences (relative error ~ (h/t0)² ~ 10⁻¹⁰).
  const double e = 0.7, sigma = 0.01, phi = 0.1, T0 = 3.0, m = 1.0;
  const double a2 = th::sonine_a2(e, 3);
  const double n = th::number_density(3, phi, sigma);
  const double chi = th::carnahan_starling_contact_value(phi);
  auto omega_maxwell = [&](double T) {
    return th::hard_sphere_collision_frequency(3, n, sigma, chi, T, m);
  };
  const double t0 = th::homogeneous_cooling_time(3, e, omega_maxwell(T0), a2);
  const double h = 1e-5 * t0;
  auto T_of = [&](double t) { return th::haff_temperature(t, T0, t0); };
  auto c_of = [&](double t) { return th::collisions_per_particle(3, t, t0, e, a2); };
  for (double x : {0.3, 2.0, 30.0}) {
    const double t = x * t0;
    const double T = T_of(t);
    const double dTdt = (T_of(t + h) - T_of(t - h)) / (2 * h);
    const double zeta = th::homogeneous_cooling_rate(3, e, omega_maxwell(T), a2);
    EXPECT_NEAR(dTdt / (-zeta * T), 1.0, 1e-8) << "t/t0 = " << x;
    const double dcdt = (c_of(t + h) - c_of(t - h)) / (2 * h);
    const double omega = omega_maxwell(T) * th::sonine_collision_frequency_factor(a2);
    EXPECT_NEAR(dcdt / (omega / 2.0), 1.0, 1e-8) << "t/t0 = " << x;
    EXPECT_NEAR(th::temperature_after_collisions(3, c_of(t), T0, e, a2) / T, 1.0, 1e-12);
  }
}

}  // namespace
