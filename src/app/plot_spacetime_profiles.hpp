// The numbers of a space–time picture (`granule plot spacetime`): the streamwise profiles ρ(y),
// V_x(y), T(y) of every frame of a run, side by side in time, as the thesis reads the layers that
// converge into a central plug (Figs 4.7–4.8, §4.3), and the image velocity U(t) of the shear
// protocol when the snapshot file stores it.  Lengths in box units, unit mass, t the run's time.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace granule::app {

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

// Streamwise averages of the `group` ("instant" or "average") maps of every complete frame of a
// fields file: ρ the row mean, V_x and T mass-weighted (the profiles of fields.h5, Figs 3.15–3.16).
SpacetimeProfiles spacetime_from_fields(const std::string& fields_path, const std::string& group);

// Each snapshot frame binned into `rows` rows of the full box width: ρ = count / row area,
// V_x = mean v_x, T = ½⟨(v − V)²⟩ (1.3) of the row, with velocities relative to
// u(y) = γ (y − L_y/2) when `relative` (γ = U(t)/L_y of the frame when the file stores U(t)).
SpacetimeProfiles spacetime_from_snapshots(const std::string& snapshots_path, int rows, bool relative);

// Fills the protocol series from a snapshot file's per-frame `shear_velocity` and `shear_offset`
// (left empty when the file has no `shear_velocity`).
void read_shear_protocol(const std::string& snapshots_path, SpacetimeProfiles& profiles);

// Writes the arrays as HDF5 (format `granule-spacetime`, schema in docs/plots.md) to
// `<path>.partial`, closed; the caller publishes or removes it.  Throws IoError.
void write_spacetime_partial(const std::string& path, const SpacetimeProfiles& profiles);

}  // namespace granule::app
