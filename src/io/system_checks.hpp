// The checks of the physical parameters and the particle state that a file records (a snapshot
// frame, a checkpoint, an initial state taken from another run): the same ranges the
// configuration accepts (io/input_ranges.hpp), so that nothing read from a file can start or
// analyse a system that no configuration could describe.  Each check returns what is wrong, one
// line per problem ("restitution is 2; expected (0, 1]"), empty when nothing is.
#pragma once

#include <string>
#include <vector>

#include "engine/system_params.hpp"

namespace granule {

std::vector<std::string> system_problems(const SystemParams& system);
// Diameters and masses (polydisperse), positions inside the box (within round-off of its faces),
// finite velocities and spins, no grain inside an obstacle (beyond round-off), for a state of
// `system`.
std::vector<std::string> particle_problems(const ParticleState& particles, const SystemParams& system);
// What is wrong with an obstacle of `system` (its centre outside the box, or along a periodic axis
// too wide for a grain to pass between it and its image; its diameter and restitutions), the
// configuration's rules (io/config_obstacles.cpp), one line per problem, naming it `name`.
std::vector<std::string> obstacle_problems(const Obstacle& obstacle, const SystemParams& system, const std::string& name);
// "<file>: <problem>; <problem>" as an InputError, when there are problems.
void refuse_problems(const std::string& file, const std::vector<std::string>& problems);

}  // namespace granule
