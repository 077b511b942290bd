#include "theory/hard_spheres.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "theory/kinetic_scales.hpp"

namespace granule::theory {

using std::numbers::pi;

void require_disks_or_spheres(int dimension) {
  if (dimension != 2 && dimension != 3)
    throw std::invalid_argument("hard-sphere theory needs dimension 2 or 3, not " +
                                std::to_string(dimension));
}

double particle_volume(int dimension, double diameter) {
  require_disks_or_spheres(dimension);
  return dimension == 2 ? pi * diameter * diameter / 4.0
                        : pi * diameter * diameter * diameter / 6.0;
}

double number_density(int dimension, double packing_fraction, double diameter) {
  return packing_fraction / particle_volume(dimension, diameter);
}

double maxwellian_mean_speed(int dimension, double temperature, double mass) {
  // Each velocity component is Gaussian with variance T/m; the mean of the norm of such a vector
  // is √(T/m)·√(π/2) in 2D (Rayleigh) and √(T/m)·√(8/π) in 3D (Maxwell).
  require_disks_or_spheres(dimension);
  const double thermal_speed = std::sqrt(temperature / mass);
  return thermal_speed * (dimension == 2 ? std::sqrt(pi / 2.0) : std::sqrt(8.0 / pi));
}

double collision_cross_section(int dimension, double contact_distance) {
  // ∫ dk̂ (ĝ·k̂)₊ = ∫_{−π/2}^{π/2} cos θ dθ = 2 on the circle, 2π ∫_0^{π/2} cos θ sin θ dθ = π on
  // the sphere.
  require_disks_or_spheres(dimension);
  return dimension == 2 ? 2.0 * contact_distance : pi * contact_distance * contact_distance;
}

double enskog_collision_frequency(int dimension, double partner_density, double contact_distance,
                                  double contact_value, double temperature, double reduced_mass) {
  return partner_density * contact_value * collision_cross_section(dimension, contact_distance) *
         maxwellian_mean_speed(dimension, temperature, reduced_mass);
}

double hard_sphere_collision_frequency(int dimension, double number_density, double diameter,
                                       double contact_value, double temperature, double mass) {
  return enskog_collision_frequency(dimension, number_density, diameter, contact_value,
                                    temperature, mass / 2.0);
}

double hard_sphere_mean_free_path(int dimension, double number_density, double diameter,
                                  double contact_value) {
  // ⟨|v|⟩/ω with ⟨|g|⟩ = √2 ⟨|v|⟩ for equal masses: T and m cancel.
  return 1.0 / (std::numbers::sqrt2 * number_density * contact_value *
                collision_cross_section(dimension, diameter));
}

double carnahan_starling_compressibility(double volume_fraction) {
  const double phi = volume_fraction;
  const double one_minus = 1.0 - phi;
  return (1.0 + phi + phi * phi - phi * phi * phi) / (one_minus * one_minus * one_minus);
}

double carnahan_starling_contact_value(double volume_fraction) {
  const double one_minus = 1.0 - volume_fraction;
  return (1.0 - volume_fraction / 2.0) / (one_minus * one_minus * one_minus);
}

double hard_sphere_contact_value(int dimension, double packing_fraction) {
  require_disks_or_spheres(dimension);
  return dimension == 2 ? henderson_contact_value(packing_fraction)
                        : carnahan_starling_contact_value(packing_fraction);
}

double hard_sphere_compressibility(int dimension, double packing_fraction) {
  const double second_virial = dimension == 2 ? 2.0 : 4.0;  // B2 n / φ = 2^{d−1}
  return 1.0 + second_virial * packing_fraction *
                   hard_sphere_contact_value(dimension, packing_fraction);
}

double hard_sphere_pressure(int dimension, double number_density, double temperature,
                            double packing_fraction) {
  return number_density * temperature * hard_sphere_compressibility(dimension, packing_fraction);
}

}  // namespace granule::theory
