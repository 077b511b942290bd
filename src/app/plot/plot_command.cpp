#include "app/plot/plot_command.hpp"

namespace granule::app {

void add_plot_command(CLI::App& root) {
  CLI::App* plot = root.add_subcommand(
      "plot", "Draw pictures, movies and exports from a run's outputs (RUN_DIR or a file; see docs/plots.md)");
  plot->require_subcommand(1);
  add_plot_picture_commands(*plot);
  add_plot_matplotlib_commands(*plot);
  add_plot_spacetime_command(*plot);
  add_plot_export_command(*plot);
  add_plot_sweep_command(*plot);
}

}  // namespace granule::app
