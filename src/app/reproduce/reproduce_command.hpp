// `granule reproduce [STUDY] --scale S --out DIR [--jobs K | --mpi]`: runs the thesis's studies
// (src/reproduce) through the sweep engine, draws their figures and writes the report
// (docs/reproduce.md).
#pragma once

#include <CLI/CLI.hpp>

namespace granule::app {

void add_reproduce_command(CLI::App& root);

}  // namespace granule::app
