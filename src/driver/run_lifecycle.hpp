// The course of one run, shared by `granule run` (RunSession, also a sweep's points) and the
// Python Simulation (bindings/InteractiveRun): the engine in the elastic pre-run of thesis §1.4.2,
// the switch to production, the time series sampled on its schedule, the measurements of
// [fields] and [collisions] when the run has a directory to write them to, and the last row at a
// stop.  What a front end adds (snapshots, checkpoint files, progress, limits chosen from Python)
// stays with it; since the engine's trajectory ignores where it is stopped, every front end
// follows the same trajectory bit for bit.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "driver/run_measurements.hpp"
#include "driver/run_start.hpp"
#include "observers/schedule.hpp"
#include "driver/stop_loop.hpp"
#include "engine/simulation.hpp"
#include "io/config.hpp"
#include "io/snapshot_file.hpp"
#include "observers/global_diagnostics.hpp"

namespace granule::driver {

// The coarse-graining grid of T̄ and κ: diagnostics.cells in 2D; in 3D the default of ~20 spheres
// per cell.
FieldGrid diagnostics_grid(const RunConfig& config);
// A number of collisions per particle as a collision count of the run (none: no limit).
std::int64_t collisions_for(const RunConfig& config, std::optional<double> collisions_per_particle);

// The lifecycle is itself the stop client of its time series; the measurements are another.
template <int D>
class RunLifecycle final : public StopClient<D> {
 public:
  // A new run at `start`, in the elastic pre-run.  `out_dir`: where the measurements write (none:
  // no measurements).
  RunLifecycle(const RunConfig& config, const CellGrid& grid, const RunStart& start, std::optional<std::string> out_dir);
  // A run continued from its checkpoint.
  RunLifecycle(const RunConfig& config, const CellGrid& grid, const StateArchive& checkpoint, std::string out_dir);
  // A run continued from a snapshot frame, in production at once: the rows `samples` kept, the
  // measurements restarted at the frame with the files as `kept` says.
  RunLifecycle(const RunConfig& config, const CellGrid& grid, const SnapshotFrame& frame,
               std::vector<DiagnosticsSample> samples, std::string out_dir, const FrameContinuation& kept);

  // At most `chunk` more collisions of the elastic pre-run; production starts when it ends (or
  // when it has no events).
  StopReason prerun(std::int64_t chunk);
  // Production to the earliest stop of the time series, `clients` and the measurements (in this
  // order at a stop) within `limits`.
  StopReason advance(const std::vector<StopClient<D>*>& clients, const StopLimits& limits);
  // The last row of a stop, unless a scheduled one was taken there.
  void sample_at_stop();
  // The engine, the pre-run's end, production (time series, measurements): under engine/, run/,
  // diagnostics/, measurements/.
  void save(StateArchive& archive) const;

  Simulation<D>& engine() { return *sim_; }
  const Simulation<D>& engine() const { return *sim_; }
  bool in_production() const { return diagnostics_ != nullptr; }
  std::int64_t equilibrate_collisions() const { return equilibrate_collisions_; }
  // The collisions of the pre-run when production started (0 before).
  std::int64_t prerun_collisions() const { return prerun_collisions_; }
  const std::vector<DiagnosticsSample>& samples() const { return samples_; }
  const Schedule& sampling() const { return sampling_; }
  RunMeasurements<D>* measurements() { return measurements_.get(); }

  std::int64_t next_collisions() const override { return sampling_.next_collisions; }
  double next_time() const override { return sampling_.next_time; }
  void on_stop(Simulation<D>& sim) override;

 private:
  void start_production();
  // Refuses (InputError, listing the keys) a configuration whose physics differs from the one
  // recorded in the checkpoint.
  void check_same_physics(const StateArchive& checkpoint) const;
  void attach_diagnostics();
  void take_sample();
  void restore_production(const StateArchive& archive);

  RunConfig config_;
  std::optional<std::string> out_dir_;
  std::unique_ptr<Simulation<D>> sim_;
  std::int64_t equilibrate_collisions_ = 0;
  std::int64_t prerun_collisions_ = 0;
  std::unique_ptr<GlobalDiagnostics<D>> diagnostics_;
  std::vector<DiagnosticsSample> samples_;
  Schedule sampling_;
  std::unique_ptr<RunMeasurements<D>> measurements_;
};

}  // namespace granule::driver
