// Initial conditions of thesis §1.4.2: uniform non-overlapping positions, Gaussian velocities at
// temperature T_i (T = ½⟨(v − V)²⟩, unit mass, eq 1.3), zero total momentum, and for
// Lees–Edwards the linear shear profile u(y) = γ (y − L_y/2) added, γ = U/L_y with U the
// `profile_velocity` (default: params.shear_velocity; 0 gives the static gas of thesis §4.3).
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "engine/system_params.hpp"

namespace granule {

enum class Placement {
  kAuto,     // random sequential addition up to ν = kRandomPlacementLimit, a lattice above
  kRandom,   // random sequential addition (jams near ν ≈ 0.55)
  kLattice,  // triangular lattice with random vacancies, to be melted by the elastic pre-run
};

inline constexpr double kRandomPlacementLimit = 0.45;
// Hexagonal close packing of disks, π / (2√3): no state at or above it exists.
inline constexpr double kClosePacking = 0.9068996821171089;

struct InitialStateResult {
  ParticleState state;
  std::string error;  // empty on success
};

InitialStateResult make_initial_state(const SystemParams& params, double temperature,
                                      std::uint64_t seed, Placement placement,
                                      std::optional<double> profile_velocity = std::nullopt);

}  // namespace granule
