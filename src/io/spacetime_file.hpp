// The space–time profiles of a run (analysis/spacetime_profiles.hpp) read from its fields or
// snapshot file, and written in their own format (`granule-spacetime`, schema in docs/plots.md)
// for the pictures of `granule plot spacetime`.
#pragma once

#include <optional>
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

// The file a run's profiles come from (a run directory, a fields file or a snapshot file): `from`
// "fields" (fields.h5) or "snapshots" (snapshots.h5), or empty: fields.h5 when the run has one.
// Throws InputError for another `from`, a missing file or a file of another format.
struct SpacetimeSource {
  std::string from;  // "fields" or "snapshots"
  std::string path;
};
SpacetimeSource spacetime_source(const std::string& run_dir_or_file, const std::string& from);

// The profiles of every complete frame of the source: the `group` maps of a fields file, with U(t)
// from the snapshots beside it, or the snapshots binned into `rows` rows (default: the rows of the
// default coarse-graining grid).  Throws InputError when no frame is complete yet.
SpacetimeProfiles read_spacetime_profiles(const SpacetimeSource& source, const std::string& group,
                                          std::optional<int> rows, bool relative);

// Writes the arrays as HDF5 (format `granule-spacetime`, schema in docs/plots.md) to
// `<path>.partial`, closed; the caller publishes or removes it.  Throws IoError.
void write_spacetime_partial(const std::string& path, const SpacetimeProfiles& profiles);

}  // namespace granule
