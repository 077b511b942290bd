#include "driver/run_lifecycle.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdint>
#include <map>
#include <string_view>
#include <utility>

#include "io/config_compare.hpp"
#include "io/io_error.hpp"

namespace granule::driver {

namespace {
// The run's resolved configuration (to_toml), as bytes: a resume compares it with its own.
constexpr const char* kConfigEntry = "run/config";
}  // namespace

FieldGrid diagnostics_grid(const RunConfig& config) {
  const SystemParams& s = config.system;
  if (s.dimension == 3) return default_field_grid_3d(s.length_x, s.length_y, s.length_z, s.particles);
  return FieldGrid{config.diagnostic_cells.first, config.diagnostic_cells.second, s.length_x, s.length_y};
}

std::int64_t collisions_for(const RunConfig& config, std::optional<double> c) {
  return c ? std::llround(*c * static_cast<double>(config.system.particles)) : kNoLimit;
}

template <int D>
RunLifecycle<D>::RunLifecycle(const RunConfig& config, const CellGrid& grid, const RunStart& start,
                              std::optional<std::string> out_dir)
    : config_(config), out_dir_(std::move(out_dir)) {
  // The elastic pre-run of thesis §1.4.2; the restitution is switched on when it ends.
  sim_ = std::make_unique<Simulation<D>>(elastic_prerun(config.system), grid, start.particles, start.clock);
  equilibrate_collisions_ = collisions_for(config, config.equilibrate);
}

template <int D>
RunLifecycle<D>::RunLifecycle(const RunConfig& config, const CellGrid& grid, const StateArchive& checkpoint,
                              std::string out_dir)
    : config_(config), out_dir_(std::move(out_dir)) {
  check_same_physics(checkpoint);
  // The engine checks the checkpoint against the parameters the run has at it: the elastic
  // pre-run's until production starts.
  const bool production = checkpoint.integer("run/in_production") != 0;
  sim_ = std::make_unique<Simulation<D>>(production ? config.system : elastic_prerun(config.system), grid, checkpoint, "engine/");
  equilibrate_collisions_ = checkpoint.count("run/equilibrate_collisions");
  if (production) restore_production(checkpoint);
}

template <int D>
RunLifecycle<D>::RunLifecycle(const RunConfig& config, const CellGrid& grid, const SnapshotFrame& frame,
                              std::vector<DiagnosticsSample> samples, std::string out_dir, const FrameContinuation& kept)
    : config_(config), out_dir_(std::move(out_dir)) {
  sim_ = std::make_unique<Simulation<D>>(config.system, grid, frame.particles, frame.clock);
  attach_diagnostics();
  samples_ = std::move(samples);
  sampling_.advance(*sim_);
  measurements_ = std::make_unique<RunMeasurements<D>>(config_, *out_dir_);
  measurements_->continue_from_frame(*sim_, kept);
}

template <int D>
void RunLifecycle<D>::check_same_physics(const StateArchive& checkpoint) const {
  const std::vector<std::uint8_t>& saved = checkpoint.get<std::uint8_t>(kConfigEntry);
  const std::vector<std::string> differences = physics_differences(std::string(saved.begin(), saved.end()), to_toml(config_));
  if (differences.empty()) return;
  std::string text = "the configuration is not the one the checkpoint was written with (only run.* and output.* may change):";
  for (const std::string& difference : differences) text += "\n  " + difference;
  throw InputError(text);
}

template <int D>
void RunLifecycle<D>::attach_diagnostics() {
  diagnostics_ = std::make_unique<GlobalDiagnostics<D>>(config_.system, diagnostics_grid(config_));
  sim_->add_observer(diagnostics_.get());
  diagnostics_->restart_interval(sim_->time(), sim_->collisions());
  sampling_ = Schedule{config_.sample_every_collisions_per_particle, config_.sample_every_time};
  sampling_.start(config_.system.particles);
}

template <int D>
void RunLifecycle<D>::start_production() {
  prerun_collisions_ = sim_->collisions();
  sim_->start_production(config_.system);
  attach_diagnostics();
  take_sample();
  if (!out_dir_) return;
  measurements_ = std::make_unique<RunMeasurements<D>>(config_, *out_dir_);
  measurements_->start(*sim_);
}

template <int D>
void RunLifecycle<D>::restore_production(const StateArchive& archive) {
  diagnostics_ = std::make_unique<GlobalDiagnostics<D>>(config_.system, diagnostics_grid(config_));
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
  // The rows of the time series the run continues: taken at finite, increasing t and c, none after now.
  for (std::size_t k = 0; k < rows; ++k) {
    const DiagnosticsSample& row = samples_[k];
    const bool ordered = k == 0 || (row.t >= samples_[k - 1].t && row.c >= samples_[k - 1].c);
    if (!std::isfinite(row.t) || !std::isfinite(row.c) || !ordered || row.t > sim_->time()) {
      throw InputError(fmt::format("checkpoint entries run/samples: row {} has t = {}, c = {}; expected finite times and "
                                   "collision counts, increasing, none after the checkpoint's t = {}",
                                   k, row.t, row.c, sim_->time()));
    }
  }
  sampling_ = Schedule{config_.sample_every_collisions_per_particle, config_.sample_every_time};
  sampling_.start(config_.system.particles);
  sampling_.restore(archive, "run/sampling/", *sim_);
  measurements_ = std::make_unique<RunMeasurements<D>>(config_, *out_dir_);
  measurements_->resume(*sim_, archive, "measurements/");
}

template <int D>
void RunLifecycle<D>::save(StateArchive& archive) const {
  sim_->save(archive, "engine/");
  const std::string toml = to_toml(config_);
  archive.put(kConfigEntry, std::vector<std::uint8_t>(toml.begin(), toml.end()));
  archive.put_integer("run/equilibrate_collisions", equilibrate_collisions_);
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
  if (measurements_) measurements_->save(archive, "measurements/");
}

template <int D>
StopReason RunLifecycle<D>::prerun(std::int64_t chunk) {
  const StopReason reason = sim_->run(kInf, std::min(equilibrate_collisions_, sim_->collisions() + chunk));
  if (reason == StopReason::kInterrupted) return reason;
  if (reason == StopReason::kNoEvents || sim_->collisions() >= equilibrate_collisions_) start_production();
  return reason;
}

template <int D>
StopReason RunLifecycle<D>::advance(const std::vector<StopClient<D>*>& clients, const StopLimits& limits) {
  // The time series first, then the outputs, then the measurements: a sample joins the fields'
  // interval before a frame.
  std::vector<StopClient<D>*> all{this};
  all.insert(all.end(), clients.begin(), clients.end());
  if (measurements_) all.push_back(measurements_.get());
  return advance_to_next_stop(*sim_, all, limits);
}

template <int D>
void RunLifecycle<D>::take_sample() {
  const StateBlocks state = sim_->state_blocks();
  samples_.push_back(
      diagnostics_->sample(state, sim_->time(), sim_->collisions(), sim_->image_velocity(), sim_->shear_offset()));
  if (measurements_) measurements_->on_sample(state, sim_->collisions(), sim_->image_velocity());
}

template <int D>
void RunLifecycle<D>::on_stop(Simulation<D>&) {
  if (!sampling_.due(*sim_)) return;
  take_sample();
  sampling_.advance(*sim_);
}

template <int D>
void RunLifecycle<D>::sample_at_stop() {
  if (samples_.back().c != sim_->collisions_per_particle() || samples_.back().t != sim_->time()) take_sample();
}

template class RunLifecycle<2>;
template class RunLifecycle<3>;

}  // namespace granule::driver
