// Appendix C, Fig C.4: a shear flow of rough disks, whose caption says that grains close together
// spin in opposite senses.  Measured as the contact value of the spin correlation, C_contact < 0
// (analysis/spin_correlation.hpp), from `granule analyze spins` on each run's snapshots.
#pragma once

#include "reproduce/study.hpp"

namespace granule::reproduce {

// The runs: N rough disks (ν = 0.05, ẽ = 0.6, β = −0.8) between Lees–Edwards images at ±100, as
// examples/walls_spin_gravity/rough_shear_fig_c4.toml; fewer disks and collisions below the thesis scale.
RunGroup rough_shear_runs(Scale scale, int seeds);
// `granule analyze spins` of the later half of each run's snapshots into spins.h5.
PointAnalysis rough_shear_spins_analysis();
// The claim appendix_c.fig_c4.neighbours_spin_opposite and the figure of C(r).
void add_spin_claim(const GroupOutputs& group, StudyOutcome& out);

}  // namespace granule::reproduce
