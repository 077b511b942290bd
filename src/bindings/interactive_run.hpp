// A run of the engine driven step by step from a host language (the Python
// module): the lifecycle of `granule run` (driver/run_lifecycle.hpp: its initial
// state, elastic pre-run of thesis §1.4.2 and time series), with production run
// to limits the caller chooses.  It writes no file unless asked
// (write_snapshot).  The trajectory is that of `granule run` for the same
// configuration, bit for bit: the engine's does not depend on where it is
// stopped (engine/simulation.hpp).
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "driver/run_lifecycle.hpp"
#include "driver/run_start.hpp"
#include "driver/run_summary.hpp"
#include "engine/simulation.hpp"
#include "io/config.hpp"

namespace granule::bindings {

// A configuration `granule run` would refuse with exit code 2: the message
// names the key, the value and the allowed range, as the command line's does.
using ConfigError = driver::ConfigError;

// The parsed configuration of TOML text or a file, with `--set`-style overrides
// "section.key=value".
RunConfig parse_run_config(const std::string& toml_text, const std::vector<std::string>& overrides);
RunConfig load_run_config(const std::string& path, const std::vector<std::string>& overrides);

// Limits of one call of run(): absolute collisions per particle and time since
// production started.  Those given replace the configuration's run.until_*, which
// apply when neither is given.
struct RunLimits {
  std::optional<double> collisions_per_particle;
  std::optional<double> time;
};

// Where one call of run() stops: total collisions and time (kNoLimit, ∞: none).
struct RunTargets {
  std::int64_t collisions = driver::kNoLimit;
  double time = driver::kInf;
};

template <int D>
class InteractiveRun {
 public:
  // The initial state of the configuration (driver/run_start.hpp).
  explicit InteractiveRun(const RunConfig& config);

  // The elastic pre-run (initial.equilibrate), then production starts at t = 0.
  // `keep_going` is asked between chunks of max(1000, N/4) collisions; false
  // stops with kInterrupted.
  StopReason equilibrate(const std::function<bool()>& keep_going);
  // The targets of `limits`.  Throws std::invalid_argument, naming the argument,
  // its allowed range and the present c or t, for a limit that is not a finite
  // number, lies beyond the engine's counters (c·N ≤ 2^62, kMaxCollisions) or is
  // reached already (a run that would do nothing).
  RunTargets targets(const RunLimits& limits) const;
  // Production up to `targets`; the time series gains a last row at the stop
  // (as a run's end).
  StopReason run(const RunTargets& targets, const std::function<bool()>& keep_going);

  const Simulation<D>& engine() const { return run_.engine(); }
  const RunConfig& config() const { return config_; }
  const std::vector<DiagnosticsSample>& samples() const { return run_.samples(); }
  bool in_production() const { return run_.in_production(); }
  // summary.json's content for the run so far, stopped for `reason`.
  nlohmann::json summary(StopReason reason) const;
  // Appends the present state as a frame of the snapshot file `path` (created
  // with this run's metadata when it does not exist), schema of snapshots.h5;
  // the file is complete after each call.
  void write_snapshot(const std::string& path) const;

 private:
  RunConfig config_;
  CellGrid grid_;
  driver::RunLifecycle<D> run_;
  double wall_seconds_ = 0.0;
};

}  // namespace granule::bindings
