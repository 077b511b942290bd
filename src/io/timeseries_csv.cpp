#include "io/timeseries_csv.hpp"

#include <fmt/format.h>

#include <cstdlib>
#include <fstream>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "io/atomic_file.hpp"

namespace granule {

std::string timeseries_header(const DiagnosticsSample& layout) {
  std::string header;
  for_each_column(layout, [&](const char* name, const double&) {
    if (!header.empty()) header += ',';
    header += name;
  });
  return header + "\n";
}

std::string timeseries_row(const DiagnosticsSample& s) {
  std::string row;
  for_each_column(s, [&](const char*, const double& value) {
    if (!row.empty()) row += ',';
    row += fmt::format("{:.12g}", value);
  });
  return row + "\n";
}

void write_timeseries(const std::string& path, const std::vector<DiagnosticsSample>& samples) {
  std::string content = samples.empty() ? timeseries_header() : timeseries_header(samples.front());
  for (const auto& sample : samples) content += timeseries_row(sample);
  write_file_atomically(path, content);
}

std::vector<DiagnosticsSample> read_timeseries(const std::string& path) {
  std::ifstream file(path);
  if (!file) throw std::runtime_error("cannot read " + path);
  std::string line;
  std::getline(file, line);
  std::vector<std::string> names;
  std::istringstream header(line);
  for (std::string name; std::getline(header, name, ',');) names.push_back(name);
  const std::optional<DiagnosticsSample> layout = diagnostics_layout_of(names);
  if (!layout) throw std::runtime_error(path + " has not the columns of this version");
  std::vector<DiagnosticsSample> samples;
  for (int number = 2; std::getline(file, line); ++number) {
    std::istringstream row(line);
    DiagnosticsSample sample = *layout;
    bool whole = true;
    for_each_column(sample, [&](const char*, double& value) {
      std::string cell;
      whole = whole && std::getline(row, cell, ',') && !cell.empty();
      if (!whole) return;
      char* end = nullptr;
      value = std::strtod(cell.c_str(), &end);
      whole = *end == '\0';
    });
    if (!whole) throw std::runtime_error(path + ", line " + std::to_string(number) + ": not a whole row");
    samples.push_back(sample);
  }
  return samples;
}

}  // namespace granule
