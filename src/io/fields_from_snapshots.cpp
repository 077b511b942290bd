#include "io/fields_from_snapshots.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "analysis/cell_fields.hpp"
#include "io/fields_file.hpp"

namespace granule {

FieldGrid fields_from_snapshots_grid(const SystemParams& s, const std::vector<int>& cells) {
  const bool three_dimensional = s.dimension == 3;
  FieldGrid grid = three_dimensional ? default_field_grid_3d(s.length_x, s.length_y, s.length_z, s.particles)
                                     : default_field_grid(s.length_x, s.length_y, s.particles);
  if (cells.empty()) return grid;
  if (cells.size() != (three_dimensional ? 3u : 2u) ||
      std::any_of(cells.begin(), cells.end(), [](int n) { return n < 1 || n > (1 << 14); })) {
    throw InputError(fmt::format("--cells expects {} with integers in [1, 16384]", three_dimensional ? "nx,ny,nz" : "nx,ny"));
  }
  grid.nx = cells[0];
  grid.ny = cells[1];
  if (three_dimensional) grid.nz = cells[2];
  return grid;
}

void write_fields_from_snapshots(const FieldsFromSnapshots& r) {
  const SystemParams& s = r.metadata.system;
  const FieldGrid& grid = r.grid;
  const ShearFrame frame{s.length_x, s.length_y, s.shear_velocity};
  FieldsWriter writer(r.out, grid, FieldsMetadata{s, r.metadata.boundary, r.subtract_shear, r.snapshots, r.version}, false);
  CellMoments running(grid, spin_inertia(s));
  double t_start = 0.0, c_start = 0.0;
  for (std::int64_t k = r.first; k <= r.last; ++k) {
    const SnapshotRead snapshot = read_snapshot(r.snapshots, k);
    const SnapshotFrame& f = snapshot.frame;
    if (k == r.first) {
      t_start = f.clock.time;
      c_start = f.collisions_per_particle;
    }
    CellMoments instant(grid, spin_inertia(s));
    instant.add(f.particles, frame, r.subtract_shear);
    running.add(f.particles, frame, r.subtract_shear);
    FieldsFrame out;
    out.t = f.clock.time;
    out.c = f.collisions_per_particle;
    out.t_start = t_start;
    out.c_start = c_start;
    out.configurations = running.configurations;
    out.shear_offset = f.shear_offset;
    out.shear_velocity = r.metadata.boundary == "lees-edwards" ? f.shear_velocity : 0.0;
    out.instant = fields_from_moments(instant, frame, f.shear_offset, r.subtract_shear);
    out.average = fields_from_moments(running, frame, f.shear_offset, r.subtract_shear);
    writer.append(out);
  }
  writer.finish();
}

}  // namespace granule
