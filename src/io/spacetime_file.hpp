// The space–time profiles of a run (analysis/spacetime_profiles.hpp) read from its fields or
// snapshot file, and written in their own format (`granule-spacetime`, schema in docs/plots.md)
// for the pictures of `granule plot spacetime`.
#pragma once

#include <string>

#include "analysis/spacetime_profiles.hpp"

namespace granule {

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

}  // namespace granule
