// timeseries.csv: one row per diagnostics sample (columns documented in README.md).
#pragma once

#include <string>
#include <vector>

#include "observers/global_diagnostics.hpp"

namespace granule {

std::string timeseries_header();
std::string timeseries_row(const DiagnosticsSample& sample);
// Rewrite the whole file atomically; `previous_rows` (CSV lines of a resumed run) come first.
void write_timeseries(const std::string& path, const std::vector<DiagnosticsSample>& samples,
                      const std::string& previous_rows = {});

}  // namespace granule
