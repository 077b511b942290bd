// Equilibrium contact values, pressure and Enskog collision frequencies of a multicomponent
// mixture of additive hard disks (d = 2) or spheres (d = 3) at a common temperature T (per degree
// of freedom, k_B = 1, hard_spheres.hpp). Species are indexed 0..s−1; σ_ij = (σ_i + σ_j)/2.
// Derivations in docs/theory.md. d must be 2 or 3: anything else throws std::invalid_argument.
#pragma once

#include <cstddef>
#include <span>

namespace granule::theory {

struct MixtureSpecies {
  double diameter = 1.0;        // σ_i [length]
  double mass = 1.0;            // m_i [mass]
  double number_density = 0.0;  // n_i [1/length^d]
};

// φ = Σ_i n_i v_d(σ_i), the total area or volume fraction.
double mixture_packing_fraction(int dimension, std::span<const MixtureSpecies> species);

// z_ij = (σ_i σ_j/σ_ij) ⟨σ^{d−1}⟩/⟨σ^d⟩ (moments over number fractions): the one size parameter
// on which the contact values below depend (Santos, Yuste and López de Haro, J. Chem. Phys. 117,
// 5785 (2002)); 1 for equal sizes, 0 for a point particle, 2 for a wall.
double contact_size_parameter(int dimension, std::span<const MixtureSpecies> species,
                              std::size_t i, std::size_t j);

// Contact value g_ij(σ_ij) of the pair correlation.
// 3D: Boublík–Mansoori–Carnahan–Starling–Leland (Boublík 1970; Mansoori et al., J. Chem. Phys.
//   54, 1523 (1971); Grundke–Henderson, Lee–Levesque),
//   g_ij = 1/(1 − φ) + (3/2) φ z_ij/(1 − φ)² + ½ φ² z_ij²/(1 − φ)³, Carnahan–Starling at z = 1.
// 2D: Jenkins and Mancini (J. Appl. Mech. 54, 27 (1987)), identical to the Santos–Yuste–López de
//   Haro linear form g_ij = 1/(1 − φ) + (χ_H(φ) − 1/(1 − φ)) z_ij with Henderson's χ_H.
double mixture_contact_value(int dimension, std::span<const MixtureSpecies> species,
                             std::size_t i, std::size_t j);

// Pressure from the virial route, P = T (n + Σ_ij n_i n_j ½ v_d(2σ_ij) g_ij) [force/length^{d−1}],
// ½ v_d(2σ_ij) being half the excluded volume of an i–j pair (the mixture's B2 per pair). In 3D
// this is the BMCSL equation of state; in 2D the Santos–Yuste–López de Haro one built on Henderson.
double mixture_pressure(int dimension, std::span<const MixtureSpecies> species, double temperature);

// Enskog frequency of collisions of one particle of species i with particles of species j:
// ω_ij = n_j g_ij β σ_ij^{d−1} ⟨|g|⟩_μij with μ_ij = m_i m_j/(m_i + m_j)
// (enskog_collision_frequency):
// n_j g_ij σ_ij √(2πT/μ_ij) in 2D, n_j g_ij σ_ij² √(8πT/μ_ij) in 3D [1/time].
double species_pair_collision_frequency(int dimension, std::span<const MixtureSpecies> species,
                                        std::size_t i, std::size_t j, double temperature);

// ω_i = Σ_j ω_ij, the collision frequency of one particle of species i [1/time].
double species_collision_frequency(int dimension, std::span<const MixtureSpecies> species,
                                   std::size_t i, double temperature);

// i–j collisions per unit volume and time: n_i ω_ij for i ≠ j, n_i ω_ii/2 for like pairs (each
// collision involves two particles) [1/(length^d time)]; symmetric in i and j.
double pair_collision_rate_density(int dimension, std::span<const MixtureSpecies> species,
                                   std::size_t i, std::size_t j, double temperature);

}  // namespace granule::theory
