#include "app/theory/theory_table.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "app/theory/theory_checks.hpp"

namespace granule::app {

void print_table(const CLI::App& command, const theory::PredictionTable& table, bool csv) {
  theory_checks::require_finite(command, table.derived_names, table.derived);
  for (const auto& row : table.rows) theory_checks::require_finite(command, table.columns, row);
  if (csv) {
    std::string line;
    for (std::size_t j = 0; j < table.columns.size(); ++j) {
      line += (j ? "," : "") + table.columns[j];
    }
    fmt::print("{}\n", line);
    for (const auto& row : table.rows) {
      line.clear();
      for (std::size_t j = 0; j < row.size(); ++j) {
        line += fmt::format("{}{:.10g}", j ? "," : "", row[j] + 0.0);
      }
      fmt::print("{}\n", line);
    }
    return;
  }
  for (const auto& s : table.summary) fmt::print("# {}\n", s);
  if (table.columns.empty()) return;
  std::vector<std::size_t> width;
  for (const auto& c : table.columns) width.push_back(std::max<std::size_t>(14, c.size() + 2));
  std::string line;
  for (std::size_t j = 0; j < table.columns.size(); ++j) {
    line += fmt::format("{:>{}}", table.columns[j], width[j]);
  }
  fmt::print("{}\n", line);
  for (const auto& row : table.rows) {
    line.clear();
    // + 0.0 prints a negative zero as 0
    for (std::size_t j = 0; j < row.size(); ++j) {
      line += fmt::format("{:>{}.6g}", row[j] + 0.0, width[j]);
    }
    fmt::print("{}\n", line);
  }
}

}  // namespace granule::app
