// `granule plot export`: particles as extended XYZ or HOOMD's GSD (OVITO) or VTK PolyData
// (ParaView), and coarse-grained fields as VTK ImageData, one frame or all frames (multi-frame
// XYZ and GSD, .pvd series).  GSD is written by python/granule_plots/export_gsd.py with python3-gsd.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <filesystem>
#include <memory>

#include "app/plot/plot_command.hpp"
#include "app/plot/plot_inputs.hpp"
#include "io/export_field_source.hpp"
#include "io/export_series.hpp"
#include "io/export_vtk.hpp"
#include "io/snapshot_file.hpp"
#include "render/configuration_picture.hpp"

namespace granule::app {

namespace {

namespace fs = std::filesystem;

struct ExportArguments {
  std::string input;
  std::string format;
  std::string what = "particles";
  std::int64_t frame = -1;
  bool all_frames = false;
  std::string out;
  std::vector<int> cells;
  bool relative = false;
};

// The frames to export, resolved to indices ≥ 0.
std::vector<std::int64_t> chosen_frames(const ExportArguments& a, std::int64_t frames) {
  if (!a.all_frames) return {resolve_frame(a.frame, frames)};
  std::vector<std::int64_t> all(static_cast<std::size_t>(frames));
  for (std::int64_t k = 0; k < frames; ++k) all[static_cast<std::size_t>(k)] = k;
  return all;
}

void print_written(const std::string& path) { fmt::print("wrote {}\n", path); }

// Returns the exit code (that of the GSD writer for --format gsd).
int export_particles(const ExportArguments& a, const std::string& snapshots) {
  const std::vector<std::int64_t> frames = chosen_frames(a, read_snapshot(snapshots, 0).frames);
  const bool xyz = a.format == "xyz";
  const bool gsd = a.format == "gsd";
  const std::string single_extension = xyz ? "xyz" : gsd ? "gsd" : "vtp";
  const std::string default_name = frames.size() > 1 ? (xyz || gsd ? "particles." + single_extension : "particles.pvd")
                                                     : fmt::format("particles_{}.{}", frames[0], single_extension);
  const fs::path out = a.out.empty() ? output_beside(a.input, default_name) : a.out;
  if (gsd) {
    return run_plot_script("export_gsd",
                           {snapshots, "--out", out.string(), "--frames", fmt::format("{}", fmt::join(frames, ","))});
  }
  if (xyz) {
    export_xyz_frames(snapshots, frames, out.string());
    fmt::print("wrote {} ({} frames)\n", out.string(), frames.size());
    return 0;
  }
  export_vtp_frames(snapshots, frames, out, print_written);
  return 0;
}

// The grid of fields computed from snapshots: --cells NX NY (NZ in 3D), or ~40 disks a cell in 2D
// (as the pictures) and ~20 spheres a cell in 3D.
FieldGrid snapshot_field_grid(const SystemParams& p, const std::vector<int>& cells) {
  if (p.dimension == 3) {
    if (cells.empty()) return default_field_grid_3d(p.length_x, p.length_y, p.length_z, p.particles);
    if (cells.size() != 3) throw BadPlotInput("--cells of a 3D run needs three integers NX NY NZ");
    return {cells[0], cells[1], p.length_x, p.length_y, cells[2], p.length_z, 3};
  }
  if (cells.size() == 3) throw BadPlotInput("--cells of a 2D run needs two integers NX NY");
  return cells.empty() ? render::automatic_picture_grid(p.particles, p.length_x, p.length_y)
                       : FieldGrid{cells[0], cells[1], p.length_x, p.length_y};
}

// Instantaneous cell fields of §1.4.3 computed from the snapshots themselves.
void export_snapshot_fields(const ExportArguments& a, const std::string& snapshots, const fs::path& out,
                            const std::vector<std::int64_t>& frames) {
  write_vtk_series(out, frames, "vti", [&](std::int64_t k, const std::string& path) {
    const SnapshotRead s = read_snapshot(snapshots, k);
    const SystemParams& p = s.metadata.system;
    const ShearFrame box{p.length_x, p.length_y, s.metadata.boundary == "lees-edwards" ? p.shear_velocity : 0.0};
    const FieldGrid grid = snapshot_field_grid(p, a.cells);
    CellMoments moments(grid, spin_inertia(p));
    moments.add(s.frame.particles, box, a.relative);
    const CellFields fields = fields_from_moments(moments, box, s.frame.shear_offset, a.relative);
    std::vector<NamedCellArray> arrays;
    if (grid.dimension == 3) {  // every field, named as in fields.h5
      for_each_field(fields, [&](const char* name, const std::vector<double>& v) { arrays.push_back({std::string("instant_") + name, v}); });
    } else {
      for (const std::string& name : render::cell_field_names()) {
        arrays.push_back({"instant_" + name, *render::cell_field_by_name(fields, name)});
      }
    }
    write_vti_fields(path, grid, arrays, s.frame.clock.time);
    return s.frame.clock.time;
  }, print_written);
}

void export_fields(const ExportArguments& a) {
  if (a.format != "vtk") throw BadPlotInput("--what fields needs --format vtk (extended XYZ and GSD hold particles only)");
  // A fields file (fields.h5) if the run has one, else fields computed from the snapshots.
  const bool from_fields_file = fs::is_directory(a.input) ? fs::exists(fs::path(a.input) / "fields.h5")
                                                          : !fs::path(a.input).filename().string().starts_with("snapshots");
  const std::string source = locate_run_file(a.input, from_fields_file ? "fields.h5" : "snapshots.h5");
  const std::int64_t available = from_fields_file ? read_field_file_frame(source, 0).frames : read_snapshot(source, 0).frames;
  const std::vector<std::int64_t> frames = chosen_frames(a, available);
  const std::string default_name = frames.size() > 1 ? "fields.pvd" : fmt::format("fields_{}.vti", frames[0]);
  const fs::path out = a.out.empty() ? output_beside(a.input, default_name) : a.out;
  if (!from_fields_file) {
    export_snapshot_fields(a, source, out, frames);
    return;
  }
  export_field_file_frames(source, frames, out, print_written);
}

int plot_export(const ExportArguments& a) {
  if (a.format != "xyz" && a.format != "vtk" && a.format != "gsd") {
    throw BadPlotInput(fmt::format("--format {} is not one of xyz, gsd, vtk", a.format));
  }
  if (a.what != "particles" && a.what != "fields") {
    throw BadPlotInput(fmt::format("--what {} is not one of particles, fields", a.what));
  }
  for (int n : a.cells) {
    if (n < 1 || n > 4096) throw BadPlotInput(fmt::format("--cells {} must be integers in [1, 4096]", fmt::join(a.cells, " ")));
  }
  if (a.what == "fields") {
    export_fields(a);
    return 0;
  }
  return export_particles(a, locate_run_file(a.input, "snapshots.h5"));
}

}  // namespace

void add_plot_export_command(CLI::App& plot) {
  auto a = std::make_shared<ExportArguments>();
  CLI::App* c = plot.add_subcommand(
      "export", "Export particles (extended XYZ or HOOMD GSD for OVITO, VTK .vtp for ParaView) or coarse-grained fields (VTK .vti)");
  c->add_option("input", a->input, "Run directory, snapshot file or fields file")->required();
  c->add_option("--format", a->format, "xyz or gsd (OVITO), or vtk (ParaView)")->required();
  c->add_option("--what", a->what, "particles, or fields (from fields.h5 if present, else computed from the snapshots)")
      ->capture_default_str();
  c->add_option("--frame", a->frame, "Frame index (negative counts from the end)")->capture_default_str();
  c->add_flag("--all-frames", a->all_frames, "Every frame: one multi-frame .xyz or .gsd, or one VTK file per frame and a .pvd series");
  c->add_option("--out", a->out, "Output file (default: particles_<k>.xyz/.gsd/.vtp, particles.xyz/.gsd/.pvd, fields_<k>.vti or fields.pvd beside the input)");
  c->add_option("--cells", a->cells,
                "Coarse-graining grid NX NY (3D: NX NY NZ) of fields computed from snapshots (default: ~40 disks, ~20 spheres a cell)")
      ->expected(2, 3);
  c->add_flag("--relative", a->relative, "Lees–Edwards fields from snapshots: velocities relative to the mean shear flow");
  c->callback([a] { finish_plot_command("export", [&] { return plot_export(*a); }); });
}

}  // namespace granule::app
