// Equilibrium and Enskog kinetic scales of monodisperse hard disks (d = 2) and spheres (d = 3):
// equation of state, contact value, collision frequency and mean free path. Units: k_B = 1,
// T is the temperature per degree of freedom, T = m⟨|v − V|²⟩/d [mass·length²/time²] (for unit
// mass in 2D this is the thesis's T = ½⟨(v − V)²⟩, (1.3)); lengths [length], masses [mass],
// number densities [1/length^d], φ the packing (area or volume) fraction. d must be 2 or 3:
// anything else throws std::invalid_argument.
#pragma once

namespace granule::theory {

// Throws std::invalid_argument unless the dimension is 2 (disks) or 3 (spheres).
void require_disks_or_spheres(int dimension);

// Area (d = 2) or volume (d = 3) of one particle of diameter σ: πσ²/4, πσ³/6 [length^d].
double particle_volume(int dimension, double diameter);

// n = φ / particle_volume [1/length^d].
double number_density(int dimension, double packing_fraction, double diameter);

// Mean speed ⟨|v|⟩ of a Maxwellian of temperature T and mass m [length/time]: √(πT/(2m)) in 2D,
// √(8T/(πm)) in 3D. With m replaced by the reduced mass μ it is the mean relative speed of two
// particles.
double maxwellian_mean_speed(int dimension, double temperature, double mass);

// The collision cross-section β σ^{d−1} = σ^{d−1} ∫ dk̂ (ĝ·k̂)₊ over unit vectors k̂: the rate at
// which a relative velocity g sweeps contact configurations per unit |g| and partner density;
// 2σ in 2D (a strip of width 2σ), πσ² in 3D (a disk of radius σ) [length^{d−1}].
double collision_cross_section(int dimension, double contact_distance);

// Enskog collision frequency of one particle with partners of density n_j at a common Maxwellian
// temperature T: ω = n_j χ · (β σ^{d−1}) · ⟨|g|⟩ with ⟨|g|⟩ the mean relative speed for the reduced
// mass μ = m_i m_j/(m_i + m_j) [1/time]; σ is the contact distance (σ_i + σ_j)/2 and χ the pair
// correlation at contact. Explicitly ω = n_j χ σ √(2πT/μ) (2D), n_j χ σ² √(8πT/μ) (3D)
// (the standard Enskog result, derived in docs/theory.md).
double enskog_collision_frequency(int dimension, double partner_density, double contact_distance,
                                  double contact_value, double temperature, double reduced_mass);

// Monodisperse ω = n χ σ^{d−1} β √2 ⟨|v|⟩ (μ = m/2): 2nσχ√(πT/m) in 2D, 4nσ²χ√(πT/m) in 3D
// [1/time]. Pass χ = 1 for the Boltzmann (dilute) value, hard_sphere_contact_value for Enskog.
double hard_sphere_collision_frequency(int dimension, double number_density, double diameter,
                                       double contact_value, double temperature, double mass);

// Mean free path ℓ = ⟨|v|⟩/ω = 1/(√2 n χ β σ^{d−1}): 1/(2√2 nσχ) in 2D, 1/(√2 π nσ²χ) in 3D
// [length], independent of T and m.
double hard_sphere_mean_free_path(int dimension, double number_density, double diameter,
                                  double contact_value);

// Carnahan–Starling (J. Chem. Phys. 51, 635 (1969)) for spheres: Z = (1 + φ + φ² − φ³)/(1 − φ)³.
double carnahan_starling_compressibility(double volume_fraction);

// The Carnahan–Starling contact value g(σ) = (1 − φ/2)/(1 − φ)³, from Z = 1 + 4φ g(σ).
double carnahan_starling_contact_value(double volume_fraction);

// Contact value of the monodisperse fluid: Henderson's (1 − 7φ/16)/(1 − φ)² for disks
// (henderson_contact_value), Carnahan–Starling for spheres.
double hard_sphere_contact_value(int dimension, double packing_fraction);

// Compressibility factor from the virial route, Z = P/(nT) = 1 + 2^{d−1} φ g(σ): the second
// virial coefficient is half the excluded volume, B2 n = 2^{d−1} φ (2φ for disks, 4φ for
// spheres).
double hard_sphere_compressibility(int dimension, double packing_fraction);

// P = n T Z(φ) [mass/(length^{d−2} time²)]: force per length in 2D, per area in 3D.
double hard_sphere_pressure(int dimension, double number_density, double temperature,
                            double packing_fraction);

}  // namespace granule::theory
