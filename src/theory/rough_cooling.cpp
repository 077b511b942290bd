#include "theory/rough_cooling.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "theory/hard_spheres.hpp"

namespace granule::theory {

namespace {

// The linear cooling equations in the variable c (collisions per particle),
// dT/dc = (2/ω) dT/dt = 2 (G√T/ω) M T with M = [[−A, B], [κB, −κC]], κ = d/d_rot.
struct CoolingMatrix {
  double m11, m12, m21, m22;
};

CoolingMatrix cooling_matrix_per_collision(int dimension, const RoughGrains& grains) {
  const RoughCoolingCoefficients k = rough_cooling_coefficients(dimension, grains);
  const double s = 2.0 * k.rate_per_collision_frequency;
  return {-s * k.translational_loss, s * k.exchange, s * k.rotational_factor * k.exchange,
          -s * k.rotational_factor * k.rotational_loss};
}

RoughTemperatures apply(const CoolingMatrix& m, RoughTemperatures t) {
  return {m.m11 * t.translational + m.m12 * t.rotational,
          m.m21 * t.translational + m.m22 * t.rotational};
}

}  // namespace

void require_valid_rough_grains(const RoughGrains& grains) {
  if (!(grains.normal_restitution >= 0.0 && grains.normal_restitution <= 1.0))
    throw std::invalid_argument("normal restitution must lie in [0, 1]");
  if (!(grains.tangential_restitution >= -1.0 && grains.tangential_restitution <= 1.0))
    throw std::invalid_argument("tangential restitution must lie in [-1, 1]");
  if (!(grains.inertia_factor > 0.0 && std::isfinite(grains.inertia_factor)))
    throw std::invalid_argument("inertia factor q must be positive");
}

int rotational_degrees_of_freedom(int dimension) {
  require_disks_or_spheres(dimension);
  return dimension == 2 ? 1 : 3;
}

double tangential_effective_mass(double mass_1, double inertia_factor_1, double mass_2,
                                 double inertia_factor_2) {
  return 1.0 / (1.0 / mass_1 + 1.0 / mass_2 + 1.0 / (inertia_factor_1 * mass_1) +
                1.0 / (inertia_factor_2 * mass_2));
}

double rough_collision_energy_change(const RoughGrains& grains, double mass_1, double mass_2,
                                     double normal_velocity, double tangential_speed) {
  // The energy an impulse J changes is J·ḡ, ḡ the mean of the contact velocities before and
  // after: J_n = −μ(1 + e) g_n against (1 − e) g_n/2, J_t = −μ_t(1 + β) g_t against (1 − β) g_t/2.
  require_valid_rough_grains(grains);
  const double e = grains.normal_restitution;
  const double beta = grains.tangential_restitution;
  const double q = grains.inertia_factor;
  const double reduced_mass = mass_1 * mass_2 / (mass_1 + mass_2);
  const double tangential_mass = tangential_effective_mass(mass_1, q, mass_2, q);
  return -0.5 * reduced_mass * (1.0 - e * e) * normal_velocity * normal_velocity -
         0.5 * tangential_mass * (1.0 - beta * beta) * tangential_speed * tangential_speed;
}

double tangential_coupling(const RoughGrains& grains) {
  require_valid_rough_grains(grains);
  const double q = grains.inertia_factor;
  return q * (1.0 + grains.tangential_restitution) / (2.0 * (1.0 + q));
}

RoughEnergyChange mean_energy_change_per_collision(int dimension, const RoughGrains& grains,
                                                   RoughTemperatures temperatures) {
  // Flux-weighted ⟨g_n²⟩ = 4T_tr/m; the d − 1 tangential components of the contact velocity
  // each carry 2T_tr/m from the centres and 2T_rot/(qm) from the spins (docs/theory.md).
  require_disks_or_spheres(dimension);
  const double eta = tangential_coupling(grains);
  const double q = grains.inertia_factor;
  const double e = grains.normal_restitution;
  const double tangential = 2.0 * (dimension - 1);
  const double t_tr = temperatures.translational;
  const double t_rot = temperatures.rotational;
  return {-(1.0 - e * e) * t_tr - tangential * eta * (1.0 - eta) * t_tr +
              tangential * (eta * eta / q) * t_rot,
          tangential * (eta / q) * (eta * t_tr - (1.0 - eta / q) * t_rot)};
}

RoughCoolingCoefficients rough_cooling_coefficients(int dimension, const RoughGrains& grains) {
  require_disks_or_spheres(dimension);
  const double eta = tangential_coupling(grains);
  const double q = grains.inertia_factor;
  const double e = grains.normal_restitution;
  const double d = dimension;
  return {(1.0 - e * e) / (2.0 * (d - 1.0)) + eta * (1.0 - eta), eta * eta / q,
          (eta / q) * (1.0 - eta / q), d / rotational_degrees_of_freedom(dimension),
          2.0 * (d - 1.0) / d};
}

RoughTemperatures rough_cooling_rates(int dimension, const RoughGrains& grains,
                                      RoughTemperatures temperatures, double collision_frequency) {
  // dT/dt = (ω/2) dT/dc.
  const RoughTemperatures per_collision =
      apply(cooling_matrix_per_collision(dimension, grains), temperatures);
  return {0.5 * collision_frequency * per_collision.translational,
          0.5 * collision_frequency * per_collision.rotational};
}

double rough_temperature_ratio(int dimension, const RoughGrains& grains) {
  const RoughCoolingCoefficients k = rough_cooling_coefficients(dimension, grains);
  const double kappa = k.rotational_factor;
  const double a_minus_kc = k.translational_loss - kappa * k.rotational_loss;
  if (k.exchange == 0.0) {
    if (a_minus_kc > 0.0) return std::numeric_limits<double>::infinity();
    return std::numeric_limits<double>::quiet_NaN();
  }
  const double h = a_minus_kc / (2.0 * k.exchange);
  const double root = std::sqrt(h * h + kappa);
  // The two forms of the positive root; the second avoids cancellation when h ≪ 0.
  return h >= 0.0 ? h + root : kappa / (root - h);
}

RoughTemperatures rough_temperatures_after_collisions(int dimension, const RoughGrains& grains,
                                                      RoughTemperatures initial,
                                                      double collisions_per_particle) {
  // exp(Mc) of a 2×2 matrix with real eigenvalues λ± = s ± r (r² = ((m11 − m22)/2)² + m12 m21
  // ≥ 0): exp(Mc) = e^{λ+ c} [(1 + e^{−2rc})/2 · 1 + (1 − e^{−2rc})/(2r) · (M − s·1)], written
  // with expm1 so that it stays exact as r → 0 and never overflows.
  const CoolingMatrix m = cooling_matrix_per_collision(dimension, grains);
  const double c = collisions_per_particle;
  const double s = 0.5 * (m.m11 + m.m22);
  const double half_gap = 0.5 * (m.m11 - m.m22);
  const double r = std::sqrt(half_gap * half_gap + m.m12 * m.m21);
  const double decay = std::exp((s + r) * c);
  const double even = decay * (1.0 + 0.5 * std::expm1(-2.0 * r * c));
  const double odd = r > 0.0 ? decay * -std::expm1(-2.0 * r * c) / (2.0 * r) : decay * c;
  const CoolingMatrix shifted{m.m11 - s, m.m12, m.m21, m.m22 - s};
  const RoughTemperatures mixed = apply(shifted, initial);
  return {even * initial.translational + odd * mixed.translational,
          even * initial.rotational + odd * mixed.rotational};
}

RoughTemperatures rough_temperatures_at_time(int dimension, const RoughGrains& grains,
                                             RoughTemperatures initial,
                                             double collision_frequency_at_start, double t) {
  // ω ∝ √T_tr. Steps of 1 % of the current collision time: the rates are at most ~ω, so RK4's
  // error per step is ~10⁻¹², and the steps grow with t as the gas cools (~100 ln(t/t_coll)).
  // A gas without translational motion never collides: nothing changes.
  if (!(initial.translational > 0.0)) return initial;
  const auto frequency = [&](RoughTemperatures temp) {
    return collision_frequency_at_start *
           std::sqrt(std::max(temp.translational, 0.0) / initial.translational);
  };
  const auto rates = [&](RoughTemperatures temp) {
    return rough_cooling_rates(dimension, grains, temp, frequency(temp));
  };
  const auto advance = [](RoughTemperatures base, RoughTemperatures slope, double h) {
    return RoughTemperatures{base.translational + h * slope.translational,
                             base.rotational + h * slope.rotational};
  };
  RoughTemperatures temp = initial;
  double now = 0.0;
  while (now < t) {
    const double omega = frequency(temp);
    const double h = omega > 0.0 ? std::min(t - now, 0.01 / omega) : t - now;
    const RoughTemperatures k1 = rates(temp);
    const RoughTemperatures k2 = rates(advance(temp, k1, h / 2.0));
    const RoughTemperatures k3 = rates(advance(temp, k2, h / 2.0));
    const RoughTemperatures k4 = rates(advance(temp, k3, h));
    const RoughTemperatures slope{
        (k1.translational + 2.0 * k2.translational + 2.0 * k3.translational + k4.translational) /
            6.0,
        (k1.rotational + 2.0 * k2.rotational + 2.0 * k3.rotational + k4.rotational) / 6.0};
    temp = advance(temp, slope, h);
    now = h == t - now ? t : now + h;
  }
  return temp;
}

double rough_homogeneous_cooling_time(int dimension, const RoughGrains& grains,
                                      double collision_frequency_at_start) {
  const RoughCoolingCoefficients k = rough_cooling_coefficients(dimension, grains);
  // Smooth grains: B = 0 and R = ∞; the translation cools at A alone.
  const double net_loss =
      k.exchange == 0.0
          ? k.translational_loss
          : k.translational_loss - k.exchange * rough_temperature_ratio(dimension, grains);
  return 2.0 / (k.rate_per_collision_frequency * collision_frequency_at_start * net_loss);
}

}  // namespace granule::theory
