// The numbers of a space–time picture (`granule plot spacetime`): the streamwise profiles ρ(y),
// V_x(y), T(y) of every frame of a run, side by side in time, as the thesis reads the layers that
// converge into a central plug (Figs 4.7–4.8, §4.3), and the image velocity U(t) of the shear
// protocol when it is known.  Lengths in box units, unit mass, t the run's time.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "analysis/cell_fields.hpp"
#include "boundary/shear_frame.hpp"
#include "engine/system_params.hpp"

namespace granule {

struct SpacetimeProfiles {
  // Where the rows come from: "fields/instant" or "fields/average" (streamwise averages of the
  // maps of fields.h5), or "snapshots" (rows of the full box width binned from each snapshot).
  std::string source;
  std::vector<double> t, c;  // time and collisions per particle of each frame
  std::vector<double> y;     // row centres
  // (frames, rows), row-major: ρ(y) in disks per unit area; V_x(y) and T(y) (1.3), 0 in empty rows.
  std::vector<double> density, velocity_x, temperature;
  // The protocol, one entry per snapshot frame, empty when the snapshot file does not store U.
  std::vector<double> protocol_t, shear_velocity, shear_offset;
  // The system, from the input file.
  std::int64_t particles = 0;
  double diameter = 0.0, length_x = 1.0, length_y = 1.0, restitution = 1.0, nominal_shear_velocity = 0.0;
  std::string boundary;
  bool relative = false;  // V_x and T taken relative to u(y) = γ(t) (y − L_y/2)
};

// Appends one frame's profiles as the next row of the picture (the row centres are taken from it).
void append_profiles(SpacetimeProfiles& out, const StreamwiseProfiles& row);

// A configuration of `system` binned into `rows` rows of the full box width (and depth, in 3D):
// ρ = count / row area, V_x = mean v_x, T = ½⟨(v − V)²⟩ (1.3) of the row, with velocities relative
// to u(y) = γ (y − L_y/2) when `relative` (γ = U/L_y of `frame`, offset Δ = `shear_offset`).
StreamwiseProfiles row_profiles(const ParticleState& particles, const SystemParams& system, int rows,
                                const ShearFrame& frame, double shear_offset, bool relative);

}  // namespace granule
