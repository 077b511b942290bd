// A run's configuration in words, as `granule run` opens with, so that a reader need not open
// config.toml to learn what ran: the system, the collision model in force (ẽ alone, or with the TC
// model and its t_c: the built-in example uses it), rough grains, walls and gravity.
#pragma once

#include <string>
#include <vector>

#include "io/config.hpp"

namespace granule {

// "rough disks, N = …, ν = …, σ = …, e = …, Lees–Edwards box L_x × L_y, U = …".
std::string describe_system(const RunConfig& config);

// The restitution law of every collision (thesis (1.2)), with the TC model when t_c > 0.
std::string collision_model_text(const SystemParams& system);

// Rough grains, each pair of walls and gravity: one line each, when present.
std::vector<std::string> describe_surfaces(const RunConfig& config);

}  // namespace granule
