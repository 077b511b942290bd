// The geometry keys of [system] (split from config.cpp): dimension, box, packing fraction or
// reference diameter, and the diameter distribution and masses of polydisperse runs.
#pragma once

#include <string>

#include "io/config.hpp"
#include "io/config_reader.hpp"

namespace granule {

// Needs seed, system.particles and the placement (c.placement, initial.from) resolved first: the
// relative diameters are drawn from the seed, and the packing fraction a polydisperse run may
// have is the one its placement reaches.
void resolve_geometry(const ConfigReader& in, RunConfig& c);
// The keys of resolve_geometry as TOML lines of [system].
std::string geometry_to_toml(const RunConfig& c);

}  // namespace granule
