#include "analysis/spacetime_profiles.hpp"

namespace granule {

void append_profiles(SpacetimeProfiles& out, const StreamwiseProfiles& row) {
  out.density.insert(out.density.end(), row.density.begin(), row.density.end());
  out.velocity_x.insert(out.velocity_x.end(), row.velocity_x.begin(), row.velocity_x.end());
  out.temperature.insert(out.temperature.end(), row.temperature.begin(), row.temperature.end());
  out.y = row.y;
}

StreamwiseProfiles row_profiles(const ParticleState& particles, const SystemParams& system, int rows,
                                const ShearFrame& frame, double shear_offset, bool relative) {
  // One cell per row, the full width (and depth, in 3D) of the box: the cell fields of §1.4.3 are
  // then the rows' own.
  const FieldGrid grid{1, rows, system.length_x, system.length_y, 1, system.length_z, system.dimension};
  CellMoments moments(grid);
  moments.add(particles, frame, relative);
  return streamwise_profiles(fields_from_moments(moments, frame, shear_offset, relative));
}

}  // namespace granule
