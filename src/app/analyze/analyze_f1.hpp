// `granule analyze f1`: the single-particle velocity distribution by cumulative sampling
// (thesis Chapter 5, Appendix B).  The command lives in analyze_f1.cpp; its output files
// (schema in docs/f1.md) are written by io/f1_file.cpp, the comparison with Appendix B in the
// run's units by analyze_f1_thesis.cpp.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "distribution/appendix_b_reference.hpp"
#include "distribution/f1_analysis.hpp"
#include "io/f1_file.hpp"
#include "io/snapshot_file.hpp"

namespace granule::app {

// Appendix B's windows for the run's ẽ, mapped to the run's units (empty when ẽ is not 0.6, 0.7, 0.8
// or 0.9, or the run is not sheared).
std::vector<distribution::AppendixBEntry> thesis_windows_in_run_units(const SystemParams& run);

// The Appendix B window (run units) nearest to a window of the run, in units of its half widths;
// none when the run's ẽ has no table.
struct ThesisMatch {
  distribution::AppendixBEntry entry;  // run units
  bool same_window = false;            // the run's window is this one (centres equal to 1e-6)
};
std::optional<ThesisMatch> nearest_thesis_window(const SystemParams& run, const distribution::WindowResult& window);

// One console line comparing the window's b₀⁽¹⁾ with Appendix B's in the run's units.
std::string describe_thesis_comparison(const ThesisMatch& match, const distribution::WindowResult& window);

// The CSV of the comparison (docs/f1.md), one row per window with a match; empty when none has.
std::string thesis_comparison_csv(const SystemParams& run, const std::vector<distribution::WindowResult>& windows);

}  // namespace granule::app
