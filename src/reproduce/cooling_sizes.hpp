// System II (ẽ = 0.6, ν = 0.05) cooled at larger N than Chapter 2's runs: whether the late decay of
// T̄ reaches the thesis's t⁻² (Figs 2.6(C), 2.7(C)) in a larger box, where clusters take longer to
// coarsen to the box's size, or moves towards the clustering regime's E ~ t⁻¹.
#pragma once

#include "reproduce/study.hpp"

namespace granule::reproduce {

// The group "system_II_sizes": two sizes, 3 seeds each (one at the tiny scale), to c = 100.
RunGroup cooling_sizes_runs(Scale scale);

// The late exponents of T̄ and E at each size, as claims.
void add_cooling_size_claims(Scale scale, const GroupOutputs& group, StudyOutcome& out);

}  // namespace granule::reproduce
