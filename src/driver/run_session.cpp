#include "driver/run_session.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <string_view>

#include "granule/version.hpp"
#include "io/atomic_file.hpp"
#include "io/checkpoint_file.hpp"
#include "io/timeseries_csv.hpp"

namespace granule::driver {

namespace {

// The coarse-graining grid of T̄ and κ: diagnostics.cells in 2D; in 3D the default of ~20 spheres
// per cell.
FieldGrid diagnostics_grid(const RunConfig& config) {
  const SystemParams& s = config.system;
  if (s.dimension == 3) return default_field_grid_3d(s.length_x, s.length_y, s.length_z, s.particles);
  return FieldGrid{config.diagnostic_cells.first, config.diagnostic_cells.second, s.length_x, s.length_y};
}

std::int64_t collisions_for(const RunConfig& config, std::optional<double> c) {
  return c ? std::llround(*c * static_cast<double>(config.system.particles)) : kNoLimit;
}

}  // namespace

template <int D>
RunSession<D>::RunSession(const RunConfig& config, const CellGrid& grid, std::string out, const ParticleState& initial,
                       const ClockState& clock)
    : config_(config), grid_(grid), out_(std::move(out)) {
  // The elastic pre-run of thesis §1.4.2; the restitution is switched on when it ends.
  sim_ = std::make_unique<Simulation<D>>(elastic_prerun(config.system), grid, initial, clock);
  equilibrate_collisions_ = std::llround(config.equilibrate * static_cast<double>(config.system.particles));
  until_collisions_ = collisions_for(config, config.until_collisions_per_particle);
  until_time_ = config.until_time.value_or(kInf);
}

template <int D>
RunSession<D>::RunSession(const RunConfig& config, const CellGrid& grid, std::string out, const StateArchive& checkpoint)
    : config_(config), grid_(grid), out_(std::move(out)) {
  sim_ = std::make_unique<Simulation<D>>(config.system, grid, checkpoint, "engine/");
  equilibrate_collisions_ = checkpoint.integer("run/equilibrate_collisions");
  earlier_wall_seconds_ = checkpoint.scalar("run/wall_seconds");
  segment_start_collisions_ = sim_->collisions();
  until_collisions_ = collisions_for(config, config.until_collisions_per_particle);
  until_time_ = config.until_time.value_or(kInf);
  if (checkpoint.integer("run/in_production") != 0) restore_production(checkpoint);
}

template <int D>
RunSession<D>::RunSession(const RunConfig& config, const CellGrid& grid, std::string out, const FrameStart& start)
    : config_(config), grid_(grid), out_(std::move(out)) {
  const SystemParams& system = config.system;
  sim_ = std::make_unique<Simulation<D>>(system, grid, start.frame.particles, start.frame.clock);
  segment_start_collisions_ = sim_->collisions();
  until_collisions_ = collisions_for(config, config.until_collisions_per_particle);
  until_time_ = config.until_time.value_or(kInf);
  diagnostics_ = std::make_unique<GlobalDiagnostics<D>>(system, diagnostics_grid(config));
  sim_->add_observer(diagnostics_.get());
  diagnostics_->restart_interval(sim_->time(), sim_->collisions());
  samples_ = start.samples;
  sampling_ = Schedule{config.sample_every_collisions_per_particle, config.sample_every_time};
  snapshotting_ = Schedule{config.snapshot_every_collisions_per_particle, config.snapshot_every_time};
  sampling_.start(system.particles);
  snapshotting_.start(system.particles);
  sampling_.advance(*sim_);
  snapshotting_.advance(*sim_);
  snapshots_ = std::make_unique<SnapshotWriter>(out_ + "/snapshots.h5", start.snapshot_frames);
  last_snapshot_events_ = sim_->events();
  measurements_ = std::make_unique<RunMeasurements<D>>(config, out_);
  measurements_->continue_from_frame(*sim_, {start.fields_frames, start.fields_frame_at_start});
  write_timeseries();
}

template <int D>
void RunSession<D>::start_production() {
  const SystemParams& system = config_.system;
  segment_prerun_collisions_ = sim_->collisions() - segment_start_collisions_;
  sim_->start_production(system);
  segment_start_collisions_ = 0;
  diagnostics_ = std::make_unique<GlobalDiagnostics<D>>(system, diagnostics_grid(config_));
  sim_->add_observer(diagnostics_.get());
  diagnostics_->restart_interval(sim_->time(), sim_->collisions());
  samples_.push_back(diagnostics_->sample(sim_->state_blocks(), sim_->time(), sim_->collisions(), sim_->image_velocity(),
                                          sim_->shear_offset()));
  SnapshotMetadata metadata;
  metadata.system = system;
  metadata.packing_fraction = config_.packing_fraction;
  metadata.boundary = boundary_kind_name(config_);
  metadata.seed = config_.seed;
  metadata.version = kVersion;
  metadata.diameters = sim_->diameters();
  metadata.masses = sim_->masses();
  snapshots_ = std::make_unique<SnapshotWriter>(out_ + "/snapshots.h5", metadata);
  append_snapshot();
  measurements_ = std::make_unique<RunMeasurements<D>>(config_, out_);
  measurements_->start(*sim_);
  sampling_ = Schedule{config_.sample_every_collisions_per_particle, config_.sample_every_time};
  snapshotting_ = Schedule{config_.snapshot_every_collisions_per_particle, config_.snapshot_every_time};
  sampling_.start(system.particles);
  snapshotting_.start(system.particles);
}

template <int D>
void RunSession<D>::restore_production(const StateArchive& archive) {
  const SystemParams& system = config_.system;
  diagnostics_ = std::make_unique<GlobalDiagnostics<D>>(system, diagnostics_grid(config_));
  diagnostics_->restore(archive, "diagnostics/");
  sim_->add_observer(diagnostics_.get());
  const std::size_t rows = archive.get<double>("run/samples/t").size();
  // The columns of this run (the optional groups of spin, gravity and walls as configured).
  const DiagnosticsSample layout = diagnostics_->layout();
  samples_.assign(rows, layout);
  for_each_column(layout, [&](const char* name, const double&) {
    const auto& column = archive.get_sized<double>(std::string("run/samples/") + name, rows);
    for (std::size_t k = 0; k < rows; ++k) {
      for_each_column(samples_[k], [&](const char* field, double& value) {
        if (field == std::string_view(name)) value = column[k];
      });
    }
  });
  sampling_ = Schedule{config_.sample_every_collisions_per_particle, config_.sample_every_time};
  snapshotting_ = Schedule{config_.snapshot_every_collisions_per_particle, config_.snapshot_every_time};
  sampling_.start(system.particles);
  snapshotting_.start(system.particles);
  sampling_.restore(archive, "run/sampling/", *sim_);
  snapshotting_.restore(archive, "run/snapshotting/", *sim_);
  // A run extended past its old end has new run.* limits: the schedules continue regardless.
  snapshots_ = std::make_unique<SnapshotWriter>(out_ + "/snapshots.h5", archive.integer("run/snapshot_frames"));
  last_snapshot_events_ = archive.integer("run/last_snapshot_events");
  measurements_ = std::make_unique<RunMeasurements<D>>(config_, out_);
  measurements_->resume(*sim_, archive, "measurements/");
  // What the interrupted segment wrote after its checkpoint is not part of this run any more.
  write_timeseries();
}

template <int D>
void RunSession<D>::save(StateArchive& archive) const {
  sim_->save(archive, "engine/");
  archive.put_integer("run/equilibrate_collisions", equilibrate_collisions_);
  archive.put_scalar("run/wall_seconds", earlier_wall_seconds_ + progress_.seconds_since_start());
  archive.put_integer("run/in_production", in_production() ? 1 : 0);
  if (!in_production()) return;
  diagnostics_->save(archive, "diagnostics/");
  std::map<std::string, std::vector<double>> columns;
  const DiagnosticsSample layout = diagnostics_->layout();
  for_each_column(layout, [&](const char* name, const double&) { columns[name].reserve(samples_.size()); });
  for (const DiagnosticsSample& sample : samples_) {
    for_each_column(sample, [&](const char* name, const double& value) { columns[name].push_back(value); });
  }
  for (auto& [name, column] : columns) archive.put("run/samples/" + name, std::move(column));
  sampling_.save(archive, "run/sampling/");
  snapshotting_.save(archive, "run/snapshotting/");
  archive.put_integer("run/snapshot_frames", snapshots_->frames());
  archive.put_integer("run/last_snapshot_events", last_snapshot_events_);
  measurements_->save(archive, "measurements/");
}

template <int D>
void RunSession<D>::write_checkpoint() {
  StateArchive archive = StateArchive::streaming();  // written at once, before the run moves on
  save(archive);
  if (in_production()) write_timeseries();  // the rows on disk include every row of the checkpoint
  granule::write_checkpoint(out_ + "/checkpoint.h5", archive, kVersion);
  last_checkpoint_wall_ = progress_.seconds_since_start();
}

template <int D>
void RunSession<D>::append_snapshot() {
  last_snapshot_events_ = sim_->events();
  // Written block by block from the engine: no copy of the whole state beside it (10^8 disks).
  snapshots_->append({{}, sim_->clock_state(), sim_->collisions_per_particle(), sim_->shear_offset(), sim_->strain(),
                      sim_->image_velocity()},
                     sim_->state_blocks());
}

template <int D>
void RunSession<D>::take_sample() {
  const StateBlocks state = sim_->state_blocks();
  samples_.push_back(
      diagnostics_->sample(state, sim_->time(), sim_->collisions(), sim_->image_velocity(), sim_->shear_offset()));
  measurements_->on_sample(state, sim_->collisions(), sim_->image_velocity());
}

template <int D>
void RunSession<D>::write_timeseries() const { granule::write_timeseries(out_ + "/timeseries.csv", samples_); }

template <int D>
void RunSession<D>::on_stop(Simulation<D>&) {
  if (snapshotting_.due(*sim_)) {
    append_snapshot();
    snapshotting_.advance(*sim_);
  }
  if (sampling_.due(*sim_)) {
    take_sample();
    sampling_.advance(*sim_);
    const double now = progress_.seconds_since_start();
    if (now - last_csv_wall_ > 10.0) {  // keep the file current on long runs
      write_timeseries();
      last_csv_wall_ = now;
    }
  }
}

template <int D>
void RunSession<D>::report_progress() {
  const double fraction =
      std::max(until_collisions_ == kNoLimit ? 0.0 : static_cast<double>(sim_->collisions()) / static_cast<double>(until_collisions_),
               std::isfinite(until_time_) ? sim_->time() / until_time_ : 0.0);
  const double elapsed = progress_.seconds_since_start();
  const double done = static_cast<double>(sim_->collisions() - segment_start_collisions_);
  progress_.update(in_production() ? std::min(1.0, fraction) : 0.0, sim_->collisions_per_particle(), sim_->time(),
                   elapsed > 0.0 ? done / elapsed : 0.0);
}

template <int D>
StopReason RunSession<D>::run(const volatile std::sig_atomic_t* interrupt) {
  sim_->set_interrupt_flag(interrupt);
  const std::int64_t chunk = std::max<std::int64_t>(1000, config_.system.particles / 4);  // progress granularity
  while (true) {
    StopReason reason;
    if (!in_production()) {
      reason = sim_->run(kInf, std::min(equilibrate_collisions_, sim_->collisions() + chunk));
      if (reason == StopReason::kInterrupted) return reason;
      if (reason == StopReason::kNoEvents) {
        fmt::print(stderr, "granule run: the elastic pre-run has no events (all disks at rest?)\n");
      }
      if (reason == StopReason::kNoEvents || sim_->collisions() >= equilibrate_collisions_) start_production();
    } else {
      // Outputs first, then the measurements: a sample joins the fields' interval before a frame.
      reason = advance_to_next_stop(*sim_, {this, measurements_.get()},
                                    {std::min(until_collisions_, sim_->collisions() + chunk), until_time_});
      if (reason == StopReason::kInterrupted) return reason;
      if (reason == StopReason::kInelasticCollapse || reason == StopReason::kNoEvents ||
          sim_->collisions() >= until_collisions_ || sim_->time() >= until_time_) {
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
    if (last_snapshot_events_ != sim_->events()) append_snapshot();
    if (samples_.back().c != sim_->collisions_per_particle() || samples_.back().t != sim_->time()) take_sample();
    measurements_->after_step(*sim_, true);
    snapshots_->finish();
    write_timeseries();
  }
  const double segment_seconds = progress_.seconds_since_start();
  const RunFacts facts{earlier_wall_seconds_ + segment_seconds, segment_seconds, sim_->collisions() - segment_start_collisions_,
                       segment_prerun_collisions_, equilibrate_collisions_, snapshot_frames()};
  nlohmann::json summary = summary_json(config_, *sim_, grid_, reason, facts, samples_);
  if (measurements_) summary["measurements"] = measurements_->finish(*sim_);
  for (const auto& [name, schedule] : {std::pair{"output.every_time", &sampling_}, {"output.snapshot_every_time", &snapshotting_}}) {
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

template class RunSession<2>;
template class RunSession<3>;

}  // namespace granule::driver
