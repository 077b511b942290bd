#include "theory/enskog_mixture.hpp"

#include <cmath>

#include "theory/hard_spheres.hpp"
#include "theory/kinetic_scales.hpp"

namespace granule::theory {

namespace {

double contact_distance(const MixtureSpecies& a, const MixtureSpecies& b) {
  return 0.5 * (a.diameter + b.diameter);
}

// Σ_k n_k σ_k^power [length^{power − d}].
double diameter_moment(std::span<const MixtureSpecies> species, int power) {
  double sum = 0.0;
  for (const auto& s : species) sum += s.number_density * std::pow(s.diameter, power);
  return sum;
}

}  // namespace

double mixture_packing_fraction(int dimension, std::span<const MixtureSpecies> species) {
  double phi = 0.0;
  for (const auto& s : species) phi += s.number_density * particle_volume(dimension, s.diameter);
  return phi;
}

double contact_size_parameter(int dimension, std::span<const MixtureSpecies> species,
                              std::size_t i, std::size_t j) {
  require_disks_or_spheres(dimension);
  const auto& a = species[i];
  const auto& b = species[j];
  // The total number density cancels between the two moments.
  return a.diameter * b.diameter / contact_distance(a, b) *
         diameter_moment(species, dimension - 1) / diameter_moment(species, dimension);
}

double mixture_contact_value(int dimension, std::span<const MixtureSpecies> species,
                             std::size_t i, std::size_t j) {
  const double phi = mixture_packing_fraction(dimension, species);
  const double z = contact_size_parameter(dimension, species, i, j);
  const double one_minus = 1.0 - phi;
  if (dimension == 2) return 1.0 / one_minus + (henderson_contact_value(phi) - 1.0 / one_minus) * z;
  return 1.0 / one_minus + 1.5 * phi * z / (one_minus * one_minus) +
         0.5 * phi * phi * z * z / (one_minus * one_minus * one_minus);
}

double mixture_pressure(int dimension, std::span<const MixtureSpecies> species,
                        double temperature) {
  double density = 0.0, contact_sum = 0.0;
  for (std::size_t i = 0; i < species.size(); ++i) {
    density += species[i].number_density;
    for (std::size_t j = 0; j < species.size(); ++j) {
      const double half_excluded =
          0.5 * particle_volume(dimension, 2.0 * contact_distance(species[i], species[j]));
      contact_sum += species[i].number_density * species[j].number_density * half_excluded *
                     mixture_contact_value(dimension, species, i, j);
    }
  }
  return temperature * (density + contact_sum);
}

double species_pair_collision_frequency(int dimension, std::span<const MixtureSpecies> species,
                                        std::size_t i, std::size_t j, double temperature) {
  const auto& a = species[i];
  const auto& b = species[j];
  const double reduced_mass = a.mass * b.mass / (a.mass + b.mass);
  return enskog_collision_frequency(dimension, b.number_density, contact_distance(a, b),
                                    mixture_contact_value(dimension, species, i, j), temperature,
                                    reduced_mass);
}

double species_collision_frequency(int dimension, std::span<const MixtureSpecies> species,
                                   std::size_t i, double temperature) {
  double omega = 0.0;
  for (std::size_t j = 0; j < species.size(); ++j)
    omega += species_pair_collision_frequency(dimension, species, i, j, temperature);
  return omega;
}

double pair_collision_rate_density(int dimension, std::span<const MixtureSpecies> species,
                                   std::size_t i, std::size_t j, double temperature) {
  const double rate = species[i].number_density *
                      species_pair_collision_frequency(dimension, species, i, j, temperature);
  return i == j ? 0.5 * rate : rate;
}

}  // namespace granule::theory
