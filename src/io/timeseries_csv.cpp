#include "io/timeseries_csv.hpp"

#include <fmt/format.h>

#include "io/atomic_file.hpp"

namespace granule {

std::string timeseries_header() {
  std::string header;
  const DiagnosticsSample layout;
  for_each_column(layout, [&](const char* name, const double&) { header += (header.empty() ? "" : ",") + std::string(name); });
  return header + "\n";
}

std::string timeseries_row(const DiagnosticsSample& s) {
  std::string row;
  for_each_column(s, [&](const char*, const double& value) { row += fmt::format("{}{:.12g}", row.empty() ? "" : ",", value); });
  return row + "\n";
}

void write_timeseries(const std::string& path, const std::vector<DiagnosticsSample>& samples,
                      const std::string& previous_rows) {
  std::string content = timeseries_header() + previous_rows;
  for (const auto& sample : samples) content += timeseries_row(sample);
  write_file_atomically(path, content);
}

}  // namespace granule
