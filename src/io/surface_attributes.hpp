// The parameters of a run's grains and surfaces that a snapshot file records beside its frames, as
// root attributes of the file (README, "Snapshot files").
#pragma once

#include <hdf5.h>

#include "engine/system_params.hpp"

namespace granule {

// The parameters of rough grains, walls, gravity and obstacles as root attributes and datasets, each group only when the run has it: roughness
// (`tangential_restitution` β, `inertia_factor` q, `friction` μ, +inf without a Coulomb limit),
// walls (`walls` [x, y, z] 0/1, and per face 2·axis + side `wall_restitution`,
// `wall_tangential_restitution` (6,), `wall_velocity` (6 × 3); when a wall moves normal to itself,
// `wall_vibration` (6 × 2: amplitude A and frequency f per face, 0 for none) and, for schedules,
// the dataset `wall_schedule` (K × 3: face, t, h per point)), `gravity` [g_x, g_y, g_z], the
// dataset `obstacles` (M × 6: centre x, y, z, diameter, restitution, tangential restitution), and a
// speed-dependent restitution (`restitution_law` "threshold" with `elastic_below`, or
// "viscoelastic" with `viscoelastic_constant`).
void write_grains_walls_gravity_attributes(hid_t f, const SystemParams& p);
// The same read back into `p` (absent groups leave it as it is); the values are checked by the
// caller (io/system_checks.hpp).  Throws InputError on a malformed entry.
void read_grains_walls_gravity_attributes(hid_t f, SystemParams& p);

}  // namespace granule
