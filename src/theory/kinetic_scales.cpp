#include "theory/kinetic_scales.hpp"

#include <cmath>
#include <numbers>

namespace granule::theory {

using std::numbers::pi;

double inelasticity(double restitution) { return 1.0 - restitution * restitution; }

double mean_free_path(double diameter, double area_fraction) {
  return pi * diameter / (8.0 * area_fraction);
}

double boltzmann_mean_free_path(double diameter, double area_fraction) {
  return mean_free_path(diameter, area_fraction) / std::numbers::sqrt2;
}

double disk_collision_frequency(double temperature, double diameter, double area_fraction,
                                double contact_value) {
  // n = 4ν/(πσ²); the relative speed of two Maxwellian disks averages √(πT).
  return 8.0 * area_fraction * contact_value * std::sqrt(temperature) / (std::sqrt(pi) * diameter);
}

double henderson_contact_value(double area_fraction) {
  const double one_minus = 1.0 - area_fraction;
  return (1.0 - 7.0 * area_fraction / 16.0) / (one_minus * one_minus);
}

double cluster_separation(double restitution, double diameter, double area_fraction) {
  return mean_free_path(diameter, area_fraction) / std::sqrt(inelasticity(restitution));
}

}  // namespace granule::theory
