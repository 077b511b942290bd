// Rough grains: the [system] keys of the collision model with spin — tangential
// restitution β, inertia factor q (I = q m σ²/4), Coulomb friction μ — and the rotational
// temperature of their initial spins in [initial].
#pragma once

#include <string>

#include "io/config.hpp"
#include "io/config_reader.hpp"

namespace granule {

// Needs the dimension, the initial temperature and initial.from resolved first.
void resolve_roughness(const ConfigReader& in, RunConfig& c);
// The roughness keys as TOML lines of [system] (none for smooth grains).
std::string roughness_to_toml(const RunConfig& c);
// initial.rotational_temperature as a TOML line of [initial] (none for smooth grains or initial.from).
std::string rotational_temperature_to_toml(const RunConfig& c);

}  // namespace granule
