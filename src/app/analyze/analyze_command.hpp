// `granule analyze ...`: measurements from the saved outputs of a run (snapshot files).  Each
// analysis registers its own subcommand from its own file.
#pragma once

#include <CLI/CLI.hpp>

namespace granule::app {

void add_analyze_command(CLI::App& root);

// One per analysis (src/app/analyze_*.cpp).
void add_analyze_fields(CLI::App& analyze);
void add_analyze_collisions(CLI::App& analyze);
void add_analyze_spectra(CLI::App& analyze);
void add_analyze_f1(CLI::App& analyze);
void add_analyze_spins(CLI::App& analyze);

}  // namespace granule::app
