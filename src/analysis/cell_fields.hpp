// Coarse-grained fields of thesis §1.4.3 from particle configurations: number density ρ(r),
// velocity V(r) (momentum over mass), temperature T(r) (1.3), kinetic stress τ^(k) (1.4) via the
// identity (1.5), kinetic pressure (half trace), vorticity and the kinetic heat flux
// q^(k) = Σ ½|c|² c / cell area, c = v − V(r) (docs/macrostructure.md).  Unit mass: ρ is both the
// number and the mass density (particles per unit area).
//
// Fields come from cell moments (count, Σv, Σvv, Σ|v|²v).  Moments add up, so the same code gives the
// instantaneous fields of one configuration and the interval-averaged fields of many (sums over
// K configurations, ρ divided by K): V and T are then mass-weighted averages, as the ensemble
// averages of §5.2.
#pragma once

#include <vector>

#include "analysis/field_grid.hpp"
#include "boundary/shear_frame.hpp"
#include "engine/state_archive.hpp"
#include "engine/system_params.hpp"

namespace granule {

struct CellMoments {
  FieldGrid grid;
  int configurations = 0;  // how many configurations were added
  std::vector<double> count, px, py, pxx, pxy, pyy;
  std::vector<double> energy_flux_x, energy_flux_y;  // Σ |v|² v: the third moments of q^(k)

  explicit CellMoments(const FieldGrid& g);
  // Add one configuration.  With `subtract_shear_profile`, each particle's velocity is taken
  // relative to the mean Lees–Edwards flow u(y) = γ (y − L_y/2) of `frame` before it is summed.
  void add(const ParticleState& state, const ShearFrame& frame, bool subtract_shear_profile);
  void save(StateArchive& archive, const std::string& prefix) const;
  void restore(const StateArchive& archive, const std::string& prefix);
};

struct CellFields {
  FieldGrid grid;
  std::vector<double> count;        // particles per cell (per configuration)
  std::vector<double> density;      // ρ = count / cell area
  std::vector<double> velocity_x;   // V(r); 0 in empty cells
  std::vector<double> velocity_y;
  std::vector<double> temperature;  // T(r) = ½⟨(v − V)²⟩ (1.3); 0 in empty cells
  std::vector<double> kinetic_xx;   // τ^(k) = ρ⟨v'v'⟩ (1.4)
  std::vector<double> kinetic_xy;
  std::vector<double> kinetic_yy;
  std::vector<double> pressure_kinetic;  // ½ Tr τ^(k) = ρ T
  std::vector<double> vorticity;    // ω = ∂V_y/∂x − ∂V_x/∂y, central differences across cells
  std::vector<double> heat_flux_kinetic_x;  // q^(k) = ρ⟨½|v'|² v'⟩, v' = v − V(r); 0 in empty cells
  std::vector<double> heat_flux_kinetic_y;
};

// `frame` and `shear_offset` (the Lees–Edwards image offset Δ) give the neighbours of the top and
// bottom rows for the vorticity: the row above the top is the bottom row shifted by Δ, moving at
// +U (unless the shear profile was subtracted).
CellFields fields_from_moments(const CellMoments& moments, const ShearFrame& frame, double shear_offset,
                               bool shear_profile_subtracted);

}  // namespace granule

namespace granule {

// The named per-cell fields, in one list for writers and readers.
template <typename Fields, typename Visit>
void for_each_field(Fields& f, Visit&& visit) {
  visit("count", f.count);
  visit("density", f.density);
  visit("velocity_x", f.velocity_x);
  visit("velocity_y", f.velocity_y);
  visit("temperature", f.temperature);
  visit("kinetic_xx", f.kinetic_xx);
  visit("kinetic_xy", f.kinetic_xy);
  visit("kinetic_yy", f.kinetic_yy);
  visit("pressure_kinetic", f.pressure_kinetic);
  visit("vorticity", f.vorticity);
  visit("heat_flux_kinetic_x", f.heat_flux_kinetic_x);
  visit("heat_flux_kinetic_y", f.heat_flux_kinetic_y);
}

// Streamwise averages over each row of cells (Figs 3.15–3.16): ρ(y) the row mean of ρ, the
// mass-weighted row means V_x(y), V_y(y), T(y) = Σ ρ T / Σ ρ, and the row means of the kinetic heat
// flux (a flux per unit area, like ρ: each cell's own q^(k), about its own V(r)).
struct StreamwiseProfiles {
  std::vector<double> y, density, velocity_x, velocity_y, temperature, heat_flux_kinetic_x, heat_flux_kinetic_y;
};
StreamwiseProfiles streamwise_profiles(const CellFields& fields);
// The mean over each row of cells of a per-cell field (index iy).
std::vector<double> row_means(const FieldGrid& grid, const std::vector<double>& field);

}  // namespace granule
