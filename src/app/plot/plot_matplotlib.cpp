// `granule plot fields | timeseries | profiles | phase | collisions | spectra | f1 | spins`: line plots and shaded
// maps drawn by the matplotlib scripts of python/granule_plots (run with Debian's /usr/bin/python3);
// `fields` of a 3D run draws density isosurfaces instead (fields3d.py).
#include <fmt/format.h>

#include <algorithm>
#include <memory>

#include "app/plot/plot_command.hpp"
#include "io/run_files.hpp"
#include "io/timeseries_csv.hpp"
#include "render/figure_scripts.hpp"

namespace granule::app {

namespace {

// The figure as asked on the command line (its input the run directory or file given), and the
// options given.
struct ScriptArguments {
  render::FigureRequest figure;
  std::string window;
  std::vector<std::string> given;
};

constexpr const char* kIsosurfaceOptions[] = {"--level", "--color-by", "--view", "--size"};

bool was_given(const ScriptArguments& a, const char* option) {
  return std::find(a.given.begin(), a.given.end(), option) != a.given.end();
}

// One matplotlib kind: its script, the run file it reads and its default output name.
struct ScriptKind {
  const char* name;
  const char* script;
  const char* input_file;
  const char* output_file;
  const char* description;
  bool has_frames;    // the input holds several frames (--frame)
  bool writes_data;   // the script can also write the numbers drawn (--data FILE.json)
  const char* window_help = nullptr;  // --window chooses a part of the file (nullptr: no such option)
  const char* window_default = nullptr;
};

int plot_with_script(const ScriptKind& kind, const ScriptArguments& a) {
  render::FigureRequest r = a.figure;
  if (r.dpi < 20 || r.dpi > 600) throw InputError(fmt::format("--dpi {} is outside [20, 600]", r.dpi));
  r.input = locate_run_file(a.figure.input, kind.input_file);
  if (r.out.empty()) r.out = output_beside(a.figure.input, kind.output_file);
  if (kind.window_help != nullptr) r.window = a.window;
  int status = 0;
  if (std::string_view(kind.name) == "fields" && hdf5_dimension(r.input) == 3) {
    // The density isosurface coloured by V_x (Figs C.1–C.3).
    if (r.quantities.size() > 1) throw InputError("--quantities of a 3D run takes one field: the one whose isosurface is drawn");
    status = render::draw_isosurface(r, was_given(a, "--colormap"));
  } else {
    for (const char* option : kIsosurfaceOptions) {
      if (was_given(a, option)) throw InputError(fmt::format("{} is for 3D runs only", option));
    }
    // The script meets only a file the reading layer accepted (draw_figure opens HDF5 inputs
    // through it; the CSV is read here).
    if (std::string_view(kind.name) == "timeseries") read_timeseries(r.input);
    status = render::draw_figure(kind.script, r);
  }
  if (status == 0) fmt::print("wrote {}\n", r.out);
  return status;
}

constexpr ScriptKind kKinds[] = {
    {"fields", "fields", "fields.h5", "fields.png",
     "Shaded maps of density, temperature, kinetic and collisional pressure from fields.h5 "
     "(thesis Figs 2.4, 2.12-2.18, 3.5-3.14); a 3D run: density isosurfaces coloured by V_x (Figs C.1-C.3)", true, false},
    {"timeseries", "timeseries", "timeseries.csv", "timeseries.png",
     "Global diagnostics against c and t from timeseries.csv (thesis Figs 2.5-2.7, 3.6)", false, false},
    {"profiles", "profiles", "fields.h5", "profiles.png",
     "Streamwise-averaged profiles V_x, V_y, density, T against y from fields.h5 (thesis Figs 3.15-3.16)", true, false},
    {"phase", "phase", "snapshots.h5", "phase.png",
     "Phase-space scatter plots of one snapshot: x, y against v_x, v_y (thesis Figs 2.1, 2.11, 2.13)", true, false},
    {"collisions", "collisions", "collisions.h5", "collisions.png",
     "Impact-parameter and free-path distributions from collisions.h5 with the fits (3.24), (3.36) "
     "(thesis Figs 2.16, 3.30-3.33)", false, true,
     "Free-path group: total, density_window_<i> or speed_window_<i>", "total"},
    {"spectra", "spectra", "spectra.h5", "spectra.png",
     "Annulus spectra R(k), P(k), power maps R, P_x, P_y and the dominant length from the spectra.h5 of "
     "`granule analyze spectra` (thesis Figs 2.8-2.10, 3.21-3.27)", true, true},
    {"f1", "f1", "f1.h5", "f1.png",
     "The velocity distribution of `granule analyze f1`: h, phi, J, psi with their fits, b(theta), f*, f** and "
     "the Jenkins-Richman form, and the per-window means, phases, stresses and ratio (thesis Figs 5.1-5.11)",
     false, true, "Window of the f1 file drawn in the upper rows: its index K (negative counts from the end)", "0"},
    {"spins", "spins", "spins.h5", "spins.png",
     "The spin correlation C(r) of neighbouring rough grains from the spins.h5 of `granule analyze spins`, overall and "
     "for pairs along the flow and along the gradient, with C_contact (thesis Fig C.4)", false, true},
};

}  // namespace

void add_plot_matplotlib_commands(CLI::App& plot) {
  for (const ScriptKind& kind : kKinds) {
    auto a = std::make_shared<ScriptArguments>();
    CLI::App* c = plot.add_subcommand(kind.name, kind.description);
    c->add_option("input", a->figure.input, fmt::format("Run directory or {}", kind.input_file))->required();
    c->add_option("--out", a->figure.out, fmt::format("PNG file (default: {} beside the input)", kind.output_file));
    c->add_option("--dpi", a->figure.dpi, "Resolution, 20 … 600 dots per inch (the figure size in inches is fixed)")->capture_default_str();
    if (kind.has_frames) {
      c->add_option("--frame", a->figure.frame, "Frame index (negative counts from the end)")->capture_default_str();
    }
    if (std::string_view(kind.name) == "fields") {
      c->add_option("--group", a->figure.group, "average (over the interval ending at the frame) or instant")->capture_default_str();
      c->add_option("--quantities", a->figure.quantities,
                    "Maps to draw (default: density temperature pressure_kinetic pressure_collisional)");
      c->add_option("--colormap", a->figure.colormap, "matplotlib colormap (gray: lighter for higher, as the thesis; 3D: coolwarm)")
          ->capture_default_str();
      c->add_option("--level", a->figure.level, "3D runs: the isosurface at this multiple of the field's mean (default 1.5)");
      c->add_option("--smooth", a->figure.smooth,
                    "Gaussian smoothing, standard deviation in cells, 0 … 16 (default 0 for 2D maps, 1 for 3D isosurfaces)");
      c->add_option("--average-frames", a->figure.average_frames,
                    "Average this many frames ending at --frame (Lees-Edwards 2D maps: in the frame moving with the shear; "
                    "default 1)");
      c->add_option("--color-by", a->figure.color_by, "3D runs: the field colouring the surface (default velocity_x)");
      c->add_option("--view", a->figure.view, "3D runs: elevation and azimuth in degrees (default 22 -58)")->expected(2);
      c->add_option("--size", a->figure.size, "3D runs: picture WIDTH HEIGHT in pixels (default 1000 800)")->expected(2);
    }
    if (std::string_view(kind.name) == "phase") {
      c->add_option("--max-points", a->figure.max_points, "Draw at most this many disks (a random subset), ≥ 100")->capture_default_str();
    }
    if (kind.window_help != nullptr) {
      a->window = kind.window_default;
      c->add_option("--window", a->window, kind.window_help)->capture_default_str();
    }
    if (kind.writes_data) c->add_option("--data", a->figure.data, "Also write the numbers drawn to this JSON file");
    c->callback([a, &kind, c] {
      a->given = given_options(*c);
      finish_plot_command(kind.name, [&] { return plot_with_script(kind, *a); });
    });
  }
}

}  // namespace granule::app
