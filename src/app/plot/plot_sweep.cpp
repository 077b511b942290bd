// `granule plot sweep DIR --x KEY --y KEY`: a swept quantity from the sweep's results.csv, drawn by
// python/granule_plots/sweep.py (with the kinetic-theory curves of `granule theory steady-shear`
// when the sweep varies the restitution of sheared runs).
#include <fmt/format.h>

#include <memory>

#include "app/command_line.hpp"
#include "app/plot/plot_command.hpp"
#include "io/run_files.hpp"
#include "render/plot_scripts.hpp"

namespace granule::app {

namespace {

struct SweepPlotArguments {
  std::string input, x, y, out, data;
  int dpi = 100;
};

int plot_sweep(const SweepPlotArguments& a) {
  if (a.dpi < 20 || a.dpi > 600) throw InputError(fmt::format("--dpi {} is outside [20, 600]", a.dpi));
  const std::string input = locate_run_file(a.input, "results.csv");
  const std::string out = a.out.empty() ? output_beside(a.input, "sweep.png") : a.out;
  std::vector<std::string> arguments{input,
                                     "--out",
                                     out,
                                     "--dpi",
                                     std::to_string(a.dpi),
                                     "--x",
                                     a.x,
                                     "--y",
                                     a.y,
                                     "--granule",
                                     own_executable()};
  if (!a.data.empty()) arguments.insert(arguments.end(), {"--data", a.data});
  const int status = render::run_plot_script("sweep", arguments);
  if (status == 0) fmt::print("wrote {}\n", out);
  return status;
}

}  // namespace

void add_plot_sweep_command(CLI::App& plot) {
  auto a = std::make_shared<SweepPlotArguments>();
  CLI::App* c = plot.add_subcommand(
      "sweep",
      "A swept quantity against a swept key from a sweep's results.csv, mean and standard error over seeds "
      "(with the kinetic-theory curves (3.1), (3.2) of sheared runs against the restitution: thesis Figs 3.1-3.3)");
  c->add_option("input", a->input, "Sweep directory (granule sweep --out) or its results.csv")->required();
  c->add_option("--x", a->x, "Column of the abscissa, e.g. system.restitution")->required();
  c->add_option("--y", a->y, "Column drawn, e.g. summary.steady_shear.temperature_measured")->required();
  c->add_option("--out", a->out, "PNG file (default: sweep.png in the sweep directory)");
  c->add_option("--dpi", a->dpi, "Resolution, 20 … 600 dots per inch (the figure size in inches is fixed)")
      ->capture_default_str();
  c->add_option("--data", a->data, "Also write the numbers drawn to this JSON file");
  c->callback([a] { finish_plot_command("sweep", [&] { return plot_sweep(*a); }); });
}

}  // namespace granule::app
