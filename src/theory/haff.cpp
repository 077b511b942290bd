#include "theory/haff.hpp"

#include <cmath>
#include <numbers>

#include "theory/kinetic_scales.hpp"

namespace granule::theory {

using std::numbers::pi;

double haff_temperature(double t, double T0, double t0) {
  const double stretch = 1.0 + t / t0;
  return T0 / (stretch * stretch);
}

double haff_temperature_after_collisions(double c, double T0, double restitution) {
  return T0 * std::exp(-inelasticity(restitution) * c);
}

double haff_collisions_per_particle(double t, double t0, double restitution) {
  // log1p keeps c accurate for t << t0.
  return 2.0 / inelasticity(restitution) * std::log1p(t / t0);
}

double haff_time_disks(double T0, double restitution, double diameter, double area_fraction,
                       double contact_value) {
  const double omega0 = disk_collision_frequency(T0, diameter, area_fraction, contact_value);
  return 4.0 / (inelasticity(restitution) * omega0);
}

double jenkins_richman_dissipation_coefficient(double restitution, double volume_fraction) {
  return 24.0 / std::sqrt(pi) * inelasticity(restitution) * volume_fraction * volume_fraction;
}

double jenkins_richman_haff_time(double T0, double restitution, double diameter,
                                 double volume_fraction) {
  // (2.11) with ρ0 = ρs ν: t0 = 3νσ/(d √T0).
  const double d = jenkins_richman_dissipation_coefficient(restitution, volume_fraction);
  return 3.0 * volume_fraction * diameter / (d * std::sqrt(T0));
}

double effective_mean_free_path(double diameter, double volume_fraction) {
  return std::sqrt(pi) / 8.0 * diameter / volume_fraction;
}

double sphere_mean_free_path(double diameter, double volume_fraction) {
  // n = 6ν/(πσ³), so 1/(πσ² n) = σ/(6ν).
  return diameter / (6.0 * volume_fraction);
}

double haff_stretched_time(double t, double t0, double eps) { return std::log1p(t / t0) / eps; }

}  // namespace granule::theory
