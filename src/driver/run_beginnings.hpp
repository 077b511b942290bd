// The three beginnings of a run in its directory (`granule run`): a new run, a run resumed from its
// checkpoint, and a run continued from one of its snapshot frames with the later outputs set aside
// (ARCHITECTURE.md, "Checkpoints, snapshots and restart").  Everything is checked before the run
// writes: a configuration or a directory refused throws ConfigError or RunDirectoryRefused, a run
// larger than the memory available NotEnoughMemory; each message is complete.
#pragma once

#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "driver/run_directory.hpp"
#include "driver/run_session.hpp"
#include "driver/run_start.hpp"

namespace granule::driver {

// A run whose estimated peak memory exceeds what the machine has available.
struct NotEnoughMemory : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The configuration of a run, with the `overrides` (KEY=VALUE, --set) applied: a continued run's
// own `continued/config.toml`, in which only run.* and output.* keys may change (from a frame also
// system.tc_duration: the way out of an inelastic collapse) — anything else would be another run;
// else the file `config_path`, or the built-in example when it is empty.
RunConfig run_configuration(const std::string& config_path, const std::string& continued, bool from_frame,
                            const std::vector<std::string>& overrides);

// Throws NotEnoughMemory, with the estimate and what is available, when `needed_bytes` exceed the
// available memory (available_memory_bytes; nothing is refused where it cannot be read).  `what`
// names the work: "a run of N = 1000".
void require_memory(double needed_bytes, const std::string& what);
// The same for the estimate of a run's peak memory (estimated_run_bytes).
void check_run_memory(const RunConfig& config, const CellGrid& grid);

// A new run in `out` (created; an earlier run's files replaced only when `force`), its resolved
// config.toml written.
template <int D>
std::unique_ptr<RunSession<D>> begin_new_run(const RunConfig& config, const CellGrid& grid, const std::string& out, bool force);

// The run in `out` continued from its checkpoint, bit for bit.
template <int D>
std::unique_ptr<RunSession<D>> resume_run(const RunConfig& config, const CellGrid& grid, const std::string& out);

// The run in `out` continued from snapshot frame `frame` (negative counts from the end).
template <int D>
struct BranchedRun {
  std::unique_ptr<RunSession<D>> session;
  std::int64_t frame = 0;  // the frame's index, ≥ 0
  double time = 0.0, collisions_per_particle = 0.0;
  std::string aside;       // where the outputs written after the frame now are
};
template <int D>
BranchedRun<D> branch_run_from_frame(const RunConfig& config, const CellGrid& grid, const std::string& out, std::int64_t frame);

}  // namespace granule::driver
