// Hydrostatics of hard disks and spheres (hydrostatics.hpp) against the equation of state of
// hard_spheres.hpp differentiated and integrated numerically, the exact barometric law of the
// dilute limit, and the exact statements of mechanical equilibrium: the amount of gas is the one
// given, the pressure at each height carries the weight above it, P(y) = m g ∫_y^∞ n dy', and the
// profile solves dφ/dy = −(m g/T) φ/(d(φZ)/dφ) (Runge–Kutta from the bottom).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <vector>

#include "theory/hard_spheres.hpp"
#include "theory/hydrostatics.hpp"

namespace {

namespace th = granule::theory;

// d(φZ)/dφ by the five-point central difference of the library's Z (error ~10⁻¹¹).
double numerical_inverse_compressibility(int d, double phi) {
  const double step = 1e-4;
  auto pz = [d](double p) { return p * th::hard_sphere_compressibility(d, p); };
  return (8.0 * (pz(phi + step) - pz(phi - step)) - (pz(phi + 2 * step) - pz(phi - 2 * step))) /
         (12.0 * step);
}

// A column whose bottom packing fraction is φ0: N_A = φ0 Z(φ0) h/v_d.
th::HydrostaticColumn column_with_bottom(int d, double phi0) {
  th::HydrostaticColumn column{d, 0.01, 2.0, 9.81, 0.5, 0.0};
  column.particles_per_floor_area = phi0 * th::hard_sphere_compressibility(d, phi0) *
                                    th::barometric_height(column) /
                                    th::particle_volume(d, column.diameter);
  return column;
}

TEST(Hydrostatics, InverseCompressibilityAndChemicalPotentialFollowFromTheEquationOfState) {
  // μ_ex/T = ∫_0^φ (Z − 1)/φ' dφ' + Z − 1 (Gibbs–Duhem at fixed T), Simpson with 2000 intervals.
  for (int d : {2, 3}) {
    for (double phi : {0.001, 0.05, 0.2, 0.4, d == 2 ? 0.65 : 0.48}) {
      EXPECT_NEAR(th::hard_sphere_inverse_compressibility(d, phi) /
                      numerical_inverse_compressibility(d, phi),
                  1.0, 1e-9)
          << "d = " << d << ", phi = " << phi;
      auto integrand = [d](double p) {
        return p == 0.0 ? (d == 2 ? 2.0 : 4.0)  // (Z − 1)/φ → 2^{d−1} at φ = 0
                        : (th::hard_sphere_compressibility(d, p) - 1.0) / p;
      };
      const int intervals = 2000;
      const double h = phi / intervals;
      double sum = integrand(0.0) + integrand(phi);
      for (int i = 1; i < intervals; ++i) sum += (i % 2 ? 4.0 : 2.0) * integrand(i * h);
      const double mu_ex = sum * h / 3.0 + th::hard_sphere_compressibility(d, phi) - 1.0;
      EXPECT_NEAR(th::hard_sphere_excess_chemical_potential(d, phi), mu_ex, 1e-11 * (1.0 + mu_ex))
          << "d = " << d << ", phi = " << phi;
    }
  }
}

TEST(Hydrostatics, DiluteColumnIsBarometric) {
  // φ0 = 10⁻⁷: n(y) = (N_A/h) exp(−y/h) up to corrections of order φ0 (~4·10⁻⁷).
  for (int d : {2, 3}) {
    const th::HydrostaticColumn column = column_with_bottom(d, 1e-7);
    const double h = th::barometric_height(column);
    std::vector<double> heights;
    for (int i = 0; i <= 40; ++i) heights.push_back(0.5 * i * h);
    const std::vector<double> phi = th::hydrostatic_packing_fraction(column, heights);
    double worst = 0.0;
    for (std::size_t i = 0; i < heights.size(); ++i) {
      const double n = th::number_density(d, phi[i], column.diameter);
      const double barometric = column.particles_per_floor_area / h * std::exp(-heights[i] / h);
      worst = std::max(worst, std::abs(n / barometric - 1.0));
    }
    std::printf("d = %d: dilute column, largest |n/n_barometric - 1| = %.2e\n", d, worst);
    EXPECT_LT(worst, 1e-6);
  }
}

TEST(Hydrostatics, DenseColumnHoldsItsAmountAndCarriesItsWeight) {
  // Bottom packing fractions near freezing: 0.45 for spheres, 0.65 for disks. Grid to 60 h
  // (φ < 10⁻²⁴ there), Simpson with 12000 intervals.
  for (int d : {2, 3}) {
    const double phi0 = d == 2 ? 0.65 : 0.45;
    const th::HydrostaticColumn column = column_with_bottom(d, phi0);
    EXPECT_NEAR(th::hydrostatic_bottom_packing_fraction(column), phi0, 1e-15);
    const double h = th::barometric_height(column);
    const int intervals = 12000;
    const double dy = 60.0 * h / intervals;
    std::vector<double> heights;
    for (int i = 0; i <= intervals; ++i) heights.push_back(i * dy);
    const std::vector<double> phi = th::hydrostatic_packing_fraction(column, heights);
    std::vector<double> n;
    for (double p : phi) n.push_back(th::number_density(d, p, column.diameter));

    // Weight above each even grid point, Simpson from the top down.
    std::vector<double> above(heights.size(), 0.0);
    for (int i = intervals - 2; i >= 0; i -= 2)
      above[i] = above[i + 2] + dy / 3.0 * (n[i] + 4.0 * n[i + 1] + n[i + 2]);
    const double amount = above[0];
    std::printf("d = %d: phi0 = %.2f, amount %.12e vs N_A %.12e\n", d, phi0, amount,
                column.particles_per_floor_area);
    EXPECT_NEAR(amount / column.particles_per_floor_area, 1.0, 1e-10);
    const double weight = column.mass * column.gravity;
    const double bottom_pressure = weight * column.particles_per_floor_area;
    double worst = 0.0;
    for (int i = 0; i <= intervals; i += 2) {
      const double pressure = th::hard_sphere_pressure(d, n[i], column.temperature, phi[i]);
      worst = std::max(worst, std::abs(pressure - weight * above[i]) / bottom_pressure);
    }
    std::printf("d = %d: largest |P(y) - m g int_y n| / P(0) = %.2e\n", d, worst);
    EXPECT_LT(worst, 1e-10);

    // The contact theorem at the floor: the local-density bottom state, n(0) Z(φ0), has the
    // contact density the weight demands.
    std::printf("d = %d: floor contact density m g N_A/T = %.6e = %.4f n(0) (Z(phi0))\n", d,
                th::floor_contact_density(column), th::floor_contact_density(column) / n[0]);
    EXPECT_NEAR(th::wall_contact_density(d, n[0], phi[0]) / th::floor_contact_density(column), 1.0,
                1e-14);
  }
}

TEST(Hydrostatics, ProfileSolvesTheHydrostaticEquation) {
  // RK4 of dφ/dy = −φ/(h d(φZ)/dφ), the derivative by central differences of Z, from φ0.
  for (int d : {2, 3}) {
    const double phi0 = d == 2 ? 0.6 : 0.4;
    const th::HydrostaticColumn column = column_with_bottom(d, phi0);
    const double h = th::barometric_height(column);
    auto slope = [&](double p) { return -p / (h * numerical_inverse_compressibility(d, p)); };
    const int steps = 4000;
    const double dy = 10.0 * h / steps;
    std::vector<double> heights;
    std::vector<double> integrated;
    double p = phi0;
    for (int s = 1; s <= steps; ++s) {
      const double k1 = slope(p), k2 = slope(p + dy / 2 * k1), k3 = slope(p + dy / 2 * k2),
                   k4 = slope(p + dy * k3);
      p += dy / 6.0 * (k1 + 2 * k2 + 2 * k3 + k4);
      if (s % 400 == 0) {
        heights.push_back(s * dy);
        integrated.push_back(p);
      }
    }
    const std::vector<double> profile = th::hydrostatic_packing_fraction(column, heights);
    for (std::size_t i = 0; i < heights.size(); ++i)
      EXPECT_NEAR(profile[i] / integrated[i], 1.0, 1e-8)
          << "d = " << d << ", y/h = " << heights[i] / h;
  }
}

TEST(Hydrostatics, RefusesAColumnThatIsNotAGas) {
  th::HydrostaticColumn column{3, 0.01, 1.0, 9.81, 1.0, 10.0};
  EXPECT_NO_THROW(th::hydrostatic_bottom_packing_fraction(column));
  for (auto spoil : {+[](th::HydrostaticColumn& c) { c.gravity = 0.0; },
                     +[](th::HydrostaticColumn& c) { c.temperature = -1.0; },
                     +[](th::HydrostaticColumn& c) { c.particles_per_floor_area = 0.0; },
                     +[](th::HydrostaticColumn& c) { c.dimension = 1; }}) {
    th::HydrostaticColumn bad = column;
    spoil(bad);
    EXPECT_THROW(th::hydrostatic_bottom_packing_fraction(bad), std::invalid_argument);
  }
}

}  // namespace
