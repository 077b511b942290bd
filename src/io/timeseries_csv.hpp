// timeseries.csv: one row per diagnostics sample (columns documented in README.md).
#pragma once

#include <string>
#include <vector>

#include "observers/global_diagnostics.hpp"

namespace granule {

// The header of rows laid out as `layout` (its optional column groups: GlobalDiagnostics::layout()).
std::string timeseries_header(const DiagnosticsSample& layout = {});
std::string timeseries_row(const DiagnosticsSample& sample);
// Rewrite the whole file atomically (the columns of the first sample; the plain ones if none).
void write_timeseries(const std::string& path, const std::vector<DiagnosticsSample>& samples);
// The rows of a file written by write_timeseries (values to the 12 digits it keeps), with the
// optional column groups its header names.  The file is untrusted (an edited or damaged one is
// refused with an InputError naming the file, line and column): the header must be the columns of
// a layout, each row one number per column, finite except where the writer leaves a measure
// undefined (the flow measures of 3D runs, T_rot/T), c >= 0, and t and c never decrease.
std::vector<DiagnosticsSample> read_timeseries(const std::string& path);

}  // namespace granule
