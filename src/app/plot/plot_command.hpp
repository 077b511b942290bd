// `granule plot <kind> RUN_DIR_or_FILE ...`: the thesis's pictures from a run's outputs
// (docs/plots.md).  Configuration pictures and movies use the C++ renderer (src/render); line
// plots and maps run matplotlib scripts (python/granule_plots) with Debian's Python.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <string>
#include <vector>

namespace granule::app {

void add_plot_command(CLI::App& root);

// One per file (src/app/plot/plot_*.cpp).
void add_plot_picture_commands(CLI::App& plot);     // config, movie
void add_plot_matplotlib_commands(CLI::App& plot);  // fields, timeseries, profiles, phase
void add_plot_spacetime_command(CLI::App& plot);    // spacetime
void add_plot_export_command(CLI::App& plot);       // export (extended XYZ, VTK)
void add_plot_sweep_command(CLI::App& plot);        // sweep (results.csv of granule sweep)

// The options given on a parsed command line ("--width", ...): options that apply to one
// dimension only are refused for the other.
std::vector<std::string> given_options(const CLI::App& command);

// Runs a plot command's body and ends the program with its exit code: 2 on InputError, 4 on IoError
// (an output that cannot be written), 1 on any other error (messages prefixed with "granule plot
// <kind>: error:").
[[noreturn]] void finish_plot_command(const std::string& kind, const std::function<int()>& body);

}  // namespace granule::app
