// The start of a sweep spec for a sheared dilute gas (Lees–Edwards, ν = 0.05, L = 1, TC model), the
// system of Chapters 4 and 5: seed, [system] and [boundary] tables; the study adds the rest.
#pragma once

#include <string>

namespace granule::reproduce {

// `boundary_lines`: the shear velocity or its protocol (README.md, "boundary.*").
std::string sheared_gas_tables(int seed, int particles, double restitution, const std::string& boundary_lines);

}  // namespace granule::reproduce
