// `granule plot export`: particles as extended XYZ or HOOMD's GSD (OVITO) or VTK PolyData
// (ParaView), and coarse-grained fields as VTK ImageData, one frame or all frames (multi-frame
// XYZ and GSD, .pvd series).  GSD is written by python/granule_plots/export_gsd.py with python3-gsd.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <memory>

#include "app/plot/plot_command.hpp"
#include "io/io_error.hpp"
#include "io/run_export.hpp"
#include "render/plot_scripts.hpp"

namespace granule::app {

namespace {

void print_written(const std::string& path) { fmt::print("wrote {}\n", path); }

// Returns the exit code (that of the GSD writer for --format gsd).
int export_particles(const ExportRequest& r) {
  const ParticleExport e = plan_particle_export(r);
  if (const std::string obstacles = export_obstacles(e, r.format); !obstacles.empty()) print_written(obstacles);
  if (r.format == "gsd") {
    return render::run_plot_script("export_gsd", {e.snapshots, "--out", e.out, "--frames", fmt::format("{}", fmt::join(e.frames, ","))});
  }
  if (r.format == "xyz") {
    export_xyz_frames(e.snapshots, e.frames, e.out);
    fmt::print("wrote {} ({} frames)\n", e.out, e.frames.size());
    return 0;
  }
  export_vtp_frames(e.snapshots, e.frames, e.out, print_written);
  return 0;
}

int plot_export(const ExportRequest& r, const std::string& what) {
  if (r.format != "xyz" && r.format != "vtk" && r.format != "gsd") {
    throw InputError(fmt::format("--format {} is not one of xyz, gsd, vtk", r.format));
  }
  if (what != "particles" && what != "fields") throw InputError(fmt::format("--what {} is not one of particles, fields", what));
  for (int n : r.cells) {
    if (n < 1 || n > 4096) throw InputError(fmt::format("--cells {} must be integers in [1, 4096]", fmt::join(r.cells, " ")));
  }
  if (what == "particles") return export_particles(r);
  if (r.format != "vtk") throw InputError("--what fields needs --format vtk (extended XYZ and GSD hold particles only)");
  export_fields(r, print_written);
  return 0;
}

}  // namespace

void add_plot_export_command(CLI::App& plot) {
  auto a = std::make_shared<ExportRequest>();
  auto what = std::make_shared<std::string>("particles");
  CLI::App* c = plot.add_subcommand(
      "export", "Export particles (extended XYZ or HOOMD GSD for OVITO, VTK .vtp for ParaView) or coarse-grained fields (VTK .vti)");
  c->add_option("input", a->input, "Run directory, snapshot file or fields file")->required();
  c->add_option("--format", a->format, "xyz or gsd (OVITO), or vtk (ParaView)")->required();
  c->add_option("--what", *what, "particles, or fields (from fields.h5 if present, else computed from the snapshots)")
      ->capture_default_str();
  c->add_option("--frame", a->frame, "Frame index (negative counts from the end)")->capture_default_str();
  c->add_flag("--all-frames", a->all_frames, "Every frame: one multi-frame .xyz or .gsd, or one VTK file per frame and a .pvd series");
  c->add_option("--out", a->out, "Output file (default: particles_<k>.xyz/.gsd/.vtp, particles.xyz/.gsd/.pvd, fields_<k>.vti or fields.pvd beside the input)");
  c->add_option("--cells", a->cells,
                "Coarse-graining grid NX NY (3D: NX NY NZ) of fields computed from snapshots (default: ~40 disks, ~20 spheres a cell)")
      ->expected(2, 3);
  c->add_flag("--relative", a->relative, "Lees–Edwards fields from snapshots: velocities relative to the mean shear flow");
  c->callback([a, what] { finish_plot_command("export", [&] { return plot_export(*a, *what); }); });
}

}  // namespace granule::app
