#include "theory/shear_time_scales.hpp"

#include <cmath>
#include <numbers>

namespace granule::theory {

double shear_delta_star(double mean_free_path, double box_length, double eps) {
  return mean_free_path / (box_length * std::sqrt(eps));
}

double shear_delta_bar_of_mode(int n, double mean_free_path, double box_length, double eps) {
  return 2.0 * std::numbers::pi * n * shear_delta_star(mean_free_path, box_length, eps);
}

double convective_time(double shear_rate) { return 1.0 / shear_rate; }

double linear_growth_time(double k, double mean_free_path, double eps, double shear_rate) {
  return std::sqrt(eps) / (k * mean_free_path * shear_rate);
}

double shear_fluctuation_rate(double k, double initial_temperature, int particle_count) {
  return k * std::sqrt(initial_temperature / particle_count);
}

double mass_motion_time_hot(double k, double mean_free_path, double eps, double h) {
  return std::sqrt(eps) / (k * mean_free_path * h);
}

double mass_motion_time_cold(double k, double mean_free_path, double eps, double h,
                             double shear_rate) {
  return std::sqrt(shear_rate / h) * std::sqrt(eps) / (k * mean_free_path * shear_rate);
}

KlWindow clustering_window_hot(double eps, double shear_rate, double h) {
  const double root = std::sqrt(eps);
  return {root * shear_rate / h, root};
}

KlWindow clustering_window_cold(double eps, double shear_rate, double h) {
  const double root = std::sqrt(eps);
  return {std::sqrt(shear_rate / h) * root, root};
}

ClusteringScales clustering_scales(double k, double mean_free_path, double eps, double shear_rate,
                                   double h) {
  const bool hot = h > shear_rate;
  return {hot, convective_time(shear_rate),
          hot ? mass_motion_time_hot(k, mean_free_path, eps, h)
              : mass_motion_time_cold(k, mean_free_path, eps, h, shear_rate),
          linear_growth_time(k, mean_free_path, eps, shear_rate),
          hot ? clustering_window_hot(eps, shear_rate, h)
              : clustering_window_cold(eps, shear_rate, h)};
}

}  // namespace granule::theory
