// Per-configuration scalars that tell the flow states of thesis Chapter 4 apart (§4.2–4.3):
// quasihomogeneous flow (small values throughout), a plugged flow or streamwise layers (large
// density contrast and densest-band fraction, V_x(y) far from linear), clusters (largest cluster).
// Definitions in docs/macrostructure.md.  The image velocity U and offset Δ are arguments (they
// may depend on time): nothing here reads the run's fixed parameters.
#pragma once

#include <cstdint>
#include <vector>

#include "boundary/shear_frame.hpp"
#include "engine/state_blocks.hpp"
#include "engine/system_params.hpp"

namespace granule {

struct FlowClassificationSettings {
  int rows = 10;                   // rows of the streamwise profiles ρ(y), V_x(y)
  double band_fraction = 0.2;      // width of the densest band, as a fraction of L_y
  double cluster_gap = 0.1;        // δ: disks with centres closer than (1 + δ) σ are connected
};

struct FlowClassification {
  double density_contrast = 0.0;           // (max − min)/mean of ρ(y) over the rows
  double density_rms_deviation = 0.0;      // rms over rows of ρ(y)/ρ̄ − 1
  double densest_band_mass_fraction = 0.0; // largest mass fraction in any band y ∈ [y₀, y₀ + w) (periodic)
  double velocity_profile_deviation = 0.0; // rms over occupied rows of V_x(y) − U (y − L_y/2)/L_y, in units of |U| (absolute if U = 0)
  double largest_cluster_mass_fraction = 0.0;
};

// The classifying scalars, named as the time-series columns, in one list.
template <typename Classification, typename Visit>
void for_each_flow_measure(Classification& f, Visit&& visit) {
  visit("density_contrast", f.density_contrast);
  visit("density_rms_deviation", f.density_rms_deviation);
  visit("densest_band_mass_fraction", f.densest_band_mass_fraction);
  visit("velocity_profile_deviation", f.velocity_profile_deviation);
  visit("largest_cluster_mass_fraction", f.largest_cluster_mass_fraction);
}

// The largest mass fraction found in a band of width w = `band_width` in y, over every position
// of the band (the box is periodic in y, also under Lees–Edwards): exact, by sorting the y's.
double densest_band_mass_fraction(const std::vector<double>& y, double length_y, double band_width);

// Cluster label of each disk (the smallest id in its cluster): disks i, j are connected when the
// distance between i and the nearest image of j is below `contact_distance`.  Images across the
// top and bottom are shifted by the Lees–Edwards offset Δ = `shear_offset` (thesis §1.4.2).  O(N)
// with a cell list and union–find.
std::vector<std::int32_t> cluster_labels(const ParticleState& state, double length_x, double length_y,
                                         double shear_offset, double contact_distance);
// The mass fraction of the largest cluster (unit mass: its share of the disks).
double largest_cluster_mass_fraction(const std::vector<std::int32_t>& labels);

// All of the above for a configuration; `frame` carries U at the configuration's time.  Of the
// state it keeps only the positions (16 bytes per disk: the clusters need them all at once).
FlowClassification classify_flow(const StateBlocks& state, const ShearFrame& frame, double shear_offset, double diameter,
                                 const FlowClassificationSettings& settings);

}  // namespace granule
