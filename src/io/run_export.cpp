#include "io/run_export.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <sstream>

#include "analysis/cell_fields.hpp"
#include "analysis/named_cell_fields.hpp"
#include "io/export_field_source.hpp"
#include "io/atomic_file.hpp"
#include "io/export_vtk.hpp"
#include "io/export_xyz.hpp"
#include "io/frame_selection.hpp"
#include "io/run_files.hpp"
#include "io/snapshot_file.hpp"

namespace granule {

namespace {

namespace fs = std::filesystem;

// The grid of fields computed from snapshots: `cells` NX NY (NZ in 3D), or ~40 disks a cell in 2D
// (as the pictures) and ~20 spheres a cell in 3D.
FieldGrid snapshot_field_grid(const SystemParams& p, const std::vector<int>& cells) {
  if (p.dimension == 3) {
    if (cells.empty()) return default_field_grid_3d(p.length_x, p.length_y, p.length_z, p.particles);
    if (cells.size() != 3) throw InputError("--cells of a 3D run needs three integers NX NY NZ");
    return {cells[0], cells[1], p.length_x, p.length_y, cells[2], p.length_z, 3};
  }
  if (cells.size() == 3) throw InputError("--cells of a 2D run needs two integers NX NY");
  return cells.empty() ? automatic_picture_grid(p.particles, p.length_x, p.length_y)
                       : FieldGrid{cells[0], cells[1], p.length_x, p.length_y};
}

// Instantaneous cell fields of §1.4.3 computed from the snapshots themselves.
void export_snapshot_fields(const ExportRequest& r, const std::string& snapshots, const fs::path& out,
                            const std::vector<std::int64_t>& frames, const ExportWritten& written) {
  write_vtk_series(out, frames, "vti", [&](std::int64_t k, const std::string& path) {
    const SnapshotRead s = read_snapshot(snapshots, k);
    const SystemParams& p = s.metadata.system;
    const ShearFrame box{p.length_x, p.length_y, s.metadata.boundary == "lees-edwards" ? p.shear_velocity : 0.0};
    const FieldGrid grid = snapshot_field_grid(p, r.cells);
    CellMoments moments(grid, spin_inertia(p));
    moments.add(s.frame.particles, box, r.relative);
    const CellFields fields = fields_from_moments(moments, box, s.frame.shear_offset, r.relative);
    std::vector<NamedCellArray> arrays;
    if (grid.dimension == 3) {  // every field, named as in fields.h5
      for_each_field(fields, [&](const char* name, const std::vector<double>& v) { arrays.push_back({std::string("instant_") + name, v}); });
    } else {
      for (const std::string& name : cell_field_names()) arrays.push_back({"instant_" + name, *cell_field_by_name(fields, name)});
    }
    write_vti_fields(path, grid, arrays, s.frame.clock.time);
    return s.frame.clock.time;
  }, written);
}

}  // namespace

ParticleExport plan_particle_export(const ExportRequest& r) {
  ParticleExport e;
  e.snapshots = locate_run_file(r.input, "snapshots.h5");
  e.frames = chosen_frames(r.all_frames, r.frame, read_snapshot(e.snapshots, 0).frames);
  const bool single_file = r.format == "xyz" || r.format == "gsd";
  const std::string extension = r.format == "vtk" ? "vtp" : r.format;
  const std::string default_name = e.frames.size() > 1 ? (single_file ? "particles." + extension : "particles.pvd")
                                                       : fmt::format("particles_{}.{}", e.frames[0], extension);
  e.out = r.out.empty() ? output_beside(r.input, default_name) : r.out;
  return e;
}

std::string export_obstacles(const ParticleExport& e, const std::string& format) {
  const SnapshotRead first = read_snapshot(e.snapshots, 0);
  const SystemParams& s = first.metadata.system;
  if (s.obstacles.empty() || (format != "vtk" && format != "xyz")) return {};
  ParticleState obstacles;
  obstacles.dimension = s.dimension;
  const std::size_t m = s.obstacles.size();
  obstacles.diameter.resize(m);
  obstacles.mass.assign(m, 1.0);
  obstacles.resize(m);
  for (std::size_t k = 0; k < m; ++k) {
    for (int a = 0; a < s.dimension; ++a) obstacles.position(a)[k] = s.obstacles[k].centre[static_cast<std::size_t>(a)];
    obstacles.diameter[k] = s.obstacles[k].diameter;
  }
  const std::string path = (fs::path(e.out).parent_path() / (format == "vtk" ? "obstacles.vtp" : "obstacles.xyz")).string();
  if (format == "vtk") {
    write_vtp_particles(path, obstacles, 0.0, 0.0);
  } else {
    std::ostringstream out;
    write_xyz_frame(out, obstacles, {0.0, s.length_x, s.length_y, 0.0, 0.0, first.metadata.boundary, 0.0, 0.0, s.length_z});
    write_file_atomically(path, out.str());
  }
  return path;
}

void export_fields(const ExportRequest& r, const ExportWritten& written) {
  const bool from_fields_file = fs::is_directory(r.input) ? fs::exists(fs::path(r.input) / "fields.h5")
                                                          : !fs::path(r.input).filename().string().starts_with("snapshots");
  const std::string source = locate_run_file(r.input, from_fields_file ? "fields.h5" : "snapshots.h5");
  const std::int64_t available = from_fields_file ? read_field_file_frame(source, 0).frames : read_snapshot(source, 0).frames;
  const std::vector<std::int64_t> frames = chosen_frames(r.all_frames, r.frame, available);
  const std::string default_name = frames.size() > 1 ? "fields.pvd" : fmt::format("fields_{}.vti", frames[0]);
  const fs::path out = r.out.empty() ? output_beside(r.input, default_name) : r.out;
  if (from_fields_file) {
    export_field_file_frames(source, frames, out, written);
  } else {
    export_snapshot_fields(r, source, out, frames, written);
  }
}

}  // namespace granule
