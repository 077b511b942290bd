#include "theory/homogeneous_cooling.hpp"

#include <cmath>

#include "theory/hard_spheres.hpp"
#include "theory/kinetic_scales.hpp"

namespace granule::theory {

namespace {

// d, the number of translational degrees of freedom of a disk or sphere.
double degrees_of_freedom(int dimension) {
  require_disks_or_spheres(dimension);
  return static_cast<double>(dimension);
}

}  // namespace

double sonine_a2(double restitution, int dimension) {
  const double e = restitution;
  const double d = degrees_of_freedom(dimension);
  return 16.0 * (1.0 - e) * (1.0 - 2.0 * e * e) /
         (9.0 + 24.0 * d - e * (41.0 - 8.0 * d) + 30.0 * (1.0 - e) * e * e);
}

double sonine_collision_frequency_factor(double a2) { return 1.0 - a2 / 16.0; }

double sonine_cooling_rate_factor(double a2) { return 1.0 + 3.0 * a2 / 16.0; }

double homogeneous_cooling_rate(int dimension, double restitution,
                                double maxwellian_collision_frequency, double a2) {
  return inelasticity(restitution) / degrees_of_freedom(dimension) *
         maxwellian_collision_frequency * sonine_cooling_rate_factor(a2);
}

double energy_loss_per_collision(int dimension, double restitution, double a2) {
  return inelasticity(restitution) / degrees_of_freedom(dimension) *
         sonine_cooling_rate_factor(a2) / sonine_collision_frequency_factor(a2);
}

double homogeneous_cooling_time(int dimension, double restitution,
                                double maxwellian_collision_frequency_at_T0, double a2) {
  // dT/dt = −ζ(T0)√(T/T0) T integrates to T0/(1 + ζ(T0)t/2)².
  return 2.0 /
         homogeneous_cooling_rate(dimension, restitution, maxwellian_collision_frequency_at_T0, a2);
}

double temperature_after_collisions(int dimension, double collisions_per_particle, double T0,
                                    double restitution, double a2) {
  return T0 * std::exp(-2.0 * energy_loss_per_collision(dimension, restitution, a2) *
                       collisions_per_particle);
}

double collisions_per_particle(int dimension, double t, double t0, double restitution, double a2) {
  // log1p keeps c accurate for t << t0.
  return std::log1p(t / t0) / energy_loss_per_collision(dimension, restitution, a2);
}

}  // namespace granule::theory
