// granule: command-line entry point.  Each subcommand lives in its own file under src/app/.
#include <CLI/CLI.hpp>

#include "app/analyze_command.hpp"
#include "app/bench_command.hpp"
#include "app/plot_command.hpp"
#include "app/run_command.hpp"
#include "app/theory_command.hpp"
#include "granule/version.hpp"

int main(int argc, char** argv) {
  CLI::App app{"Granule: event-driven simulation and analysis of rapid granular flows of inelastic hard disks\n"
               "(after M.-L. Tan, Microstructures and Macrostructures in Rapid Granular Flows, Princeton 1995)."};
  app.set_version_flag("--version", granule::kVersion);
  app.require_subcommand(1);
  granule::app::add_run_command(app);
  granule::app::add_bench_command(app);
  granule::app::add_theory_command(app);
  granule::app::add_analyze_command(app);
  granule::app::add_plot_command(app);
  CLI11_PARSE(app, argc, argv);
  return 0;
}
