#include "theory/hydrostatics.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "theory/hard_spheres.hpp"

namespace granule::theory {

namespace {

// The root of an increasing function on [lo, hi] by bisection to the last bit: slow but sure,
// and these are cheap functions.
template <class F>
double increasing_root(F&& f, double lo, double hi) {
  for (;;) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) return mid;
    (f(mid) < 0.0 ? lo : hi) = mid;
  }
}

// μ/T up to a constant as a function of x = ln φ: x + μ_ex(e^x)/T, increasing with slope
// d(φZ)/dφ ≥ 1.
double reduced_chemical_potential(int dimension, double log_packing_fraction) {
  return log_packing_fraction +
         hard_sphere_excess_chemical_potential(dimension, std::exp(log_packing_fraction));
}

}  // namespace

double hard_sphere_inverse_compressibility(int dimension, double packing_fraction) {
  require_disks_or_spheres(dimension);
  const double phi = packing_fraction;
  const double free = 1.0 - phi;
  if (dimension == 2)
    return (8.0 + 8.0 * phi + 3.0 * phi * phi - phi * phi * phi) / (8.0 * free * free * free);
  return (1.0 + 4.0 * phi + 4.0 * phi * phi - 4.0 * phi * phi * phi + phi * phi * phi * phi) /
         (free * free * free * free);
}

double hard_sphere_excess_chemical_potential(int dimension, double packing_fraction) {
  require_disks_or_spheres(dimension);
  const double phi = packing_fraction;
  const double free = 1.0 - phi;
  if (dimension == 2)
    return phi * (25.0 - 16.0 * phi) / (8.0 * free * free) - 7.0 / 8.0 * std::log1p(-phi);
  return phi * (8.0 - 9.0 * phi + 3.0 * phi * phi) / (free * free * free);
}

double barometric_height(const HydrostaticColumn& column) {
  return column.temperature / (column.mass * column.gravity);
}

double hydrostatic_bottom_packing_fraction(const HydrostaticColumn& column) {
  require_disks_or_spheres(column.dimension);
  if (!(column.diameter > 0.0 && column.mass > 0.0 && column.gravity > 0.0 &&
        column.temperature > 0.0 && column.particles_per_floor_area > 0.0))
    throw std::invalid_argument(
        "a hydrostatic column needs positive diameter, mass, gravity, temperature and amount");
  // φ Z(φ) = v_d P/T grows from 0 to ∞ on [0, 1).
  const double target = particle_volume(column.dimension, column.diameter) *
                        column.particles_per_floor_area / barometric_height(column);
  return increasing_root(
      [&](double phi) { return phi * hard_sphere_compressibility(column.dimension, phi) - target; },
      0.0, 1.0);
}

std::vector<double> hydrostatic_packing_fraction(const HydrostaticColumn& column,
                                                 std::span<const double> heights) {
  const double bottom = hydrostatic_bottom_packing_fraction(column);
  const double log_bottom = std::log(bottom);
  const double mu_bottom = reduced_chemical_potential(column.dimension, log_bottom);
  const double h = barometric_height(column);
  std::vector<double> profile;
  profile.reserve(heights.size());
  for (double y : heights) {
    // μ/T must fall by y/h. Its slope in ln φ is at least 1, so ln φ lies within y/h below
    // ln φ0, and not above the ideal gas's μ/T (μ_ex ≥ 0).
    const double drop = y / h;
    const double target = mu_bottom - drop;
    const double x = increasing_root(
        [&](double log_phi) {
          return reduced_chemical_potential(column.dimension, log_phi) - target;
        },
        log_bottom - drop, std::min(log_bottom, target));
    profile.push_back(std::exp(x));
  }
  return profile;
}

double wall_contact_density(int dimension, double number_density, double packing_fraction) {
  return number_density * hard_sphere_compressibility(dimension, packing_fraction);
}

double floor_contact_density(const HydrostaticColumn& column) {
  return column.particles_per_floor_area / barometric_height(column);
}

}  // namespace granule::theory
