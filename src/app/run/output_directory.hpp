// The output directory of a run: refuse to mix two runs' files, check that it can be written and
// that the machine has the memory for the run, before anything is written.  Failures are thrown
// as CommandFailure with the exit code they deserve (exit_codes.hpp).
#pragma once

#include <string>
#include <vector>

#include "cells/cell_grid.hpp"
#include "io/config.hpp"

namespace granule::app {

// Create `out` for a new run.  An existing directory with files in it is refused unless `force`,
// which removes the files a Granule run writes (and nothing else).
void prepare_new_output_directory(const std::string& out, bool force);
// Before a run continues: the outputs written only at a run's end (summary, collision statistics,
// picture) describe the earlier end, not the continued run.
void remove_end_of_run_outputs(const std::string& out);
// Before a run continues from an earlier snapshot frame: its outputs move to a new subdirectory
// `set_aside_after_frame_<K>` (returned), where nothing of them is lost.
std::string set_aside_run_outputs(const std::string& out, std::int64_t frame);
// The first `--set` key outside run.*, output.* and `also_allowed`, or "" (a resumed run keeps
// its physics).
std::string first_physics_override(const std::vector<std::string>& overrides, const std::vector<std::string>& also_allowed = {});
// Refuses (exit 5) a run whose estimated peak memory exceeds what the machine has available.
void check_memory_for_run(const RunConfig& config, const CellGrid& grid);

}  // namespace granule::app
