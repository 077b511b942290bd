// `granule plot spacetime`: ρ(y, t), V_x(y, t), T(y, t) as three shaded panels, time across and y
// up (thesis Figs 4.7–4.8: dense streamwise layers converging into a central plug), with U(t)
// above when the snapshots store it.  The arrays are assembled by io/spacetime_file (the rows by
// analysis/spacetime_profiles), written as HDF5 beside the picture and drawn by
// render/spacetime_picture.
#include <fmt/format.h>

#include <filesystem>
#include <memory>
#include <optional>

#include "app/plot/plot_command.hpp"
#include "io/run_files.hpp"
#include "io/spacetime_file.hpp"
#include "render/spacetime_picture.hpp"

namespace granule::app {

namespace {

namespace fs = std::filesystem;

constexpr int kMaxRows = 16384;  // as `fields.cells`

struct SpacetimeArguments {
  std::string input;
  std::string from;  // "fields" or "snapshots"; empty: fields.h5 when there is one
  std::string group = "instant";
  std::optional<int> rows;  // default: the rows of the default coarse-graining grid
  bool relative = false;
  std::string out;
  std::string data;
  int dpi = 100;
};

int plot_spacetime(const SpacetimeArguments& a) {
  if (a.dpi < 20 || a.dpi > 600) throw InputError(fmt::format("--dpi {} is outside [20, 600]", a.dpi));
  if (a.group != "instant" && a.group != "average") {
    throw InputError(fmt::format("--group {} is not one of instant, average", a.group));
  }
  if (a.rows && (*a.rows < 1 || *a.rows > kMaxRows)) {
    throw InputError(fmt::format("--rows {} is outside [1, {}]", *a.rows, kMaxRows));
  }
  const SpacetimeSource source = spacetime_source(a.input, a.from);
  if (source.from == "fields" && (a.rows || a.relative)) {
    throw InputError("--rows and --relative apply to --from snapshots (fields.h5 has its own grid and frame)");
  }
  const SpacetimeProfiles profiles = read_spacetime_profiles(source, a.group, a.rows, a.relative);

  const std::string out = a.out.empty() ? output_beside(a.input, "spacetime.png") : a.out;
  const std::string data = a.data.empty() ? fs::path(out).replace_extension(".h5").string() : a.data;
  if (data == out) throw InputError(fmt::format("--data {} is the picture itself", data));
  if (const int status = render::draw_spacetime(profiles, out, data, a.dpi); status != 0) return status;
  fmt::print("wrote {} and {} ({} frames × {} rows, from {})\n", out, data, profiles.t.size(), profiles.y.size(),
             profiles.source);
  return 0;
}

}  // namespace

void add_plot_spacetime_command(CLI::App& plot) {
  auto a = std::make_shared<SpacetimeArguments>();
  CLI::App* c = plot.add_subcommand(
      "spacetime", "Space–time pictures of the streamwise profiles ρ(y, t), V_x(y, t), T(y, t), time across and y up, "
                   "with the image velocity U(t) above (thesis Figs 4.7-4.8); the arrays go to an HDF5 file beside it");
  c->add_option("input", a->input, "Run directory, fields.h5 or snapshots.h5")->required();
  c->add_option("--from", a->from,
                "fields (the profiles of fields.h5) or snapshots (rows binned from snapshots.h5); default: fields.h5 "
                "when the run has one");
  c->add_option("--group", a->group, "With fields: instant (the configuration at each frame) or average (the interval)")
      ->capture_default_str();
  c->add_option("--rows", a->rows,
                fmt::format("With snapshots: rows of the full box width, 1 … {} (default: the rows of the default "
                            "coarse-graining grid, ~20 disks a cell)", kMaxRows));
  c->add_flag("--relative", a->relative,
              "With snapshots: velocities relative to u(y) = γ(t) (y − L_y/2) before binning (Lees–Edwards)");
  c->add_option("--out", a->out, "PNG file (default: spacetime.png beside the input)");
  c->add_option("--data", a->data, "HDF5 file of the arrays drawn (default: the PNG's name with .h5)");
  c->add_option("--dpi", a->dpi, "Resolution, 20 … 600 dots per inch (the figure is 10 × 9 inches)")->capture_default_str();
  c->callback([a] { finish_plot_command("spacetime", [&] { return plot_spacetime(*a); }); });
}

}  // namespace granule::app
