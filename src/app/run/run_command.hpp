// `granule run`: the simulation command (options documented in README.md).
#pragma once

#include <CLI/CLI.hpp>

namespace granule::app {

void add_run_command(CLI::App& root);

}  // namespace granule::app
