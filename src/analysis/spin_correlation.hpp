// The spin correlation of neighbouring grains against their centre distance (thesis Fig C.4: under
// shear, rough disks close together spin in opposite senses).  Distances are in units of the pair's
// contact distance σ_ij = (σ_i + σ_j)/2; spins in the units of the state (1/time).
//
// What is correlated is the spin fluctuation δω = ω − ⟨ω⟩, ⟨ω⟩ the mean over the configuration's
// grains: a shear flow of rate γ carries a mean spin ≈ −γ/2 (half its vorticity), which alone would
// make every pair look aligned.  For a pair (i, j) at reduced distance r = |r_ij|/σ_ij,
//     C(r) = ⟨δω_i · δω_j⟩_pairs at r / ⟨|δω|²⟩_grains,
// so C = 1 for neighbours spinning alike, −1 for a pair of meshing gears, 0 for independent spins.
// The same with the pairs split by the direction of their separation: along the flow x (|Δx| the
// largest component) or along the gradient y (|Δy| the largest; in 3D pairs along z count only in
// the overall C).  C_contact is that of the pairs in contact: r < 1 + contact_shell.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "engine/system_params.hpp"

namespace granule {

struct SpinCorrelationSettings {
  double max_distance = 3.0;   // the largest r binned, in contact distances
  int bins = 20;               // equal bins of r over [1, max_distance]
  double contact_shell = 0.1;  // pairs with r < 1 + contact_shell are in contact
};

// Where a pair's images are: the box, which axes have walls (no images across them), and the
// Lees–Edwards offset Δ of the images above (thesis §1.4.2; 0 for a periodic box or y walls).
struct PairImages {
  std::array<double, 3> length{1.0, 1.0, 1.0};
  std::array<bool, 3> walls{};
  double shear_offset = 0.0;
};

// The pair directions of the split: all pairs, along the flow, along the gradient.
enum class PairDirection { kAll = 0, kFlow = 1, kGradient = 2 };
inline constexpr std::size_t kPairDirections = 3;

// The sums of one configuration, from which C follows, and which add over configurations.
struct SpinPairSums {
  // Per direction and bin: the pairs and Σ δω_i·δω_j / ⟨|δω|²⟩ over them (so C = products / pairs).
  std::array<std::vector<double>, kPairDirections> pairs, products;
  double contact_pairs = 0.0, contact_products = 0.0;
  std::array<double, 3> mean_spin{};  // ⟨ω⟩ subtracted (ω_z only for disks: entry 2)
  double spin_variance = 0.0;         // ⟨|δω|²⟩ over the grains

  // C of one bin (NaN without pairs), and C_contact.
  double correlation(PairDirection direction, std::size_t bin) const;
  double contact_correlation() const;
};

// Bin edges r_0 = 1 … r_bins = max_distance.
std::vector<double> spin_correlation_edges(const SpinCorrelationSettings& settings);

// The sums of one configuration of rough grains (state.rough()), `diameter` the σ of a monodisperse
// state (a polydisperse one carries its own); O(N) with a cell list of cells at least
// max_distance · σ_max wide.  Throws std::invalid_argument for a smooth state, settings out of
// range (max_distance ≤ 1 + contact_shell, bins < 1), or a periodic length below 2 · max_distance ·
// σ_max (a pair would have two images in range).  A configuration whose spins are all equal has
// ⟨|δω|²⟩ = 0: its products are 0 and it adds pairs only.
SpinPairSums spin_pair_sums(const ParticleState& state, const PairImages& images, double diameter,
                            const SpinCorrelationSettings& settings);

// The sums of several configurations, and the frame-to-frame scatter of C_contact.
struct SpinCorrelationAverage {
  SpinPairSums total;
  std::vector<double> contact_by_frame;  // C_contact of each configuration added

  void add(const SpinPairSums& frame);
  // Mean of the configurations' C_contact and its standard error, sd/√F (NaN for fewer than 2):
  // the configurations are taken as independent, so frames closer than a spin's relaxation time
  // make the error too small.
  double contact_mean() const;
  double contact_error() const;
};

}  // namespace granule
