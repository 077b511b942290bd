// Hydrostatic equilibrium of an elastic hard-disk (d = 2) or hard-sphere (d = 3) gas at one
// temperature T in a uniform gravity g along −y above a flat hard floor, in the local-density
// approximation (P(y) = n T Z(φ(y)) with Henderson's Z in 2D, Carnahan–Starling's in 3D), and the
// contact theorem for a hard wall. Units: k_B = 1, T per degree of freedom [mass·length²/time²],
// g [length/time²], heights y [length] of particle centres above their lowest position (σ/2
// above the floor), N_A the number of particles per unit floor area (3D) or per unit floor length
// (2D) [1/length^{d−1}]. The local-density theory ignores the layering a hard floor imposes
// within a few σ of it. Derivations in docs/theory.md. d must be 2 or 3.
#pragma once

#include <span>
#include <vector>

namespace granule::theory {

// d(φZ)/dφ = (1/T) ∂P/∂n, the inverse isothermal compressibility in units of the ideal gas's:
// (8 + 8φ + 3φ² − φ³)/(8(1 − φ)³) for Henderson's disks, (1 + 4φ + 4φ² − 4φ³ + φ⁴)/(1 − φ)⁴
// for Carnahan–Starling's spheres.
double hard_sphere_inverse_compressibility(int dimension, double packing_fraction);

// Excess chemical potential over T, μ_ex/T = ∫_0^φ (Z − 1)/φ' dφ' + Z − 1:
// φ(25 − 16φ)/(8(1 − φ)²) − (7/8) ln(1 − φ) for disks, φ(8 − 9φ + 3φ²)/(1 − φ)³ for spheres.
double hard_sphere_excess_chemical_potential(int dimension, double packing_fraction);

struct HydrostaticColumn {
  int dimension;
  double diameter;                  // σ [length]
  double mass;                      // m [mass]
  double gravity;                   // g > 0 [length/time²], pointing to −y
  double temperature;               // T
  double particles_per_floor_area;  // N_A [1/length^{d−1}]
};

// The barometric height T/(m g) [length].
double barometric_height(const HydrostaticColumn& column);

// φ at the bottom (y = 0): the root of φ Z(φ) = v_d m g N_A/T, i.e. P(0) = m g N_A, the weight of
// the column per unit floor area. Throws std::invalid_argument for a column that is not a gas
// (non-positive g, T, m, σ or N_A, or a dimension other than 2, 3).
double hydrostatic_bottom_packing_fraction(const HydrostaticColumn& column);

// φ(y) at the given heights (y ≥ 0): the solution of μ(φ(y)) + m g y = μ(φ(0)), i.e.
// ln φ + μ_ex(φ)/T = ln φ0 + μ_ex(φ0)/T − y/h with h the barometric height, which is
// dP/dy = −m g n integrated exactly; n(y) = φ(y)/v_d (number_density).
std::vector<double> hydrostatic_packing_fraction(const HydrostaticColumn& column,
                                                 std::span<const double> heights);

// Contact theorem of a flat hard wall bounding a fluid in equilibrium (exact, any density): the
// pressure on the wall is T times the density of centres at contact (σ/2 from the wall). With a
// homogeneous fluid of bulk density n beside the wall that pressure is the bulk P = n T Z(φ), so
// the contact density is n Z(φ) [1/length^d] (the wall's layering raises it above n).
double wall_contact_density(int dimension, double number_density, double packing_fraction);

// Under gravity the floor carries the whole weight, P_floor = m g N_A (momentum balance, exact),
// so the contact density of centres at the floor is m g N_A/T [1/length^d], whatever the layering.
double floor_contact_density(const HydrostaticColumn& column);

}  // namespace granule::theory
