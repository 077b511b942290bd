// `granule plot fields | timeseries | profiles | phase | collisions | spectra | f1`: line plots and shaded
// maps drawn by the matplotlib scripts of python/granule_plots (run with Debian's /usr/bin/python3);
// `fields` of a 3D run draws density isosurfaces instead (fields3d.py).
#include <fmt/format.h>

#include <algorithm>
#include <memory>
#include <utility>

#include "app/plot/plot_command.hpp"
#include "io/run_files.hpp"
#include "render/plot_scripts.hpp"

namespace granule::app {

namespace {

struct ScriptArguments {
  std::string input;
  std::string out;
  std::int64_t frame = -1;
  int dpi = 100;
  std::string group = "average";
  std::vector<std::string> quantities;
  std::string colormap = "gray";
  std::int64_t max_points = 200000;
  std::string window;
  std::string data;
  // `fields`: smoothing and frame averages (2D maps and 3D isosurfaces), passed on as given.
  std::string smooth, average_frames;
  // `fields` of a 3D run only (density isosurfaces, fields3d.py); passed on as given.
  std::string level, color_by;
  std::vector<std::string> view, size;
  std::vector<std::string> given;  // the options given on the command line
};

constexpr const char* kIsosurfaceOptions[] = {"--level", "--color-by", "--view", "--size"};

bool was_given(const ScriptArguments& a, const char* option) {
  return std::find(a.given.begin(), a.given.end(), option) != a.given.end();
}

// `granule plot fields` of a 3D fields.h5: the density isosurface coloured by V_x (Figs C.1–C.3).
int plot_isosurface(const ScriptArguments& a, const std::string& input, const std::string& out) {
  if (a.quantities.size() > 1) throw BadInput("--quantities of a 3D run takes one field: the one whose isosurface is drawn");
  std::vector<std::string> arguments{input, "--out", out, "--frame", std::to_string(a.frame), "--dpi", std::to_string(a.dpi),
                                     "--group", a.group};
  if (!a.quantities.empty()) arguments.insert(arguments.end(), {"--quantity", a.quantities[0]});
  if (was_given(a, "--colormap")) arguments.insert(arguments.end(), {"--colormap", a.colormap});
  const std::pair<const char*, const std::string*> single[] = {
      {"--level", &a.level}, {"--smooth", &a.smooth}, {"--average-frames", &a.average_frames}, {"--color-by", &a.color_by}};
  for (const auto& [option, value] : single) {
    if (!value->empty()) arguments.insert(arguments.end(), {option, *value});
  }
  for (const auto& [option, values] : {std::pair{"--view", &a.view}, std::pair{"--size", &a.size}}) {
    if (values->empty()) continue;
    arguments.emplace_back(option);
    arguments.insert(arguments.end(), values->begin(), values->end());
  }
  const int status = render::run_plot_script("fields3d", arguments);
  if (status == 0) fmt::print("wrote {}\n", out);
  return status;
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
  if (a.dpi < 20 || a.dpi > 600) throw BadInput(fmt::format("--dpi {} is outside [20, 600]", a.dpi));
  const std::string input = locate_run_file(a.input, kind.input_file);
  const std::string out = a.out.empty() ? output_beside(a.input, kind.output_file) : a.out;
  if (std::string_view(kind.name) == "fields") {
    if (hdf5_dimension(input) == 3) return plot_isosurface(a, input, out);
    for (const char* option : kIsosurfaceOptions) {
      if (was_given(a, option)) throw BadInput(fmt::format("{} is for 3D runs only", option));
    }
  }
  std::vector<std::string> arguments{input, "--out", out, "--frame", std::to_string(a.frame), "--dpi", std::to_string(a.dpi)};
  if (std::string_view(kind.name) == "fields") {
    arguments.insert(arguments.end(), {"--group", a.group, "--colormap", a.colormap});
    for (const auto& [option, value] : {std::pair{"--smooth", &a.smooth}, std::pair{"--average-frames", &a.average_frames}}) {
      if (!value->empty()) arguments.insert(arguments.end(), {option, *value});
    }
    if (!a.quantities.empty()) {
      arguments.emplace_back("--quantities");
      arguments.insert(arguments.end(), a.quantities.begin(), a.quantities.end());
    }
  }
  if (std::string_view(kind.name) == "phase") arguments.insert(arguments.end(), {"--max-points", std::to_string(a.max_points)});
  if (kind.window_help != nullptr) arguments.insert(arguments.end(), {"--window", a.window});
  if (!a.data.empty()) arguments.insert(arguments.end(), {"--data", a.data});
  const int status = render::run_plot_script(kind.script, arguments);
  if (status == 0) fmt::print("wrote {}\n", out);
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
};

}  // namespace

void add_plot_matplotlib_commands(CLI::App& plot) {
  for (const ScriptKind& kind : kKinds) {
    auto a = std::make_shared<ScriptArguments>();
    CLI::App* c = plot.add_subcommand(kind.name, kind.description);
    c->add_option("input", a->input, fmt::format("Run directory or {}", kind.input_file))->required();
    c->add_option("--out", a->out, fmt::format("PNG file (default: {} beside the input)", kind.output_file));
    c->add_option("--dpi", a->dpi, "Resolution, 20 … 600 dots per inch (the figure size in inches is fixed)")->capture_default_str();
    if (kind.has_frames) {
      c->add_option("--frame", a->frame, "Frame index (negative counts from the end)")->capture_default_str();
    }
    if (std::string_view(kind.name) == "fields") {
      c->add_option("--group", a->group, "average (over the interval ending at the frame) or instant")->capture_default_str();
      c->add_option("--quantities", a->quantities,
                    "Maps to draw (default: density temperature pressure_kinetic pressure_collisional)");
      c->add_option("--colormap", a->colormap, "matplotlib colormap (gray: lighter for higher, as the thesis; 3D: coolwarm)")
          ->capture_default_str();
      c->add_option("--level", a->level, "3D runs: the isosurface at this multiple of the field's mean (default 1.5)");
      c->add_option("--smooth", a->smooth,
                    "Gaussian smoothing, standard deviation in cells, 0 … 16 (default 0 for 2D maps, 1 for 3D isosurfaces)");
      c->add_option("--average-frames", a->average_frames,
                    "Average this many frames ending at --frame (Lees-Edwards 2D maps: in the frame moving with the shear; "
                    "default 1)");
      c->add_option("--color-by", a->color_by, "3D runs: the field colouring the surface (default velocity_x)");
      c->add_option("--view", a->view, "3D runs: elevation and azimuth in degrees (default 22 -58)")->expected(2);
      c->add_option("--size", a->size, "3D runs: picture WIDTH HEIGHT in pixels (default 1000 800)")->expected(2);
    }
    if (std::string_view(kind.name) == "phase") {
      c->add_option("--max-points", a->max_points, "Draw at most this many disks (a random subset), ≥ 100")->capture_default_str();
    }
    if (kind.window_help != nullptr) {
      a->window = kind.window_default;
      c->add_option("--window", a->window, kind.window_help)->capture_default_str();
    }
    if (kind.writes_data) c->add_option("--data", a->data, "Also write the numbers drawn to this JSON file");
    c->callback([a, &kind, c] {
      a->given = given_options(*c);
      finish_plot_command(kind.name, [&] { return plot_with_script(kind, *a); });
    });
  }
}

}  // namespace granule::app
