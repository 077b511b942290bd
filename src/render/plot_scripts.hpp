// Pictures drawn by other programs: the matplotlib scripts of python/granule_plots, run with
// Debian's Python, and ffmpeg, which encodes movies.  The scripts are found in
// $GRANULE_PYTHON_DIR, else beside an installed binary, else in the source tree of the build.
#pragma once

#include <string>
#include <vector>

namespace granule::render {

// Runs a program (argv[0] is looked up in PATH) and returns its exit code (127 if it cannot start).
int run_program(const std::vector<std::string>& argv);

// Whether an executable `name` is in one of the folders of PATH.
bool program_in_path(const std::string& name);

// Runs python/granule_plots/<script>.py with Debian's Python; returns its exit code.
int run_plot_script(const std::string& script, const std::vector<std::string>& arguments);

}  // namespace granule::render
