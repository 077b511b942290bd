// The groups of `granule theory` subcommands, each registered on the `theory` command.
#pragma once

#include <CLI/CLI.hpp>

namespace granule::app {

// haff, free-stability: the freely cooling gas (thesis chapter 2).
void add_cooling_theory(CLI::App& theory);
// shear-stability, shear-scales, steady-shear: the sheared gas (thesis chapters 3 and 4).
void add_shear_theory(CLI::App& theory);
// shear-start: the early-time temperature and clustering window of a hot or cold start under
// shear (thesis §4.2).
void add_shear_start(CLI::App& theory);

}  // namespace granule::app
