// The windows of a run compared with thesis Appendix B like with like: the thesis's windows and
// b₀⁽ⁱ⁾ are mapped to the run's units (appendix_b_reference.hpp) before anything is compared.
#pragma once

#include <optional>
#include <vector>

#include "distribution/appendix_b_reference.hpp"
#include "distribution/f1_analysis.hpp"
#include "engine/system_params.hpp"

namespace granule::distribution {

// Appendix B's windows for the run's ẽ, mapped to the run's units (empty when ẽ is not 0.6, 0.7,
// 0.8 or 0.9, or the run is not sheared).
std::vector<AppendixBEntry> thesis_windows_in_run_units(const SystemParams& run);

// Adds Appendix B's 4 ρ × 4 T windows of the run's ẽ, in the run's units (docs/f1.md, "Units"), to
// `densities` and `temperatures`, each centre once.  False, and nothing added, when the run has
// none (above).
bool add_thesis_windows(const SystemParams& run, std::vector<ValueWindow>& densities, std::vector<ValueWindow>& temperatures);

// The Appendix B window (run units) nearest to a window of the run, in units of its half widths;
// none when the run's ẽ has no table.
struct ThesisMatch {
  AppendixBEntry entry;      // run units
  bool same_window = false;  // the run's window is this one (centres equal to 1e-6)
};
std::optional<ThesisMatch> nearest_thesis_window(const SystemParams& run, const WindowResult& window);

}  // namespace granule::distribution
