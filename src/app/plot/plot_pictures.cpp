// `granule plot config` (one configuration picture, thesis Figs 2.2, 2.3, 3.4, 3.10) and
// `granule plot movie` (one such picture per snapshot with its time, encoded as mp4 by ffmpeg).
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <memory>

#include "app/plot/plot_command.hpp"
#include "io/run_files.hpp"
#include "render/config3d_picture.hpp"
#include "render/snapshot_movie.hpp"
#include "render/snapshot_picture.hpp"

namespace granule::app {

namespace {

struct PictureArguments {
  std::string input;
  std::string out;
  std::int64_t frame = -1;
  int width = 1000;
  std::string color = "direction";
  std::string field = "density";
  std::vector<int> cells;
  bool no_arrows = false;
  bool relative = false;
  bool no_legend = false;
  double min_radius = 0.6;
  std::vector<double> view;  // 3D only: elevation, azimuth
  bool perspective = false;  // 3D only
  std::vector<std::string> given;  // the options given on the command line
};

// Options that exist for one dimension only, refused for the other.
constexpr const char* kOptions2dOnly[] = {"--field", "--cells", "--no-arrows", "--relative", "--min-radius"};
constexpr const char* kOptions3dOnly[] = {"--view", "--perspective"};

bool was_given(const PictureArguments& a, const char* option) {
  return std::find(a.given.begin(), a.given.end(), option) != a.given.end();
}

template <std::size_t N>
void refuse_given(const PictureArguments& a, const char* const (&options)[N], const char* which) {
  for (const char* option : options) {
    if (was_given(a, option)) {
      throw InputError(fmt::format("{} is for {} runs only", option, which));
    }
  }
}

// The sphere picture of a 3D run (config3d.py): --color direction (the 2D default) becomes auto.
int plot_config_3d(const PictureArguments& a, const std::string& snapshots) {
  refuse_given(a, kOptions2dOnly, "2D");
  if (was_given(a, "--color") && (a.color == "direction" || a.color == "field" || a.color == "spin")) {
    throw InputError(fmt::format("--color {} is for 2D runs; a 3D picture takes velocity_x, speed or none", a.color));
  }
  const std::string out = a.out.empty() ? output_beside(a.input, "configuration.png") : a.out;
  const int status = render::draw_config_3d(
      {snapshots, out, a.frame, a.width, was_given(a, "--color") ? a.color : "auto", a.view, a.perspective, !a.no_legend});
  if (status == 0) fmt::print("wrote {}\n", out);
  return status;
}

void add_picture_options(CLI::App* command, PictureArguments& a) {
  command->add_option("input", a.input, "Run directory or snapshot file (snapshots.h5)")->required();
  command->add_option("--width", a.width, "Picture width in pixels, 16 … 20000 (the height follows the box)")
      ->capture_default_str();
  command->add_option("--color", a.color,
                      "Disk colours: direction (hue wheel, thesis Fig 1.1), speed, field (a cell field), spin (ω_z on a "
                      "scale centred on 0, thesis Fig C.4; the default for rough grains), none")
      ->capture_default_str();
  command->add_option("--field", a.field,
                      "Cell field for --color field: density, temperature, velocity_x, velocity_y, kinetic_xx, "
                      "kinetic_xy, kinetic_yy, pressure_kinetic, vorticity, count")
      ->capture_default_str();
  command->add_option("--cells", a.cells, "Coarse-graining grid NX NY of the arrows and field colours (default: ~40 disks a cell)")
      ->expected(2);
  command->add_flag("--no-arrows", a.no_arrows, "Do not draw the coarse-grained velocity field");
  command->add_flag("--relative", a.relative, "Lees–Edwards: velocities relative to the mean shear flow u(y) = γ (y − L_y/2)");
  command->add_flag("--no-legend", a.no_legend, "Do not draw the colour wheel / colour bar");
  command->add_option("--min-radius", a.min_radius, "Smallest disk radius drawn, in pixels, 0 … 10")->capture_default_str();
}

render::PictureOptions picture_options(const PictureArguments& a) {
  render::PictureOptions o;
  if (a.width < 16 || a.width > 20000) throw InputError(fmt::format("--width {} is outside [16, 20000]", a.width));
  const auto coloring = render::parse_disk_coloring(a.color);
  if (!coloring) throw InputError(fmt::format("--color {} is not one of direction, speed, field, spin, none", a.color));
  const auto& names = cell_field_names();
  if (std::find(names.begin(), names.end(), a.field) == names.end()) {
    throw InputError(fmt::format("--field {} is not one of {}", a.field, fmt::join(names, ", ")));
  }
  if (!a.cells.empty() && (a.cells[0] < 1 || a.cells[1] < 1 || a.cells[0] > 4096 || a.cells[1] > 4096)) {
    throw InputError(fmt::format("--cells {} {} must be two integers in [1, 4096]", a.cells[0], a.cells[1]));
  }
  if (!(a.min_radius >= 0.0 && a.min_radius <= 10.0)) throw InputError(fmt::format("--min-radius {} is outside [0, 10]", a.min_radius));
  o.width_px = a.width;
  o.coloring = *coloring;
  o.field = a.field;
  if (!a.cells.empty()) {
    o.cells_x = a.cells[0];
    o.cells_y = a.cells[1];
  }
  o.arrows = !a.no_arrows;
  o.subtract_shear_profile = a.relative;
  o.legend = !a.no_legend;
  o.min_disk_radius_px = a.min_radius;
  return o;
}

int plot_config(const PictureArguments& a) {
  const std::string snapshots = locate_run_file(a.input, "snapshots.h5");
  require_hdf5_format(snapshots, "granule-snapshots", "`granule run`");
  if (hdf5_dimension(snapshots) == 3) return plot_config_3d(a, snapshots);
  refuse_given(a, kOptions3dOnly, "3D");
  const render::PictureOptions options = picture_options(a);
  const std::string out = a.out.empty() ? output_beside(a.input, "configuration.png") : a.out;
  const std::int64_t frame = render::write_snapshot_picture(snapshots, a.frame, options, was_given(a, "--color"), out);
  fmt::print("wrote {} (frame {})\n", out, frame);
  return 0;
}

struct MovieArguments {
  PictureArguments picture;
  double fps = 10.0;
  std::int64_t stride = 1;
  bool no_caption = false;
};

int plot_movie(const MovieArguments& m) {
  const render::PictureOptions options = picture_options(m.picture);
  if (!(m.fps >= 0.1 && m.fps <= 120.0)) throw InputError(fmt::format("--fps {} is outside [0.1, 120]", m.fps));
  if (m.stride < 1) throw InputError(fmt::format("--stride {} must be at least 1", m.stride));
  const std::string snapshots = locate_run_file(m.picture.input, "snapshots.h5");
  require_hdf5_format(snapshots, "granule-snapshots", "`granule run`");
  if (hdf5_dimension(snapshots) == 3) throw InputError("plot movie draws 2D runs only (a 3D run: plot config --frame K per frame)");
  refuse_given(m.picture, kOptions3dOnly, "3D");
  const std::string out = m.picture.out.empty() ? output_beside(m.picture.input, "movie.mp4") : m.picture.out;
  const render::MovieWritten movie =
      render::write_snapshot_movie(snapshots, options, was_given(m.picture, "--color"), {m.fps, m.stride, !m.no_caption}, out);
  fmt::print("wrote {} ({} of {} snapshots at {} per second)\n", out, movie.drawn, movie.frames, m.fps);
  return 0;
}

}  // namespace

void add_plot_picture_commands(CLI::App& plot) {
  auto config = std::make_shared<PictureArguments>();
  CLI::App* c = plot.add_subcommand(
      "config", "Particle configuration, disks to scale, coloured by velocity direction, speed or a cell field, with the "
                "coarse-grained velocity field as arrows (thesis Figs 2.2, 2.3, 3.4, 3.10); a 3D run: spheres as shaded "
                "disks coloured by v_x or the speed (Appendix C)");
  add_picture_options(c, *config);
  c->add_option("--frame", config->frame, "Snapshot index (negative counts from the end)")->capture_default_str();
  c->add_option("--out", config->out, "PNG file (default: configuration.png beside the input)");
  c->add_option("--view", config->view, "3D runs: elevation and azimuth of the view in degrees (default 22 -58)")->expected(2);
  c->add_flag("--perspective", config->perspective, "3D runs: perspective instead of orthographic projection");
  c->callback([config, c] {
    config->given = given_options(*c);
    finish_plot_command("config", [&] { return plot_config(*config); });
  });

  auto movie = std::make_shared<MovieArguments>();
  movie->picture.width = 800;
  CLI::App* m = plot.add_subcommand(
      "movie", "An mp4 movie of a run, one configuration picture per snapshot with its t and c (needs ffmpeg)");
  add_picture_options(m, movie->picture);
  m->add_option("--fps", movie->fps, "Frames per second, 0.1 … 120")->capture_default_str();
  m->add_option("--stride", movie->stride, "Draw every S-th snapshot (0, S, 2S, …)")->capture_default_str();
  m->add_flag("--no-caption", movie->no_caption, "Do not print t, c (and U) in the top-left corner of each frame");
  m->add_option("--out", movie->picture.out, "mp4 file (default: movie.mp4 beside the input)");
  m->callback([movie, m] {
    movie->picture.given = given_options(*m);
    finish_plot_command("movie", [&] { return plot_movie(*movie); });
  });
}

}  // namespace granule::app
