// `granule plot spacetime`: ρ(y, t), V_x(y, t), T(y, t) as three shaded panels, time across and y
// up (thesis Figs 4.7–4.8: dense streamwise layers converging into a central plug), with U(t)
// above when the snapshots store it.  The arrays are assembled by io/spacetime_file (the rows by
// analysis/spacetime_profiles), written as HDF5 beside the picture, and drawn by
// python/granule_plots/spacetime.py.
#include <fmt/format.h>

#include <filesystem>
#include <memory>
#include <optional>

#include "analysis/field_grid.hpp"
#include "app/plot/plot_command.hpp"
#include "app/plot/plot_inputs.hpp"
#include "io/spacetime_file.hpp"
#include "io/atomic_file.hpp"
#include "io/snapshot_file.hpp"

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

// The input's fields file or snapshot file, as `from` asks (or as the input offers).
std::pair<std::string, std::string> source_file(const SpacetimeArguments& a) {
  std::string from = a.from;
  if (from.empty()) {
    if (fs::is_directory(a.input)) {
      from = fs::exists(fs::path(a.input) / "fields.h5") || fs::exists(fs::path(a.input) / "fields.h5.partial") ? "fields"
                                                                                                              : "snapshots";
    } else {
      from = hdf5_format(a.input) == "granule-snapshots" ? "snapshots" : "fields";
    }
  }
  if (from != "fields" && from != "snapshots") throw BadPlotInput(fmt::format("--from {} is not one of fields, snapshots", from));
  const bool fields = from == "fields";
  const std::string path = locate_run_file(a.input, fields ? "fields.h5" : "snapshots.h5");
  require_hdf5_format(path, fields ? "granule-fields" : "granule-snapshots",
                      fields ? "`granule run` or `granule analyze fields`" : "`granule run`");
  return {from, path};
}

// The snapshot file beside a fields file (for U(t)), or "" when there is none.
std::string snapshots_beside(const std::string& fields_path) {
  for (const char* name : {"snapshots.h5", "snapshots.h5.partial"}) {
    const fs::path candidate = fs::path(fields_path).parent_path() / name;
    if (fs::exists(candidate)) return candidate.string();
  }
  return "";
}

int plot_spacetime(const SpacetimeArguments& a) {
  if (a.dpi < 20 || a.dpi > 600) throw BadPlotInput(fmt::format("--dpi {} is outside [20, 600]", a.dpi));
  if (a.group != "instant" && a.group != "average") {
    throw BadPlotInput(fmt::format("--group {} is not one of instant, average", a.group));
  }
  if (a.rows && (*a.rows < 1 || *a.rows > kMaxRows)) {
    throw BadPlotInput(fmt::format("--rows {} is outside [1, {}]", *a.rows, kMaxRows));
  }
  const auto [from, path] = source_file(a);
  if (from == "fields" && (a.rows || a.relative)) {
    throw BadPlotInput("--rows and --relative apply to --from snapshots (fields.h5 has its own grid and frame)");
  }
  SpacetimeProfiles profiles;
  if (from == "fields") {
    profiles = spacetime_from_fields(path, a.group);
    const std::string snapshots = snapshots_beside(path);
    if (!snapshots.empty()) read_shear_protocol(snapshots, profiles);
  } else {
    const SnapshotMetadata m = read_snapshot(path, 0).metadata;
    const int rows = a.rows.value_or(default_field_grid(m.system.length_x, m.system.length_y, m.system.particles).ny);
    profiles = spacetime_from_snapshots(path, rows, a.relative);
  }
  if (profiles.t.empty()) throw BadPlotInput(fmt::format("{} has no complete frame yet", path));

  const std::string out = a.out.empty() ? output_beside(a.input, "spacetime.png") : a.out;
  const std::string data = a.data.empty() ? fs::path(out).replace_extension(".h5").string() : a.data;
  if (data == out) throw BadPlotInput(fmt::format("--data {} is the picture itself", data));
  // The arrays are published only with the picture drawn from them.
  const std::string partial = data + ".partial";
  const RemovedAtExit cleanup{partial};
  write_spacetime_partial(data, profiles);
  const int status = run_plot_script("spacetime", {partial, "--out", out, "--dpi", std::to_string(a.dpi)});
  if (status != 0) return status;
  publish_file(partial, data);
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
