// `granule sweep`: run every point of a parameter sweep, locally (--jobs K), over MPI ranks (--mpi)
// or as SLURM array tasks, and gather results.csv (options documented in README.md, "Sweeps").
#pragma once

#include <CLI/CLI.hpp>

namespace granule::app {

void add_sweep_command(CLI::App& root);

}  // namespace granule::app
