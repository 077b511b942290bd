// One `granule run` in its output directory: the engine, the elastic pre-run of thesis §1.4.2,
// the time series, snapshots and measurements, driven by one loop; checkpoints of all of it.
//
// A checkpoint holds everything that decides what the run writes from then on (engine, open
// measurement intervals, schedules, the time-series rows so far, how many frames each file has),
// so a run continued from one writes, bit for bit, what the uninterrupted run would have written.
// Checkpoints are taken every `output.checkpoint_every_seconds` of wall time, on SIGINT/SIGTERM,
// and when the run ends — always before the extra end-of-run outputs (a last snapshot and row),
// which a continuation drops together with anything else written after its checkpoint.
#pragma once

#include <csignal>
#include <memory>
#include <string>
#include <vector>

#include "driver/progress.hpp"
#include "driver/run_lifecycle.hpp"
#include "driver/run_summary.hpp"
#include "observers/schedule.hpp"
#include "driver/stop_loop.hpp"
#include "engine/simulation.hpp"
#include "io/config.hpp"
#include "io/snapshot_file.hpp"

namespace granule::driver {

// The session is the stop client of its snapshots; the time series and the measurements are the
// lifecycle's (driver/run_lifecycle.hpp).
template <int D>
class RunSession final : public StopClient<D> {
 public:
  // A new run into the existing, empty directory `out` from `start` (driver/run_start.hpp).
  RunSession(const RunConfig& config, const CellGrid& grid, std::string out, const RunStart& start);
  // A run continued from its checkpoint in `out`.
  RunSession(const RunConfig& config, const CellGrid& grid, std::string out, const StateArchive& checkpoint);
  // A run continued from snapshot frame K in `out` (whose later frames and rows were set aside):
  // the same physical state and clock with new round-off, measurements restarted at the frame.
  struct FrameStart {
    SnapshotFrame frame;
    std::int64_t snapshot_frames = 0;  // frames 0..K kept in snapshots.h5
    std::vector<DiagnosticsSample> samples;  // rows up to the frame
    FrameContinuation kept;            // what the measurements' files keep
  };
  RunSession(const RunConfig& config, const CellGrid& grid, std::string out, const FrameStart& start);

  // Run until the configured end, collapse, no events, or `*interrupt` (set by a signal).
  StopReason run(const volatile std::sig_atomic_t* interrupt);
  // The checkpoint, the end-of-run outputs and summary.json.  Returns the summary.
  nlohmann::json finish(StopReason reason);

  const Simulation<D>& simulation() const { return run_.engine(); }
  const std::vector<DiagnosticsSample>& samples() const { return run_.samples(); }
  std::int64_t snapshot_frames() const { return snapshots_ ? snapshots_->frames() : 0; }
  // The mean free time per particle over the last sampled interval (each collision involves two).
  double mean_free_time() const;

  std::int64_t next_collisions() const override { return snapshotting_.next_collisions; }
  double next_time() const override { return snapshotting_.next_time; }
  // A snapshot, if due at the present stop.
  void on_stop(Simulation<D>& sim) override;

 private:
  bool in_production() const { return run_.in_production(); }
  void start_snapshots();
  void append_snapshot();
  void write_timeseries() const;
  void write_checkpoint();
  void save(StateArchive& archive) const;
  void report_progress();

  RunConfig config_;
  CellGrid grid_;
  std::string out_;
  RunLifecycle<D> run_;
  Simulation<D>& sim_;
  std::int64_t until_collisions_ = kNoLimit;
  double until_time_ = kInf;

  // Production (after the pre-run).
  Schedule snapshotting_;
  std::unique_ptr<SnapshotWriter> snapshots_;
  std::int64_t last_snapshot_events_ = -1;

  Progress progress_;
  double earlier_wall_seconds_ = 0.0;  // of the segments before a resume
  std::int64_t segment_start_collisions_ = 0;
  std::int64_t segment_prerun_collisions_ = 0;  // executed by this invocation before production
  double last_checkpoint_wall_ = 0.0;
  bool has_checkpoint_ = false;  // a new run writes its first checkpoint before its first event
  double last_csv_wall_ = 0.0;
};

}  // namespace granule::driver
