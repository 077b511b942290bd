// summary.json of a run: its parameters, how and why it stopped, performance, and the steady-shear
// temperature beside the theory (schema in README.md).
#pragma once

#include <nlohmann/json.hpp>
#include <vector>

#include "cells/cell_grid.hpp"
#include "engine/simulation.hpp"
#include "io/config.hpp"
#include "observers/global_diagnostics.hpp"

namespace granule::driver {

const char* stop_text(StopReason reason);

struct RunFacts {
  double wall_seconds = 0.0;          // of all segments of the run (resumed ones included)
  double segment_wall_seconds = 0.0;  // of this invocation
  std::int64_t segment_collisions = 0;          // of production, in this invocation
  std::int64_t segment_prerun_collisions = 0;   // of the elastic pre-run, in this invocation
  std::int64_t equilibrate_collisions = 0;
  std::int64_t snapshots = 0;
};

template <int D>
nlohmann::json summary_json(const RunConfig& config, const Simulation<D>& sim, const CellGrid& grid, StopReason reason,
                            const RunFacts& facts, const std::vector<DiagnosticsSample>& samples);

}  // namespace granule::driver
