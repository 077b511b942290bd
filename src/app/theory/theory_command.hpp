// `granule theory ...`: the thesis's kinetic-theory predictions printed as tables or CSV, so that
// a run and its theory can sit side by side (docs/theory.md).
#pragma once

#include <CLI/CLI.hpp>

namespace granule::app {

// Registers the `theory` subcommand and its sub-subcommands (haff, free-stability,
// shear-stability, shear-scales, steady-shear); their callbacks print to stdout.
void add_theory_command(CLI::App& root);

}  // namespace granule::app
