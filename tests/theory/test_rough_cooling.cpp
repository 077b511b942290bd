// Homogeneous cooling of rough grains (rough_cooling.hpp) against exact limits (smooth grains are
// the smooth theory of homogeneous_cooling.hpp with a frozen spin; e = β = 1 conserves energy and
// equipartition), the printed 3D coefficients of Huthmann and Zippelius (1997) and the printed 3D
// temperature ratio of Santos, Kremer and dos Santos (2011), and the three solutions against each
// other's independent routes (exact in c, Runge–Kutta in c from the per-collision energy changes,
// Runge–Kutta in t, Haff's law of the cooling state). The per-collision averages themselves are
// checked by Monte Carlo in test_rough_collision_monte_carlo.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "theory/haff.hpp"
#include "theory/hard_spheres.hpp"
#include "theory/homogeneous_cooling.hpp"
#include "theory/rough_cooling.hpp"

namespace {

namespace th = granule::theory;

TEST(RoughCooling, SmoothGrainsCoolAsTheSmoothTheoryAndKeepTheirSpin) {
  for (int d : {2, 3}) {
    for (double e : {0.3, 0.8, 1.0}) {
      const th::RoughGrains smooth{e, -1.0, d == 2 ? 0.5 : 0.4};
      const double omega = 3.7, t_tr = 1.9, t_rot = 0.6;
      const th::RoughTemperatures rates = th::rough_cooling_rates(d, smooth, {t_tr, t_rot}, omega);
      EXPECT_NEAR(rates.translational, -th::homogeneous_cooling_rate(d, e, omega, 0.0) * t_tr,
                  1e-14);
      EXPECT_EQ(rates.rotational, 0.0);
      if (e < 1.0) {
        EXPECT_TRUE(std::isinf(th::rough_temperature_ratio(d, smooth)));
        EXPECT_NEAR(th::rough_homogeneous_cooling_time(d, smooth, omega),
                    th::homogeneous_cooling_time(d, e, omega, 0.0), 1e-14);
      } else {
        EXPECT_TRUE(std::isnan(th::rough_temperature_ratio(d, smooth)));
      }
    }
  }
}

TEST(RoughCooling, ElasticPerfectlyRoughGrainsConserveEnergyAndReachEquipartition) {
  // e = β = 1: every collision conserves energy, so d T_tr + d_rot T_rot is constant, and
  // A = B = C = q/(1 + q)²; the cooling state is equipartition R = 1.
  for (int d : {2, 3}) {
    for (double q : {0.4, 0.5, 2.0 / 3.0, 1.0}) {
      const th::RoughGrains grains{1.0, 1.0, q};
      const th::RoughCoolingCoefficients k = th::rough_cooling_coefficients(d, grains);
      const double expected = q / ((1.0 + q) * (1.0 + q));
      EXPECT_NEAR(k.translational_loss, expected, 1e-15);
      EXPECT_NEAR(k.exchange, expected, 1e-15);
      EXPECT_NEAR(k.rotational_loss, expected, 1e-15);
      EXPECT_NEAR(th::rough_temperature_ratio(d, grains), 1.0, 1e-15);
      const th::RoughTemperatures rates = th::rough_cooling_rates(d, grains, {2.5, 0.3}, 1.1);
      EXPECT_NEAR(d * rates.translational + th::rotational_degrees_of_freedom(d) * rates.rotational,
                  0.0, 1e-14);
      EXPECT_LT(rates.translational, 0.0);  // energy flows into the cold spin
      const th::RoughTemperatures late =
          th::rough_temperatures_after_collisions(d, grains, {2.5, 0.3}, 200.0);
      const double total = d * 2.5 + th::rotational_degrees_of_freedom(d) * 0.3;
      EXPECT_NEAR(d * late.translational + th::rotational_degrees_of_freedom(d) * late.rotational,
                  total, 1e-13 * total);
      EXPECT_NEAR(late.rotational / late.translational, 1.0, 1e-12);
    }
  }
}

TEST(RoughCooling, ThreeDimensionalCoefficientsArePrintedOnes) {
  // Huthmann and Zippelius, PRE 56, R6275 (1997): A = (1 − e²)/4 + η(1 − η), B = η²/q,
  // C = (η/q)(1 − η/q), η = q(1 + β)/(2(1 + q)), G√T = (4/3)ω, equal factors in both equations.
  for (double e : {0.2, 0.7, 0.95}) {
    for (double beta : {-0.8, 0.0, 0.5, 1.0}) {
      const double q = 0.4;
      const double eta = q * (1.0 + beta) / (2.0 * (1.0 + q));
      const th::RoughCoolingCoefficients k = th::rough_cooling_coefficients(3, {e, beta, q});
      EXPECT_NEAR(k.translational_loss, (1.0 - e * e) / 4.0 + eta * (1.0 - eta), 1e-15);
      EXPECT_NEAR(k.exchange, eta * eta / q, 1e-15);
      EXPECT_NEAR(k.rotational_loss, eta / q * (1.0 - eta / q), 1e-15);
      EXPECT_EQ(k.rotational_factor, 1.0);
      EXPECT_NEAR(k.rate_per_collision_frequency, 4.0 / 3.0, 1e-15);
    }
  }
}

TEST(RoughCooling, ThreeDimensionalTemperatureRatioIsThePrintedOne) {
  // Maxwellian cooling state of rough spheres as written by Santos, Kremer and dos Santos, Phys.
  // Fluids 23, 030604 (2011) (arXiv:1009.6180): θ = T_rot/T_tr = h + √(1 + h²),
  // h = (1 + κ)/(2κ(1 + β)) [(1 + κ)(1 − α²)/(1 + β) − (1 − κ)(1 − β)], κ = q, α = e.
  std::printf("3D, q = 2/5:  e      beta    R\n");
  for (double e : {0.5, 0.8, 0.9, 0.99, 1.0}) {
    for (double beta : {-0.9, -0.5, 0.0, 0.5, 1.0}) {
      const double kappa = 0.4;
      const double h =
          (1.0 + kappa) / (2.0 * kappa * (1.0 + beta)) *
          ((1.0 + kappa) * (1.0 - e * e) / (1.0 + beta) - (1.0 - kappa) * (1.0 - beta));
      const double printed = h + std::sqrt(1.0 + h * h);
      const double ratio = th::rough_temperature_ratio(3, {e, beta, kappa});
      std::printf("            %.2f  %+.2f  %.6f\n", e, beta, ratio);
      EXPECT_NEAR(ratio / printed, 1.0, 1e-12) << "e = " << e << ", beta = " << beta;
    }
  }
}

TEST(RoughCooling, CoolingStateRatioIsStationaryAndAttracting) {
  // At R the two temperatures decay at one rate: d ln T_rot/dt = d ln T_tr/dt; from any start,
  // T_rot/T_tr tends to R.
  for (int d : {2, 3}) {
    for (const th::RoughGrains grains :
         {th::RoughGrains{0.7, 0.4, d == 2 ? 0.5 : 0.4}, th::RoughGrains{0.95, -0.5, 0.5},
          th::RoughGrains{0.6, 1.0, 0.4}, th::RoughGrains{0.99, 0.0, 0.5}}) {
      const double ratio = th::rough_temperature_ratio(d, grains);
      const th::RoughTemperatures rates = th::rough_cooling_rates(d, grains, {1.0, ratio}, 2.0);
      std::printf("d = %d, e = %.2f, beta = %+.2f, q = %.2f: R = %.6f\n", d,
                  grains.normal_restitution, grains.tangential_restitution, grains.inertia_factor,
                  ratio);
      EXPECT_GT(ratio, 0.0);
      EXPECT_NEAR(rates.rotational / ratio, rates.translational, 1e-13);
      for (double start : {0.0, 0.3, 5.0}) {
        const th::RoughTemperatures late =
            th::rough_temperatures_after_collisions(d, grains, {1.0, start}, 400.0);
        EXPECT_NEAR(late.rotational / late.translational / ratio, 1.0, 1e-9)
            << "d = " << d << ", start " << start;
      }
    }
  }
}

TEST(RoughCooling, ExactSolutionInCollisionsAgreesWithRungeKuttaOfThePerCollisionChanges) {
  // Each collision changes the pair's energies by the means of mean_energy_change_per_collision
  // and takes c = collisions/N up by 1/N: d(N d T_tr/2) = N dc ΔE_tr, so dT_tr/dc = 2ΔE_tr/d and
  // dT_rot/dc = 2ΔE_rot/d_rot. RK4 with 10⁴ steps (truncation error ~10⁻¹⁰ over c = 20) against
  // the matrix exponential.
  for (int d : {2, 3}) {
    const double d_rot = th::rotational_degrees_of_freedom(d);
    for (const th::RoughGrains grains :
         {th::RoughGrains{0.7, 0.2, 0.5}, th::RoughGrains{0.95, -0.9, 0.4},
          th::RoughGrains{1.0, 1.0, 0.4}, th::RoughGrains{0.5, -1.0, 0.5}}) {
      const th::RoughTemperatures start{1.7, 0.2};
      const double c_end = 20.0;
      const int steps = 10000;
      const double h = c_end / steps;
      auto slope = [&](th::RoughTemperatures t) {
        const th::RoughEnergyChange de = th::mean_energy_change_per_collision(d, grains, t);
        return th::RoughTemperatures{2.0 * de.translational / d, 2.0 * de.rotational / d_rot};
      };
      auto advance = [](th::RoughTemperatures t, th::RoughTemperatures k, double dc) {
        return th::RoughTemperatures{t.translational + dc * k.translational,
                                     t.rotational + dc * k.rotational};
      };
      th::RoughTemperatures t = start;
      for (int s = 1; s <= steps; ++s) {
        const auto k1 = slope(t), k2 = slope(advance(t, k1, h / 2)),
                   k3 = slope(advance(t, k2, h / 2)), k4 = slope(advance(t, k3, h));
        t.translational +=
            h / 6 *
            (k1.translational + 2 * k2.translational + 2 * k3.translational + k4.translational);
        t.rotational +=
            h / 6 * (k1.rotational + 2 * k2.rotational + 2 * k3.rotational + k4.rotational);
        if (s % 2500 == 0) {
          const th::RoughTemperatures exact =
              th::rough_temperatures_after_collisions(d, grains, start, s * h);
          EXPECT_NEAR(exact.translational / t.translational, 1.0, 1e-9) << "d = " << d;
          EXPECT_NEAR(exact.rotational / t.rotational, 1.0, 1e-9) << "d = " << d;
        }
      }
    }
  }
}

TEST(RoughCooling, SolutionInTimeFollowsTheSolutionInCollisions) {
  // t(c) = ∫ 2 dc'/ω(T_tr(c')) with ω = ω0 √(T_tr/T_tr(0)) (Simpson, 2·10⁴ intervals, on the exact
  // T(c)); T at that time from the Runge–Kutta integration in t must be T(c).
  const double omega0 = 50.0;
  for (int d : {2, 3}) {
    for (const th::RoughGrains grains :
         {th::RoughGrains{0.7, 0.2, 0.5}, th::RoughGrains{0.9, -0.5, 0.4}}) {
      const th::RoughTemperatures start{1.0, 3.0};
      auto inverse_rate = [&](double c) {
        const double t_tr =
            th::rough_temperatures_after_collisions(d, grains, start, c).translational;
        return 2.0 / (omega0 * std::sqrt(t_tr / start.translational));
      };
      for (double c_end : {0.5, 5.0, 30.0}) {
        const int intervals = 20000;
        const double h = c_end / intervals;
        double sum = inverse_rate(0.0) + inverse_rate(c_end);
        for (int i = 1; i < intervals; ++i) sum += (i % 2 ? 4.0 : 2.0) * inverse_rate(i * h);
        const double t = sum * h / 3.0;
        const th::RoughTemperatures by_c =
            th::rough_temperatures_after_collisions(d, grains, start, c_end);
        const th::RoughTemperatures by_t =
            th::rough_temperatures_at_time(d, grains, start, omega0, t);
        std::printf("d = %d, c = %5.1f, t = %.6f: T_tr %.9e vs %.9e, T_rot %.9e vs %.9e\n", d,
                    c_end, t, by_t.translational, by_c.translational, by_t.rotational,
                    by_c.rotational);
        EXPECT_NEAR(by_t.translational / by_c.translational, 1.0, 1e-9);
        EXPECT_NEAR(by_t.rotational / by_c.rotational, 1.0, 1e-9);
      }
    }
  }
}

TEST(RoughCooling, CoolingStateFollowsHaffsLaw) {
  // Started at T_rot = R T_tr the gas stays in the cooling state, T_tr = T0/(1 + t/t0)².
  const double omega0 = 10.0, t0_tr = 2.0;
  for (int d : {2, 3}) {
    const th::RoughGrains grains{0.8, 0.5, d == 2 ? 0.5 : 0.4};
    const double ratio = th::rough_temperature_ratio(d, grains);
    const double t0 = th::rough_homogeneous_cooling_time(d, grains, omega0);
    for (double t : {0.1 * t0, t0, 30.0 * t0}) {
      const th::RoughTemperatures temp =
          th::rough_temperatures_at_time(d, grains, {t0_tr, ratio * t0_tr}, omega0, t);
      EXPECT_NEAR(temp.translational / th::haff_temperature(t, t0_tr, t0), 1.0, 1e-9);
      EXPECT_NEAR(temp.rotational / (ratio * temp.translational), 1.0, 1e-9);
    }
  }
}

TEST(RoughCooling, RefusesParametersOutsideTheirRanges) {
  EXPECT_THROW(th::rough_cooling_coefficients(3, {1.1, 0.0, 0.4}), std::invalid_argument);
  EXPECT_THROW(th::rough_cooling_coefficients(3, {0.9, 1.5, 0.4}), std::invalid_argument);
  EXPECT_THROW(th::rough_cooling_coefficients(3, {0.9, 0.0, 0.0}), std::invalid_argument);
  EXPECT_THROW(th::rough_cooling_coefficients(4, {0.9, 0.0, 0.4}), std::invalid_argument);
  EXPECT_THROW(th::rotational_degrees_of_freedom(1), std::invalid_argument);
}

}  // namespace
