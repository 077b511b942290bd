#include "driver/run_session.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <filesystem>
#include <map>
#include <string_view>

#include "granule/version.hpp"
#include "io/atomic_file.hpp"
#include "io/checkpoint_file.hpp"
#include "io/timeseries_csv.hpp"

namespace granule::driver {

template <int D>
RunSession<D>::RunSession(const RunConfig& config, const CellGrid& grid, std::string out, const RunStart& start)
    : config_(config), grid_(grid), out_(std::move(out)), run_(config, grid, start, out_), sim_(run_.engine()) {
  until_collisions_ = collisions_for(config, config.until_collisions_per_particle);
  until_time_ = config.until_time.value_or(kInf);
}

template <int D>
RunSession<D>::RunSession(const RunConfig& config, const CellGrid& grid, std::string out, const StateArchive& checkpoint)
    : config_(config), grid_(grid), out_(std::move(out)), run_(config, grid, checkpoint, out_), sim_(run_.engine()) {
  has_checkpoint_ = true;
  earlier_wall_seconds_ = checkpoint.scalar("run/wall_seconds");
  if (!(earlier_wall_seconds_ >= 0.0 && std::isfinite(earlier_wall_seconds_))) {
    throw std::runtime_error("checkpoint entry run/wall_seconds is not a duration");
  }
  segment_start_collisions_ = sim_.collisions();
  until_collisions_ = collisions_for(config, config.until_collisions_per_particle);
  until_time_ = config.until_time.value_or(kInf);
  if (!in_production()) return;
  snapshotting_ = Schedule{config.snapshot_every_collisions_per_particle, config.snapshot_every_time};
  snapshotting_.start(config.system.particles);
  snapshotting_.restore(checkpoint, "run/snapshotting/", sim_);
  // A run extended past its old end has new run.* limits: the schedules continue regardless.
  snapshots_ = std::make_unique<SnapshotWriter>(out_ + "/snapshots.h5", checkpoint.count("run/snapshot_frames"));
  last_snapshot_events_ = checkpoint.integer("run/last_snapshot_events");
  // What the interrupted segment wrote after its checkpoint is not part of this run any more.
  write_timeseries();
}

template <int D>
RunSession<D>::RunSession(const RunConfig& config, const CellGrid& grid, std::string out, const FrameStart& start)
    : config_(config),
      grid_(grid),
      out_(std::move(out)),
      run_(config, grid, start.frame, start.samples, out_, start.kept),
      sim_(run_.engine()) {
  segment_start_collisions_ = sim_.collisions();
  until_collisions_ = collisions_for(config, config.until_collisions_per_particle);
  until_time_ = config.until_time.value_or(kInf);
  snapshotting_ = Schedule{config.snapshot_every_collisions_per_particle, config.snapshot_every_time};
  snapshotting_.start(config.system.particles);
  snapshotting_.advance(sim_);
  snapshots_ = std::make_unique<SnapshotWriter>(out_ + "/snapshots.h5", start.snapshot_frames);
  last_snapshot_events_ = sim_.events();
  write_timeseries();
}

// The snapshots of production: the first at its start.
template <int D>
void RunSession<D>::start_snapshots() {
  SnapshotMetadata metadata;
  metadata.system = config_.system;
  metadata.packing_fraction = config_.packing_fraction;
  metadata.boundary = boundary_kind_name(config_);
  metadata.seed = config_.seed;
  metadata.version = kVersion;
  metadata.diameters = sim_.diameters();
  metadata.masses = sim_.masses();
  snapshots_ = std::make_unique<SnapshotWriter>(out_ + "/snapshots.h5", metadata);
  append_snapshot();
  snapshotting_ = Schedule{config_.snapshot_every_collisions_per_particle, config_.snapshot_every_time};
  snapshotting_.start(config_.system.particles);
}

template <int D>
void RunSession<D>::save(StateArchive& archive) const {
  run_.save(archive);
  archive.put_scalar("run/wall_seconds", earlier_wall_seconds_ + progress_.seconds_since_start());
  if (!in_production()) return;
  snapshotting_.save(archive, "run/snapshotting/");
  archive.put_integer("run/snapshot_frames", snapshots_->frames());
  archive.put_integer("run/last_snapshot_events", last_snapshot_events_);
}

template <int D>
void RunSession<D>::write_checkpoint() {
  StateArchive archive = StateArchive::streaming();  // written at once, before the run moves on
  save(archive);
  if (in_production()) write_timeseries();  // the rows on disk include every row of the checkpoint
  granule::write_checkpoint(out_ + "/checkpoint.h5", archive, kVersion);
  last_checkpoint_wall_ = progress_.seconds_since_start();
  has_checkpoint_ = true;
}

template <int D>
void RunSession<D>::append_snapshot() {
  last_snapshot_events_ = sim_.events();
  // Written block by block from the engine: no copy of the whole state beside it (10^8 disks).
  snapshots_->append({{}, sim_.clock_state(), sim_.collisions_per_particle(), sim_.shear_offset(), sim_.strain(),
                      sim_.image_velocity()},
                     sim_.state_blocks());
}

template <int D>
void RunSession<D>::write_timeseries() const { granule::write_timeseries(out_ + "/timeseries.csv", samples()); }

template <int D>
void RunSession<D>::on_stop(Simulation<D>&) {
  if (snapshotting_.due(sim_)) {
    append_snapshot();
    snapshotting_.advance(sim_);
  }
  const double now = progress_.seconds_since_start();
  if (now - last_csv_wall_ > 10.0) {  // keep the file current on long runs
    write_timeseries();
    last_csv_wall_ = now;
  }
}

template <int D>
void RunSession<D>::report_progress() {
  const double fraction =
      std::max(until_collisions_ == kNoLimit ? 0.0 : static_cast<double>(sim_.collisions()) / static_cast<double>(until_collisions_),
               std::isfinite(until_time_) ? sim_.time() / until_time_ : 0.0);
  const double elapsed = progress_.seconds_since_start();
  const double done = static_cast<double>(sim_.collisions() - segment_start_collisions_);
  progress_.update(in_production() ? std::min(1.0, fraction) : 0.0, sim_.collisions_per_particle(), sim_.time(),
                   elapsed > 0.0 ? done / elapsed : 0.0);
}

template <int D>
StopReason RunSession<D>::run(const volatile std::sig_atomic_t* interrupt) {
  sim_.set_interrupt_flag(interrupt);
  // A run killed at any moment can be resumed: its first checkpoint holds the initial state.
  if (!has_checkpoint_) write_checkpoint();
  const std::int64_t chunk = std::max<std::int64_t>(1000, config_.system.particles / 4);  // progress granularity
  while (true) {
    StopReason reason;
    if (!in_production()) {
      reason = run_.prerun(chunk);
      if (reason == StopReason::kInterrupted) return reason;
      if (reason == StopReason::kNoEvents) {
        fmt::print(stderr, "granule run: the elastic pre-run has no events (all disks at rest?)\n");
      }
      if (in_production()) {
        segment_prerun_collisions_ = run_.prerun_collisions() - segment_start_collisions_;
        segment_start_collisions_ = 0;
        start_snapshots();
      }
    } else {
      reason = run_.advance({this}, {std::min(until_collisions_, sim_.collisions() + chunk), until_time_});
      if (reason == StopReason::kInterrupted) return reason;
      if (reason == StopReason::kInelasticCollapse || reason == StopReason::kNoEvents ||
          sim_.collisions() >= until_collisions_ || sim_.time() >= until_time_) {
        return reason;
      }
    }
    if (progress_.seconds_since_start() - last_checkpoint_wall_ >= config_.checkpoint_every_seconds) write_checkpoint();
    report_progress();
  }
}

template <int D>
nlohmann::json RunSession<D>::finish(StopReason reason) {
  progress_.finish();
  write_checkpoint();
  // The end-of-run outputs, after the checkpoint: a continuation drops them again.
  if (in_production()) {
    if (last_snapshot_events_ != sim_.events()) append_snapshot();
    run_.sample_at_stop();
    run_.measurements()->after_step(sim_, true);
    snapshots_->finish();
    write_timeseries();
  }
  const double segment_seconds = progress_.seconds_since_start();
  const RunFacts facts{earlier_wall_seconds_ + segment_seconds, segment_seconds, sim_.collisions() - segment_start_collisions_,
                       segment_prerun_collisions_, run_.equilibrate_collisions(), snapshot_frames()};
  nlohmann::json summary = summary_json(config_, sim_, grid_, reason, facts, samples());
  if (RunMeasurements<D>* measurements = run_.measurements()) summary["measurements"] = measurements->finish(sim_);
  for (const std::string& warning : run_warnings(config_)) summary["warnings"].push_back(warning);
  for (const auto& [name, schedule] : {std::pair{"output.every_time", &run_.sampling()}, {"output.snapshot_every_time", &snapshotting_}}) {
    if (schedule->rounded_up) {
      summary["warnings"].push_back(fmt::format("{} is below one ulp of the clock: rounded up", name));
    }
    if (schedule->skipped > 0) {
      summary["warnings"].push_back(fmt::format("{}: {} outputs skipped that fell between the same two events", name,
                                                schedule->skipped));
    }
  }
  write_file_atomically(out_ + "/summary.json", summary.dump(2) + "\n");
  return summary;
}

template <int D>
double RunSession<D>::mean_free_time() const {
  for (auto it = samples().rbegin(); it != samples().rend(); ++it) {
    if (it->collision_rate > 0.0) return 0.5 / it->collision_rate;
  }
  return sim_.collisions() > 0 ? 0.5 * sim_.time() / sim_.collisions_per_particle() : 0.0;
}

template class RunSession<2>;
template class RunSession<3>;

}  // namespace granule::driver
