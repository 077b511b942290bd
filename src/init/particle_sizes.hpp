// Diameters and masses of polydisperse runs, and the packing fraction they give.
// Diameters are σ_i = σ̄ r_i: a reference diameter σ̄ (system.diameter, or solved from the packing
// fraction) times relative sizes r_i drawn from the run's seed on a stream of their own, so that
// they are known before placement and the same on every platform.  The realised diameters are
// sorted in decreasing order (particle 0 is the largest), which is the order of placement.
#pragma once

#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "engine/system_params.hpp"

namespace granule {

enum class SizeDistributionKind {
  kMonodisperse,  // every σ = σ̄, unit mass
  kBidisperse,    // round(x_B N) particles of σ_B = ratio · σ̄, the others of σ_A = σ̄ (exact counts)
  kUniform,       // σ uniform in [σ̄ (1 − w), σ̄ (1 + w)]: mean σ̄
  kLogNormal,     // ln σ normal with standard deviation s, and mean of σ equal to σ̄
};

struct SizeDistribution {
  SizeDistributionKind kind = SizeDistributionKind::kMonodisperse;
  double ratio = 1.0;     // σ_B / σ_A (bidisperse)
  double fraction = 0.0;  // x_B, the number fraction of species B (bidisperse)
  double width = 0.0;     // w (uniform) or s (log-normal)
  // [m_A, m_B] (bidisperse only); absent: m_i ∝ σ_i^d with mean mass 1.
  std::optional<std::pair<double, double>> species_masses;
  bool monodisperse() const { return kind == SizeDistributionKind::kMonodisperse; }
};

// Per-particle diameters and masses, both empty for a monodisperse system.
struct ParticleSizes {
  std::vector<double> diameter;
  std::vector<double> mass;
  bool monodisperse() const { return diameter.empty(); }
};

// round(x_B N): the exact number of particles of species B.
std::int64_t species_b_count(const SizeDistribution& distribution, std::int64_t n);

// What the configuration needs of the relative sizes without storing them (O(1) memory):
// Σ r_i^d, and the largest and smallest r_i, from the same draws as relative_diameters (up to the
// order of summation).
struct RelativeSizeSummary {
  double sum_of_powers = 0.0;  // Σ r_i^d (N for a monodisperse system)
  double largest = 1.0;
  double smallest = 1.0;
};
RelativeSizeSummary summarize_relative_sizes(const SizeDistribution& distribution, int dimension, std::int64_t n,
                                             std::uint64_t seed);

// r_i in decreasing order (empty when monodisperse).
std::vector<double> relative_diameters(const SizeDistribution& distribution, std::int64_t n, std::uint64_t seed);

// σ_i = σ̄ r_i and the masses (m_i = r_i^d / ⟨r^d⟩, or the species masses); empty when monodisperse.
ParticleSizes particle_sizes(const SizeDistribution& distribution, int dimension, std::int64_t n,
                             double reference_diameter, std::uint64_t seed);

// ν = π Σ σ_i^d / (k_d V), k_2 = 4 (area fraction), k_3 = 6 (volume fraction), with σ_i = σ̄ r_i
// and sum_of_powers = Σ r_i^d.
double packing_fraction(int dimension, double sum_of_powers, double reference_diameter, double volume);
// The σ̄ for which packing_fraction(...) = ν.
double reference_diameter_for(int dimension, double packing_fraction, double sum_of_powers, double volume);
// L_x L_y in 2D, L_x L_y L_z in 3D.
double box_volume(const SystemParams& params);
// The packing fraction of a system with these sizes (params.diameter when monodisperse).
double packing_fraction(const SystemParams& params, const ParticleSizes& sizes);

}  // namespace granule
