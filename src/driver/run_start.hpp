// How a new run begins, for every front end (`granule run`, its sweep points, the Python module):
// the engine's cell grid and the initial state with its clock — a frame of an earlier run
// (initial.from), or the state of thesis §1.4.2 with the shear profile (initial.shear_profile) or
// at rest relative to the box (the static gas of §4.3).  Until production starts the images move
// at the velocity of the initial profile: U(0) of the protocol, or 0 for the static gas.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "cells/cell_grid.hpp"
#include "engine/system_params.hpp"
#include "io/config.hpp"

namespace granule::driver {

// A configuration a run refuses (`granule run` exits with code 2; Python raises ConfigError): the
// message names the key, the value and what is allowed.
class ConfigError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// The engine's cell grid of the run.
CellGrid run_cell_grid(const RunConfig& config);

struct RunStart {
  ParticleState particles;
  ClockState clock;
};

// The initial state of a new run of `config`.
RunStart run_start(const RunConfig& config);

// What a valid configuration will cost beyond the usual, in words a user can act on (printed when
// the run starts and kept in summary.json): a Lees–Edwards protocol whose tolerance makes it take
// more than kManySegments constant-velocity segments while U(t) changes.
inline constexpr std::int64_t kManySegments = 1000000;
std::vector<std::string> run_warnings(const RunConfig& config);

}  // namespace granule::driver
