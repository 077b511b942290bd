// The zeroth-order amplitudes b₀⁽⁰⁾, b₀⁽¹⁾, b₀⁽²⁾ of thesis Appendix B, in the thesis's units, and
// the map from those units to a run's.  Appendix B's windows (ρ = 1.6…2.8·10⁵ per unit area, T = 0.11
// … 0.7) belong to the system of Chapter 5: "the parameters other than ẽ are as for System III"
// (L_x = L_y = 1, U = 100, ν̄ = 0.05, unit mass) but with "hundreds of thousands of particles" (§5.1):
// ρ windows around the mean N/L² = 2·10⁵ give N = 2·10⁵ (as in Fig 3.1), so σ = √(4ν̄/πN) =
// 5.64·10⁻⁴ (System IV's); T̄ of (3.1) in that system is 0.10, 0.15, 0.23, 0.48 for ẽ = 0.6 … 0.9,
// where the tables' T windows lie.  At fixed ν̄ and ẽ a dilute sheared gas has no scales but σ, 1/γ
// and the box, so lengths map by σ_run/σ_thesis and times by γ_thesis/γ_run: velocities by
// u = (σ_run γ_run)/(σ_thesis γ_thesis), T by u², ρ by (σ_thesis/σ_run)², b⁽¹⁾ by 1/u, b⁽²⁾ by 1/u², and
// b⁽⁰⁾ = −log f (f normalised over the velocity plane, units 1/velocity²) by + 2 log u.  What the map
// cannot change is the box in units of σ (L/σ = 1773 in the thesis): a run with another N is another
// finite system (docs/f1.md, "Units").
#pragma once

#include <span>

#include "engine/system_params.hpp"

namespace granule::distribution {

// The system of Appendix B (thesis units).
struct AppendixBSystem {
  static constexpr double particles = 2.0e5;
  static constexpr double box = 1.0;            // L_x = L_y
  static constexpr double shear_velocity = 100.0;  // U, so γ = U/L_y = 100
  static constexpr double area_fraction = 0.05;
  static double diameter();  // √(4 ν̄ L²/(π N)) = 5.64·10⁻⁴
};

// One window of Appendix B and its row j = 0.
struct AppendixBEntry {
  double restitution;
  double density, density_half_width;          // per unit area
  double temperature, temperature_half_width;  // T = ½⟨v′²⟩ (1.3)
  double b0, b1, b2;                           // b₀⁽⁰⁾, b₀⁽¹⁾, b₀⁽²⁾
};

// The 64 windows of Appendix B (ẽ = 0.6, 0.7, 0.8, 0.9; 4 ρ × 4 T each), thesis units.
std::span<const AppendixBEntry> appendix_b_means();

// Run units per thesis unit.
struct ThesisUnitMap {
  double length = 1.0;    // σ_run/σ_thesis
  double velocity = 1.0;  // (σ_run γ_run)/(σ_thesis γ_thesis)
  AppendixBEntry to_run_units(const AppendixBEntry& thesis) const;
};

// The map for a Lees–Edwards run (γ = U/L_y, σ the run's diameter).
ThesisUnitMap appendix_b_unit_map(const SystemParams& run);

}  // namespace granule::distribution
