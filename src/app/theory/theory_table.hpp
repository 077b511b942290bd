// The output of the `granule theory` subcommands: tables of numbers, and the grids they are
// evaluated on.
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace granule::app {

// A table of numbers with named columns, printed aligned (with `# ` summary lines above it) or as
// CSV (header and rows only, so that any CSV reader takes it).
struct Table {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
  std::vector<std::string> summary;
};

// Refuses (exit 2) a table holding an infinite or NaN value, before printing anything.
void print_table(const CLI::App& command, const Table& table, bool csv);

// Evenly spaced values from lo to hi inclusive (one value when points == 1).
std::vector<double> linspace(double lo, double hi, int points);
// The same, evenly spaced in log (lo, hi > 0).
std::vector<double> logspace(double lo, double hi, int points);

}  // namespace granule::app
