#include "theory/steady_shear.hpp"

#include <cmath>
#include <numbers>

#include "theory/kinetic_scales.hpp"

namespace granule::theory {

using std::numbers::pi;

namespace {

double shear_temperature_scale(double shear_rate, double diameter, double area_fraction) {
  const double x = shear_rate * diameter / area_fraction;
  return x * x;  // γ²σ²/ν̄²
}

}  // namespace

double steady_shear_temperature_tan_fit(double restitution, double shear_rate, double diameter,
                                        double area_fraction) {
  return tan_fit_A * shear_temperature_scale(shear_rate, diameter, area_fraction) *
         (1.0 / inelasticity(restitution) + tan_fit_B);
}

double steady_shear_temperature_jenkins_richman(double restitution, double shear_rate,
                                                double diameter, double area_fraction) {
  const double e = restitution;
  const double a = (1.0 + e) * (7.0 - 3.0 * e);
  return pi / (a * a) * shear_temperature_scale(shear_rate, diameter, area_fraction) *
         (1.0 / (1.0 - e) - 7.0 / 16.0);
}

double heated_steady_temperature(double heating_function, double mean_free_path, double eps) {
  return mean_free_path * mean_free_path * heating_function / (2.0 * pi * eps);
}

double steady_shear_temperature_kinetic(double restitution, double shear_rate, double diameter,
                                        double area_fraction) {
  // Tr D̂² = 2γ² for v = (γy, 0) by (4.4).
  return heated_steady_temperature(2.0 * shear_rate * shear_rate,
                                   mean_free_path(diameter, area_fraction),
                                   inelasticity(restitution));
}

double diameter_for_area_fraction(double area_fraction, int particle_count, double box_x,
                                  double box_y) {
  return std::sqrt(4.0 * area_fraction * box_x * box_y / (pi * particle_count));
}

}  // namespace granule::theory
