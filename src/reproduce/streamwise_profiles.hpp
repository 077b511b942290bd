// The streamwise profiles ρ(y), V_x(y), T(y) and the heat flux q_y(y) of a run's fields.h5
// (README.md, "fields.h5": /profiles/*), averaged over the frames of a window of c, and what the
// Chapter 4 claims read off them: where the densest band lies, how cold it is against the rest of
// the box, and whether the heat flows towards it (thesis §4.3, Figs 4.7–4.8).  Lengths in box
// units, ρ in disks per unit area, T = ½⟨v′²⟩ (1.3).
#pragma once

#include <string>
#include <vector>

namespace granule::reproduce {

struct StreamwiseProfiles {
  double length_y = 1.0;
  int frames = 0;  // frames averaged (0: none in the window, or no file)
  std::vector<double> y, density, velocity_x, temperature;
  std::vector<double> heat_flux_y;  // interval-averaged total q_y; empty when the run observed no collisions
};

// The mean of the profiles of the fields frames with c in [c_from, c_to] of `fields_path`; frames = 0
// when the file is missing or no frame lies in the window.
StreamwiseProfiles read_streamwise_profiles(const std::string& fields_path, double c_from, double c_to);

// The densest band of `band_rows` consecutive rows (periodic in y, as the box is under
// Lees–Edwards), and what it says about a plug.
struct DensestBand {
  double centre = 0.0;             // y of the band's centre
  double distance_from_middle = 0.0;  // |centre − L_y/2|: 0 for a central plug, L_y/2 at the boundary
  double temperature_ratio = 0.0;  // mass-weighted T inside over outside the band
  // The share of the rows outside the band whose q_y points to the band along the shorter way
  // (NaN without heat-flux profiles).
  double flux_towards_band = 0.0;
};
DensestBand densest_band(const StreamwiseProfiles& p, int band_rows);

// The number of dense layers: runs of consecutive rows (periodic in y) whose density exceeds
// `threshold` times the mean; 0 without profiles.
int dense_layers(const StreamwiseProfiles& p, double threshold);

}  // namespace granule::reproduce
