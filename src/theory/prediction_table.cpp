#include "theory/prediction_table.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace granule::theory {

std::optional<NonFiniteEntry> first_non_finite(const PredictionTable& table) {
  const auto first_in = [](const std::vector<std::string>& names, const std::vector<double>& values) -> std::optional<NonFiniteEntry> {
    for (std::size_t j = 0; j < values.size(); ++j) {
      if (!std::isfinite(values[j])) return NonFiniteEntry{names[j], values[j]};
    }
    return std::nullopt;
  };
  if (auto derived = first_in(table.derived_names, table.derived)) return derived;
  for (const auto& row : table.rows) {
    if (auto entry = first_in(table.columns, row)) return entry;
  }
  return std::nullopt;
}

std::string table_text(const PredictionTable& table) {
  std::string text;
  for (const auto& s : table.summary) text += fmt::format("# {}\n", s);
  if (table.columns.empty()) return text;
  std::vector<std::size_t> width;
  for (const auto& c : table.columns) width.push_back(std::max<std::size_t>(14, c.size() + 2));
  for (std::size_t j = 0; j < table.columns.size(); ++j) text += fmt::format("{:>{}}", table.columns[j], width[j]);
  text += "\n";
  for (const auto& row : table.rows) {
    // + 0.0 prints a negative zero as 0
    for (std::size_t j = 0; j < row.size(); ++j) text += fmt::format("{:>{}.6g}", row[j] + 0.0, width[j]);
    text += "\n";
  }
  return text;
}

std::string table_csv(const PredictionTable& table) {
  std::string text;
  for (std::size_t j = 0; j < table.columns.size(); ++j) text += (j ? "," : "") + table.columns[j];
  text += "\n";
  for (const auto& row : table.rows) {
    for (std::size_t j = 0; j < row.size(); ++j) text += fmt::format("{}{:.10g}", j ? "," : "", row[j] + 0.0);
    text += "\n";
  }
  return text;
}

std::vector<double> linspace(double lo, double hi, int points) {
  std::vector<double> out;
  for (int j = 0; j < points; ++j) {
    out.push_back(points == 1 ? lo : lo + (hi - lo) * j / (points - 1));
  }
  return out;
}

std::vector<double> logspace(double lo, double hi, int points) {
  std::vector<double> out;
  for (double x : linspace(std::log(lo), std::log(hi), points)) out.push_back(std::exp(x));
  return out;
}

}  // namespace granule::theory
