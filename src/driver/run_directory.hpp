// The directory of a run: refuse to mix two runs' files, check that it can be written, set a
// continued run's later outputs aside, and estimate the memory a run needs, before anything is
// written.  Files that cannot be written or moved throw IoError.
#pragma once

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "cells/cell_grid.hpp"
#include "io/config.hpp"
#include "observers/global_diagnostics.hpp"
#include "observables/observable.hpp"

namespace granule::driver {

// A run directory a run may not begin in: a new run's directory with another run's files, or a
// continued run whose checkpoint or snapshots cannot be read or do not belong to its config.toml
// (the message names it and what to do instead).
struct RunDirectoryRefused : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Create `out` for a new run.  An existing directory with files in it is refused unless `force`,
// which removes the files a Granule run writes (and nothing else).
void prepare_new_output_directory(const std::string& out, bool force);
// Before a run continues: the outputs written only at a run's end (summary, collision statistics,
// picture) describe the earlier end, not the continued run.
void remove_end_of_run_outputs(const std::string& out);
// Before a run continues from an earlier snapshot frame: its outputs move to a new subdirectory
// `set_aside_after_frame_<K>` (returned), where nothing of them is lost.
std::string set_aside_run_outputs(const std::string& out, std::int64_t frame);

// The published or partial file `name` in the run directory `out` ("" if neither exists).
std::string existing_run_output(const std::string& out, const std::string& name);

// A run branching from snapshot frame K (index ≥ 0) at c collisions per particle: its outputs set
// aside (above), then snapshots.h5 and, when `fields` is measured, fields.h5 brought back as
// `.partial` files, with the time-series rows and fields frames up to c that the continued run
// keeps.
struct BranchedOutputs {
  std::string aside;                        // where the earlier outputs now are
  std::vector<DiagnosticsSample> samples;   // timeseries.csv's rows up to c
  FrameContinuation kept;                   // what the measurements' files keep
};
BranchedOutputs branch_run_outputs(const std::string& out, std::int64_t frame, double c, bool fields);

// The regular files under `out` (paths relative to it, sorted) modified since `since`.
std::vector<std::string> files_written_since(const std::string& out, std::filesystem::file_time_type since);

// The estimated peak memory of a run [bytes].
double estimated_run_bytes(const RunConfig& config, const CellGrid& grid);
// Available memory [bytes]: /proc/meminfo's MemAvailable, or the cgroup limit if that is smaller;
// 0 when neither can be read.
double available_memory_bytes();

}  // namespace granule::driver
