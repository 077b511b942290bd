// The collisional transfer fields of a run of disks (D = 2) or spheres (D = 3), accumulated from
// collision records per cell of the coarse-graining grid (V the cell area or volume, t the length
// of the averaging interval):
//  • the collisional stress of thesis eq (1.6): τ^(c) = 1/(V t) Σ σ_ij J k̂ k̂.  Each collision moves
//    momentum J k̂ across the contact over the distance σ_ij between the centres (§1.4.3, after
//    Allen & Tildesley §16.4); σ_ij = σ in a monodisperse run, (σ_i + σ_j)/2 in a polydisperse one;
//  • the collisional heat flux q^(c) = 1/(V t) Σ σ_ij J k̂ [k̂·(c₁ + c₂)/2 + J (1/m₂ − 1/m₁)/4],
//    c = v − V(r) the peculiar velocities of the pair before the collision: each collision moves
//    the energy (ΔE₂ − ΔE₁)/2 across the contact over σ_ij k̂ (derivation below and in
//    docs/macrostructure.md; the mass term vanishes for equal masses).
// A collision belongs to the cell of its contact point.  Summed over all cells these are exactly
// the global collisional stress and heat flux of the whole box; the collisional pressure is the
// trace over d.
//
// Derivation of q^(c) (k̂ from particle 1 to particle 2, J k̂ the impulse on particle 2, so
// c₂′ = c₂ + J k̂/m₂, c₁′ = c₁ − J k̂/m₁).  The peculiar kinetic energies change by
//     ΔE₂ = J k̂·(c₂ + c₂′)/2,   ΔE₁ = −J k̂·(c₁ + c₁′)/2,
// at r₂ = r₁ + σ k̂ and r₁.  Split the local change ΔE₁ δ(r − r₁) + ΔE₂ δ(r − r₂) into a source
// (ΔE₁ + ΔE₂)/2 [δ(r − r₁) + δ(r − r₂)] — the collisional loss, −(1 − ẽ²)(k̂·v₂₁)²/4, shared by
// the two disks — and (ΔE₂ − ΔE₁)/2 [δ(r − r₂) − δ(r − r₁)] = −∇·[(ΔE₂ − ΔE₁)/2 σ k̂ ∫₀¹ δ(r − r₁ − sσk̂) ds],
// the divergence of a flux carried along the segment between the centres.  (ΔE₂ − ΔE₁)/2 =
// J k̂·(c₁ + c₂ + c₁′ + c₂′)/4 = J k̂·(c₁ + c₂)/2 + J² (1/m₂ − 1/m₁)/4 (for unit masses the thesis's
// c₁ + c₂ = c₁′ + c₂′); the same split of Δp₂ = J k̂, Δp₁ = −J k̂ gives (1.6) (Lun et al. 1984,
// J. Fluid Mech. 140, 223).
//
// The observer needs no image velocity U: it sums the pair's velocities in the frame of the
// contact point's cell, s = (v₁ + v₂)/2 (lab velocities, a Lees–Edwards partner taken as the image
// in that cell's frame), as E = Σ σ_ij J k̂ (k̂·s + J (1/m₂ − 1/m₁)/4).  Since k̂·(c₁ + c₂)/2 =
// k̂·s − k̂·V for a reference velocity V of the cell, q^(c) = E/(V t) − τ^(c)·V is formed when the
// interval closes (collisional_heat_flux), with the V of the caller's choosing (the interval's
// mean V(r)).
//
// In 2D every value is the plain 2D computation, operation for operation: the sums are
// Σ J k̂ k̂ (σ_ij/σ = 1 is not multiplied in) scaled by σ/(V t).
//
// Rough grains: the momentum given to particle 2 is P = J k̂ + P_t (the record's
// tangential_impulse), so τ^(c)_ab = 1/(V t) Σ σ_ij k̂_a P_b — no longer symmetric: its entries below
// the diagonal (yx, zx, zy) are kept as well, τ_yx being the flux of x momentum along y (what a y
// wall feels).  The trace, and the pressure, are unchanged (P_t ⊥ k̂).  The energy carried is the
// translational one, σ_ij k̂ [P·s + |P|² (1/m₂ − 1/m₁)/4] (the same derivation with P in place of
// J k̂); the exchange of rotational energy is not in q^(c).
#pragma once

#include <optional>
#include <vector>

#include "analysis/cell_fields.hpp"
#include "analysis/field_grid.hpp"
#include "boundary/shear_frame.hpp"
#include "engine/observer.hpp"
#include "archive/state_archive.hpp"

namespace granule {

struct CollisionalStress {
  std::vector<double> xx, xy, yy;  // per cell: τ_ab = Σ σ k̂_a P_b (a ≤ b)
  std::vector<double> collisions;  // collisions per cell in the interval
  double interval = 0.0;           // t: length of the averaging interval
  std::vector<double> energy_x, energy_y;  // 1/(V t) Σ σ_ij J k̂ (k̂·s + …): the lab-frame energy transfer
  std::vector<double> xz, yz, zz, energy_z;  // 3D only (empty in 2D)
  std::vector<double> yx, zx, zy;  // rough grains only: the entries below the diagonal (zx, zy in 3D)

  bool full() const { return !yx.empty(); }
  // τ^(c)_ab, the lower entries from the upper ones unless the tensor is full, and the energy
  // transfer by axis (0 = x, 1 = y, 2 = z).
  std::vector<double>& component(int a, int b);
  const std::vector<double>& component(int a, int b) const { return const_cast<CollisionalStress&>(*this).component(a, b); }
  std::vector<double>& energy(int a) { return a == 0 ? energy_x : (a == 1 ? energy_y : energy_z); }
  const std::vector<double>& energy(int a) const { return const_cast<CollisionalStress&>(*this).energy(a); }
  // The collisional pressure Tr τ^(c) / d of cell c.
  double pressure(std::size_t c) const;
};

// `diameter`: σ of a monodisperse run, or none (polydisperse): then each collision's own σ_ij.
template <int D>
class CollisionalStressField final : public EventObserver<D> {
 public:
  // `rough`: collisions carry tangential impulses (the full tensor is kept).
  CollisionalStressField(const FieldGrid& grid, std::optional<double> diameter, bool rough = false);
  void on_collision(const CollisionRecord<D>& record) override;
  // Start a new averaging interval at time t.
  void restart(double t);
  // The stress (1.6) and energy transfer over the interval [start, t].
  CollisionalStress stress(double t) const;
  double interval_start() const { return start_; }
  void save(StateArchive& archive, const std::string& prefix) const;
  void restore(const StateArchive& archive, const std::string& prefix);

 private:
  FieldGrid grid_;
  std::optional<double> diameter_;
  bool rough_ = false;
  double start_ = 0.0;
  CollisionalStress sums_;  // unscaled sums Σ (σ_ij/σ) J k̂k̂, Σ (σ_ij/σ) J k̂ (k̂·s + …) and counts of the open interval
};

// The velocity of the pair (v₁ + v₂)/2 before the collision, in the lab frame of the cell that
// holds the record's contact point: particle 1's frame if the contact point lies on its side of
// the box, else (a contact mapped across the Lees–Edwards boundary) particle 2's.  No U needed:
// the relative velocity v₂₁ is the same in every frame.  `diameter` is σ_ij (any length well below
// L_y/2 decides the side the same way), `length_y` the box height L_y.
template <int D>
Vec<D> pair_velocity_at_contact(const CollisionRecord<D>& record, double diameter, double length_y);

// q^(c) = E/(V t) − τ^(c)·V per cell, V = (reference_x, reference_y(, reference_z)) the lab
// velocity the peculiar velocities are taken from in each cell (normally the interval's mean V(r)).
struct HeatFlux {
  std::vector<double> x, y;
  std::vector<double> z;  // 3D only
  std::vector<double>& component(int a) { return a == 0 ? x : (a == 1 ? y : z); }
  const std::vector<double>& component(int a) const { return const_cast<HeatFlux&>(*this).component(a); }
};
HeatFlux collisional_heat_flux(const CollisionalStress& stress, const std::vector<double>& reference_x,
                               const std::vector<double>& reference_y, const std::vector<double>& reference_z = {});
// The same about the interval's mean velocity V(r) of `average` (the cell fields of the same
// interval and grid).  When those were measured relative to the mean flow u(y) (`frame`'s U at the
// interval's end), the reference is V(r) + u(y) at the cell's centre: the collisional flux is then
// taken about u at the centre of the cell rather than at each contact point (the difference,
// γ Σ J k̂ k̂_x (y_contact − y_centre), has zero mean when contacts fill the cell evenly).
HeatFlux collisional_heat_flux(const CollisionalStress& stress, const CellFields& average, const ShearFrame& frame,
                               bool shear_profile_subtracted);

}  // namespace granule
