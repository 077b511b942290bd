// How the `granule theory` subcommands print a prediction (theory/prediction_table.hpp).
#pragma once

#include <CLI/CLI.hpp>

#include "theory/prediction_table.hpp"

namespace granule::app {

// Aligned columns with `# ` summary lines above them, or CSV (header and rows only, so that any
// CSV reader takes it).  Refuses (exit 2) a table whose derived values or rows hold an infinite
// or NaN value, before printing anything.
void print_table(const CLI::App& command, const theory::PredictionTable& table, bool csv);

}  // namespace granule::app
