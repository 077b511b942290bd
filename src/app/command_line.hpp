#pragma once
// The whole command line behind `main`: kept in the application library so that its one heavy
// header (CLI11) is compiled once, in the library's precompiled header.

#include <string>

namespace granule::app {

// Parses argv, runs the chosen subcommand and returns the process exit code (README.md).
int run_granule(int argc, char** argv);

// The path of this executable: sweeps and studies run their points as its children.
std::string own_executable();

}  // namespace granule::app
