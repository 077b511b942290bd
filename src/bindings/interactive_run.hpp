// A run of the engine driven step by step from a host language (the Python
// module): the initial state and elastic pre-run of `granule run` (thesis
// §1.4.2), then production runs to limits the caller chooses, recording the
// time series on the configured schedule.  It writes no file unless asked
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

#include "driver/run_summary.hpp"
#include "driver/schedule.hpp"
#include "driver/stop_loop.hpp"
#include "engine/simulation.hpp"
#include "io/config.hpp"
#include "observers/global_diagnostics.hpp"

namespace granule::bindings {

// A configuration `granule run` would refuse with exit code 2: the message
// names the key, the value and the allowed range, as the command line's does.
class ConfigError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// The parsed configuration of TOML text or a file, with `--set`-style overrides
// "section.key=value".
RunConfig parse_run_config(const std::string& toml_text, const std::vector<std::string>& overrides);
RunConfig load_run_config(const std::string& path, const std::vector<std::string>& overrides);

// Limits of one call of run(): absolute collisions per particle and time since
// production started (absent: the configuration's run.until_*).
struct RunLimits {
  std::optional<double> collisions_per_particle;
  std::optional<double> time;
};

template <int D>
class InteractiveRun final : public driver::StopClient<D> {
 public:
  // The initial state of the configuration (initial.from is refused: it needs a
  // run directory).
  explicit InteractiveRun(const RunConfig& config);

  // The elastic pre-run (initial.equilibrate), then production starts at t = 0.
  // `keep_going` is asked between chunks of max(1000, N/4) collisions; false
  // stops with kInterrupted.
  StopReason equilibrate(const std::function<bool()>& keep_going);
  // Production up to `limits`; the time series gains a last row at the stop (as
  // a run's end).
  StopReason run(const RunLimits& limits, const std::function<bool()>& keep_going);

  const Simulation<D>& engine() const { return *sim_; }
  const RunConfig& config() const { return config_; }
  const std::vector<DiagnosticsSample>& samples() const { return samples_; }
  bool in_production() const { return diagnostics_ != nullptr; }
  // summary.json's content for the run so far, stopped for `reason`.
  nlohmann::json summary(StopReason reason) const;
  // Appends the present state as a frame of the snapshot file `path` (created
  // with this run's metadata when it does not exist), schema of snapshots.h5;
  // the file is complete after each call.
  void write_snapshot(const std::string& path) const;

  std::int64_t next_collisions() const override { return sampling_.next_collisions; }
  double next_time() const override { return sampling_.next_time; }
  void on_stop(Simulation<D>& sim) override;

 private:
  void start_production();
  void take_sample();

  RunConfig config_;
  CellGrid grid_;
  std::unique_ptr<Simulation<D>> sim_;
  std::int64_t equilibrate_collisions_ = 0;
  std::int64_t prerun_collisions_ = 0;
  std::unique_ptr<GlobalDiagnostics<D>> diagnostics_;
  std::vector<DiagnosticsSample> samples_;
  driver::Schedule sampling_;
  double wall_seconds_ = 0.0;
};

}  // namespace granule::bindings
