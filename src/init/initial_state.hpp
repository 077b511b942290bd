// Initial conditions of thesis §1.4.2 for disks (d = 2) and spheres (d = 3): uniform
// non-overlapping positions, Gaussian velocities of variance T/m_i per component rescaled to
// exactly the temperature T_i per degree of freedom, T = Σ m_i |v_i − V|² / (d N) (the thesis's
// ½⟨v'²⟩ for unit-mass disks, eq 1.3), zero total momentum Σ m_i v_i, and for Lees–Edwards the
// linear shear profile u(y) = γ (y − L_y/2) along x added, γ = U/L_y with U the
// `profile_velocity` (default: params.shear_velocity; 0 gives the static gas of thesis §4.3).
// With walls every centre starts at least its own radius from each wall, and between
// moving y walls the profile runs linearly from one wall's velocity to the other's; rough grains
// get Gaussian angular velocities, drawn after everything else so that smooth runs keep their
// initial states bit for bit.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "engine/system_params.hpp"
#include "init/particle_sizes.hpp"

namespace granule {

enum class Placement {
  kAuto,     // random sequential addition up to random_placement_limit(d), a lattice above
  kRandom,   // random sequential addition (jams near ν ≈ 0.55 in 2D, φ ≈ 0.38 in 3D)
  kLattice,  // triangular (2D) or FCC (3D) lattice with random vacancies, melted by the elastic pre-run
};

// The packing fractions up to which `auto` places particles at random: area fraction 0.45 of
// disks, volume fraction 0.30 of spheres (random sequential addition jams at 0.547 and 0.38).
inline constexpr double kRandomPlacementLimit = 0.45;
inline constexpr double kRandomPlacementLimit3d = 0.30;
inline double random_placement_limit(int dimension) {
  return dimension == 3 ? kRandomPlacementLimit3d : kRandomPlacementLimit;
}
// Hexagonal close packing of disks, π / (2√3), and FCC packing of spheres, π / (3√2): no state
// of equal particles at or above them exists.
inline constexpr double kClosePacking = 0.9068996821171089;
inline constexpr double kClosePacking3d = 0.7404804896930609;
inline double close_packing(int dimension) { return dimension == 3 ? kClosePacking3d : kClosePacking; }

// What walls and rough grains add to an initial state.
struct WallFlowAndSpins {
  // Between y walls: v_x(y) linear from the lower wall's velocity to the upper one's (a wall-driven
  // Couette flow); false: a static gas.  profile_velocity (Lees–Edwards images) is 0 then.
  bool wall_profile = true;
  // Rough grains: T_rot = Σ I_i |ω_i|² / (d_rot N), I_i = q m_i σ_i²/4, d_rot = 1 (disks) or 3
  // (spheres); default the translational T (equipartition); 0: no spin.
  std::optional<double> rotational_temperature;
};

struct InitialStateResult {
  ParticleState state;
  std::string error;  // empty on success
};

// `sizes`: per-particle diameters (sorted in decreasing order, the largest equal to
// params.diameter) and masses of a polydisperse system; empty for a monodisperse one.
InitialStateResult make_initial_state(const SystemParams& params, double temperature, std::uint64_t seed,
                                      Placement placement, std::optional<double> profile_velocity = std::nullopt,
                                      const ParticleSizes& sizes = {}, const WallFlowAndSpins& walls_and_spins = {});

}  // namespace granule
