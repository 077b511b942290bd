// A prediction of the thesis's kinetic theory as a table of numbers, as `granule theory` prints it
// (built here, below the command line, so that any caller can have it), and the grids it is
// evaluated on.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace granule::theory {

// Named columns and rows of numbers, with summary lines of text (the inputs and the scalar
// results the table rests on).  `derived_names`/`derived` are those scalar results, one value
// per name, for a caller to refuse a prediction whose inputs combine beyond double precision.
struct PredictionTable {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
  std::vector<std::string> summary;
  std::vector<std::string> derived_names;
  std::vector<double> derived;
};

// The first derived value or entry of the table that is infinite or NaN, named by its derived name
// or column; none when every number is finite.  Inputs inside their ranges may still combine into
// a result beyond double precision (say ν = 1e-300 with σ = 1e30).
struct NonFiniteEntry {
  std::string name;
  double value = 0.0;
};
std::optional<NonFiniteEntry> first_non_finite(const PredictionTable& table);

// The table as text: the summary lines as `# ` lines above aligned columns (6 significant digits).
std::string table_text(const PredictionTable& table);
// The table as CSV: the header and rows only (10 significant digits), so that any CSV reader takes it.
std::string table_csv(const PredictionTable& table);

// Evenly spaced values from lo to hi inclusive (one value when points == 1).
std::vector<double> linspace(double lo, double hi, int points);
// The same, evenly spaced in log (lo, hi > 0).
std::vector<double> logspace(double lo, double hi, int points);

}  // namespace granule::theory
