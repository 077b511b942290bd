// timeseries.csv: one row per diagnostics sample (columns documented in README.md).
#pragma once

#include <string>
#include <vector>

#include "observers/global_diagnostics.hpp"

namespace granule {

std::string timeseries_header();
std::string timeseries_row(const DiagnosticsSample& sample);
// Rewrite the whole file atomically.
void write_timeseries(const std::string& path, const std::vector<DiagnosticsSample>& samples);
// The rows of a file written by write_timeseries (values to the 12 digits it keeps).  Throws
// std::runtime_error naming the file and line when a row is not whole.
std::vector<DiagnosticsSample> read_timeseries(const std::string& path);

}  // namespace granule
