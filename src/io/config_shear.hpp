// The [boundary] kind and shear drive and the speeds of [initial] (split from config.cpp): the
// protocol of thesis Chapter 4 (ramp, schedule, oscillation), or the steady ±U/2 of walls on y,
// U and T_i within the numerical ranges, and T_i as a multiple of the steady T₀ of (4.5).
#pragma once

#include "io/config.hpp"
#include "io/config_reader.hpp"

namespace granule {

// Needs the geometry and the restitution resolved first (T₀ depends on them).
void resolve_speeds(const ConfigReader& in, RunConfig& c);
// The [boundary] and [initial] keys of resolve_speeds, as TOML.
std::string speeds_to_toml(const RunConfig& c);

}  // namespace granule
