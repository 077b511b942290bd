#include "io/timeseries_csv.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <string_view>

#include "io/atomic_file.hpp"
#include "io/io_error.hpp"

namespace granule {

namespace {

// Columns the writer leaves undefined (NaN, or ±inf for a ratio) where they have no meaning: the
// Chapter 4 flow measures of a 3D run (2D pictures of bands and clusters), and T_rot/T of a gas
// with no translational temperature left.  Every other column is a finite number.
bool may_be_undefined(const char* name) {
  if (std::string_view(name) == "rotational_temperature_ratio") return true;
  FlowClassification probe;
  bool flow_measure = false;
  for_each_flow_measure(probe, [&](const char* measure, double&) { flow_measure = flow_measure || std::string_view(name) == measure; });
  return flow_measure;
}

// The comma-separated fields of one line (the writer quotes nothing: every field is a number or a name).
std::vector<std::string_view> split_row(std::string_view line) {
  std::vector<std::string_view> cells;
  for (std::size_t start = 0;;) {
    const std::size_t comma = line.find(',', start);
    cells.push_back(line.substr(start, comma - start));
    if (comma == std::string_view::npos) return cells;
    start = comma + 1;
  }
}

}  // namespace

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
  std::string line;
  if (!file || !std::getline(file, line)) throw InputError(fmt::format("{}: cannot be read, or empty", path));
  const std::vector<std::string_view> header_cells = split_row(line);
  const std::vector<std::string> header(header_cells.begin(), header_cells.end());
  const std::optional<DiagnosticsSample> layout = diagnostics_layout_of(header);
  if (!layout) {
    throw InputError(fmt::format("{}, line 1: the header is not the columns of a timeseries.csv of this version "
                                 "(README.md, \"timeseries.csv\")",
                                 path));
  }
  std::vector<DiagnosticsSample> samples;
  for (long number = 2; std::getline(file, line); ++number) {
    const std::vector<std::string_view> cells = split_row(line);
    if (cells.size() != header.size()) {
      throw InputError(
          fmt::format("{}, line {}: {} values, expected {} (one per column)", path, number, cells.size(), header.size()));
    }
    DiagnosticsSample sample = *layout;
    std::size_t column = 0;
    for_each_column(sample, [&](const char* name, double& value) {
      const std::string cell(cells[column++]);
      const std::string shown = cell.substr(0, 40);  // a damaged cell may be any length
      const auto refuse = [&](const std::string& why) {
        return InputError(fmt::format("{}, line {}, column {}: {}", path, number, name, why));
      };
      char* end = nullptr;
      value = std::strtod(cell.c_str(), &end);
      if (cell.empty() || *end != '\0') throw refuse(fmt::format("\"{}\" is not a number", shown));
      if (!std::isfinite(value) && !may_be_undefined(name)) throw refuse(fmt::format("{} is not a finite number", shown));
    });
    if (!(sample.c >= 0.0)) throw InputError(fmt::format("{}, line {}, column c: {} is negative", path, number, sample.c));
    if (!samples.empty()) {
      const auto forward = [&](const char* name, double now, double before) {
        if (now < before) {
          throw InputError(fmt::format("{}, line {}, column {}: {} is less than in the row before ({}): rows go "
                                       "forward in time",
                                       path, number, name, now, before));
        }
      };
      forward("t", sample.t, samples.back().t);
      forward("c", sample.c, samples.back().c);
    }
    samples.push_back(sample);
  }
  return samples;
}

}  // namespace granule
