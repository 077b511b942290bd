// Coarse-grained fields of thesis §1.4.3 from particle configurations, in 2D and 3D: number density
// n(r) (particles per unit area or volume), velocity V(r) (momentum over mass), temperature T(r)
// per degree of freedom (1.3), T = Σ m|v − V|² / (d · count), kinetic stress τ^(k) = Σ m v'v' / cell
// (1.4) via the identity (1.5), kinetic pressure Tr τ^(k) / d = n T, the z component of the
// vorticity and the kinetic heat flux q^(k) = Σ ½ m|c|² c / cell, c = v − V(r)
// (docs/macrostructure.md).  Unit masses unless the configuration carries masses (polydisperse):
// then V, τ^(k), T and q^(k) are mass-weighted and ρ stays the number density.  In 2D with unit
// masses no 3D or mass term enters: every value is the plain 2D computation, operation for operation.
//
// Rough grains add the mean angular velocity Ω(r) = Σ I ω / Σ I (per component: ω_z
// of disks, ω_x, ω_y, ω_z of spheres) and the rotational temperature T_rot(r) = Σ I|ω − Ω|² /
// (d_rot · count), d_rot = 1 for disks and 3 for spheres, I = q m σ²/4 — the rotational analogue
// of (1.3), the spin fluctuation about the cell's mean spin.
//
// Fields come from cell moments (count, Σmv, Σmvv, Σm|v|²v).  Moments add up, so the same code gives
// the instantaneous fields of one configuration and the interval-averaged fields of many (sums over
// K configurations, ρ divided by K): V and T are then mass-weighted averages, as the ensemble
// averages of §5.2.
#pragma once

#include <vector>

#include "analysis/field_grid.hpp"
#include "boundary/shear_frame.hpp"
#include "archive/state_archive.hpp"
#include "engine/state_blocks.hpp"
#include "engine/system_params.hpp"

namespace granule {

// The moment of inertia of grain i, I = q m σ²/4 (q = RoughnessParams::inertia_factor), with σ the
// grain's own diameter when the state carries diameters, else the monodisperse `diameter`.
struct SpinInertia {
  double inertia_factor = 0.0;  // q; 0: unknown (moments of smooth grains only)
  double diameter = 0.0;        // σ of a monodisperse system
  double of(const ParticleState& state, std::size_t i) const {
    const double sigma = state.diameter_of(i, diameter);
    return 0.25 * inertia_factor * state.mass_of(i) * sigma * sigma;
  }
};
inline SpinInertia spin_inertia(const SystemParams& system) { return {system.roughness.inertia_factor, system.diameter}; }

struct CellMoments {
  FieldGrid grid;
  SpinInertia inertia;
  int configurations = 0;  // how many configurations were added
  std::vector<double> count, px, py, pxx, pxy, pyy;
  std::vector<double> energy_flux_x, energy_flux_y;  // Σ m|v|² v: the third moments of q^(k)
  std::vector<double> pz, pxz, pyz, pzz, energy_flux_z;  // 3D only (empty in 2D)
  // Σ m per cell: kept only once a configuration with masses was added (with unit masses it is `count`).
  std::vector<double> mass;
  // Rough grains only, kept once a configuration with spins was added: Σ I, Σ I ω_k (k over the
  // spin components: z alone for disks) and Σ I|ω|².
  std::vector<double> inertia_sum, spin_x, spin_y, spin_z, spin_square;

  // With `inertia` (q > 0), configurations of rough grains add their spins; without, spins are ignored.
  explicit CellMoments(const FieldGrid& g, const SpinInertia& inertia = {});
  bool rough() const { return !inertia_sum.empty(); }
  std::vector<double>& spin(int k) { return k == 0 ? spin_x : (k == 1 ? spin_y : spin_z); }
  const std::vector<double>& spin(int k) const { return const_cast<CellMoments&>(*this).spin(k); }
  // Add one configuration (of the grid's dimension).  With `subtract_shear_profile`, each
  // particle's velocity is taken relative to the mean Lees–Edwards flow u(y) = γ (y − L_y/2) of
  // `frame` before it is summed.
  void add(const StateBlocks& state, const ShearFrame& frame, bool subtract_shear_profile);
  void save(StateArchive& archive, const std::string& prefix) const;
  void restore(const StateArchive& archive, const std::string& prefix);

  // Σ m v_a, Σ m v_a v_b (either order) and Σ m|v|² v_a by axis (0 = x, 1 = y, 2 = z).
  std::vector<double>& momentum(int a) { return a == 0 ? px : (a == 1 ? py : pz); }
  const std::vector<double>& momentum(int a) const { return const_cast<CellMoments&>(*this).momentum(a); }
  std::vector<double>& second_moment(int a, int b);
  const std::vector<double>& second_moment(int a, int b) const { return const_cast<CellMoments&>(*this).second_moment(a, b); }
  std::vector<double>& energy_flux(int a) { return a == 0 ? energy_flux_x : (a == 1 ? energy_flux_y : energy_flux_z); }
  const std::vector<double>& energy_flux(int a) const { return const_cast<CellMoments&>(*this).energy_flux(a); }

 private:
  void start_spin_moments();
  void add_spin(const ParticleState& state, std::size_t i, std::size_t c);
  // The particles of one block of a configuration (add counts the configuration once).
  void add_particles(const ParticleState& state, const ShearFrame& frame, bool subtract_shear_profile);
};

// The axes about which grains of dimension d spin: z alone for disks, x, y, z for spheres.
inline int first_spin_axis(int dimension) { return dimension == 3 ? 0 : 2; }

struct CellFields {
  FieldGrid grid;
  std::vector<double> count;        // particles per cell (per configuration)
  std::vector<double> density;      // ρ = count / cell area (2D) or volume (3D)
  std::vector<double> velocity_x;   // V(r); 0 in empty cells
  std::vector<double> velocity_y;
  std::vector<double> temperature;  // T(r) = Σ m|v − V|² / (d · count) (1.3); 0 in empty cells
  std::vector<double> kinetic_xx;   // τ^(k) = Σ m v'v' / cell (1.4); ρ⟨v'v'⟩ for unit masses
  std::vector<double> kinetic_xy;
  std::vector<double> kinetic_yy;
  std::vector<double> pressure_kinetic;  // Tr τ^(k) / d = ρ T
  std::vector<double> vorticity;    // ω_z = ∂V_y/∂x − ∂V_x/∂y, central differences across cells (each layer in 3D)
  std::vector<double> heat_flux_kinetic_x;  // q^(k) = Σ ½ m|v'|² v' / cell, v' = v − V(r); 0 in empty cells
  std::vector<double> heat_flux_kinetic_y;
  std::vector<double> velocity_z, kinetic_xz, kinetic_yz, kinetic_zz, heat_flux_kinetic_z;  // 3D only
  // Rough grains only (empty otherwise): Ω(r) = Σ I ω / Σ I (spin_z alone for disks) and T_rot(r);
  // 0 in empty cells.
  std::vector<double> spin_x, spin_y, spin_z, rotational_temperature;
  bool rough = false;
  std::vector<double>& spin(int k) { return k == 0 ? spin_x : (k == 1 ? spin_y : spin_z); }

  std::vector<double>& velocity(int a) { return a == 0 ? velocity_x : (a == 1 ? velocity_y : velocity_z); }
  std::vector<double>& kinetic(int a, int b);
  std::vector<double>& heat_flux_kinetic(int a) {
    return a == 0 ? heat_flux_kinetic_x : (a == 1 ? heat_flux_kinetic_y : heat_flux_kinetic_z);
  }
};

// `frame` and `shear_offset` (the Lees–Edwards image offset Δ) give the neighbours of the top and
// bottom rows for the vorticity: the row above the top is the bottom row shifted by Δ, moving at
// +U (unless the shear profile was subtracted).
CellFields fields_from_moments(const CellMoments& moments, const ShearFrame& frame, double shear_offset,
                               bool shear_profile_subtracted);

// The bytes the arrays of one CellMoments and of one CellFields on `grid` take, with the Σm of
// configurations with masses and the spin moments and fields of rough grains or without: one double
// per array and cell, the arrays counted in the lists that hold them (the moments' checkpoint
// list, for_each_field).  An analysis's memory check adds one per set it keeps.
double cell_moments_bytes(const FieldGrid& grid, bool masses, bool rough);
double cell_fields_bytes(const FieldGrid& grid, bool rough);

}  // namespace granule

namespace granule {

// The named per-cell fields, in one list for writers and readers: the 2D set, then in 3D the z
// components.
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
  if (f.grid.dimension == 3) {
    visit("velocity_z", f.velocity_z);
    visit("kinetic_xz", f.kinetic_xz);
    visit("kinetic_yz", f.kinetic_yz);
    visit("kinetic_zz", f.kinetic_zz);
    visit("heat_flux_kinetic_z", f.heat_flux_kinetic_z);
  }
  if (!f.rough) return;
  if (f.grid.dimension == 3) {
    visit("spin_x", f.spin_x);
    visit("spin_y", f.spin_y);
  }
  visit("spin_z", f.spin_z);
  visit("rotational_temperature", f.rotational_temperature);
}

// Streamwise averages over each row of cells (Figs 3.15–3.16; in 3D over x and z): ρ(y) the row
// mean of ρ, the mass-weighted row means V_x(y), V_y(y), T(y) = Σ ρ T / Σ ρ, and the row means of
// the kinetic heat flux (a flux per unit area, like ρ: each cell's own q^(k), about its own V(r)).
struct StreamwiseProfiles {
  std::vector<double> y, density, velocity_x, velocity_y, temperature, heat_flux_kinetic_x, heat_flux_kinetic_y;
};
StreamwiseProfiles streamwise_profiles(const CellFields& fields);
// The mean over each row of cells (all ix, and all iz in 3D) of a per-cell field (index iy).
std::vector<double> row_means(const FieldGrid& grid, const std::vector<double>& field);

}  // namespace granule
