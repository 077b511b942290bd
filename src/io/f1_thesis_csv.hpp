// The CSV comparing `granule analyze f1`'s windows with thesis Appendix B in the run's units
// (<stem>_thesis.csv, schema in docs/f1.md), with the dimensionless forms √(2T) b₀⁽¹⁾ and
// 2T b₀⁽²⁾ beside them.
#pragma once

#include <string>
#include <vector>

#include "distribution/f1_analysis.hpp"
#include "engine/system_params.hpp"

namespace granule {

// One row per window with an Appendix B match (distribution/appendix_b_comparison.hpp); empty
// when none has.
std::string thesis_comparison_csv(const SystemParams& run, const std::vector<distribution::WindowResult>& windows);

}  // namespace granule
