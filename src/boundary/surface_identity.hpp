// What a checkpoint records of the surfaces a grain can hit, so that a run resumes only with the
// same ones: which axes have walls, each wall's restitutions, velocity and normal drive, and the
// obstacles with their restitutions (those in force: elastic during the pre-run).  A new kind of
// surface records itself here; the engine's checkpoint writes and checks whatever this gives.
#pragma once

#include <array>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "boundary/surface_set.hpp"

namespace granule {

// By checkpoint name, the values that identify the surfaces in d dimensions (nothing for a box
// without any: its checkpoint holds no such entries).
std::map<std::string, std::vector<double>> surface_identity(const SurfaceSet& surfaces, int dimension);

// Every name surface_identity can give in d dimensions, and of the points of wall schedules the
// first that `configured` does not have: a checkpoint that holds one the configuration's identity
// lacks was written with a surface (or a longer schedule) the configuration does not have.
std::set<std::string> surface_identity_names(const SurfaceSet& configured, int dimension);

}  // namespace granule
