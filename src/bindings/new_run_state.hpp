// The start of a new run as `granule run` makes it: the engine's cell grid and the initial state
// of thesis §1.4.2 with its clock (the images held at U(0) of the protocol, or at rest for the
// static gas of §4.3, until production starts).
#pragma once

#include "cells/cell_grid.hpp"
#include "engine/system_params.hpp"
#include "io/config.hpp"

namespace granule::bindings {

struct NewRunState {
  CellGrid grid;
  ParticleState particles;
  ClockState clock;
};

// Throws ConfigError (interactive_run.hpp) where `granule run` exits with code 2.
NewRunState new_run_state(const RunConfig& config);

}  // namespace granule::bindings
