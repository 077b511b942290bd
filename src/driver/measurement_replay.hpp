// A run continued from one of its snapshot frames with measurements attached (`granule analyze
// collisions`): collisions are not stored, so the statistics that need them (impact parameters,
// free paths, the collisional stress) are measured after the fact.  The same physical state and
// clock with new round-off: a statistically equivalent trajectory, not the same bits.
#pragma once

#include <functional>
#include <cstdint>
#include <string>
#include <vector>

#include "io/config.hpp"
#include "io/snapshot_file.hpp"

namespace granule::driver {

// What a replay starts from: the run's config.toml in `run_dir` with `overrides` (the settings of
// [fields] and [collisions]) and its snapshot frame `frame` (negative counts from the end), checked
// to belong together.  A config refused throws ConfigError; a frame that cannot be read, or
// snapshots of another system, RunDirectoryRefused.
struct ReplayStart {
  RunConfig config;
  SnapshotRead snapshot;
};
ReplayStart replay_start(const std::string& run_dir, std::int64_t frame, const std::vector<std::string>& overrides);

struct ReplayOutcome {
  std::string error;                 // non-empty: the engine grid was refused, nothing was run
  std::string out;                   // the directory of the measurements and summary.json
  double collisions_per_particle = 0.0;  // c at the end
};

// Continues `snapshot`'s frame with the measurements of `config` ([fields], [collisions]) for
// `collisions_per_particle` more collisions per particle (or until no event or an inelastic
// collapse), writing them and summary.json into `out_dir(c at the start)`, which it creates.  A
// replay larger than the memory available throws NotEnoughMemory before anything is created.
ReplayOutcome replay_with_measurements(const RunConfig& config, const SnapshotRead& snapshot,
                                       double collisions_per_particle,
                                       const std::function<std::string(double c_start)>& out_dir);

}  // namespace granule::driver
