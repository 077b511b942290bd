#include "bindings/interactive_run.hpp"

#include <algorithm>
#include <chrono>
#include <filesystem>

#include "bindings/new_run_state.hpp"
#include "granule/version.hpp"
#include "io/snapshot_file.hpp"

namespace granule::bindings {

namespace {

RunConfig parsed_or_thrown(const ConfigResult& parsed) {
  if (!parsed.config) throw ConfigError(parsed.error);
  if (parsed.config->initial_from) {
    throw ConfigError(
        "initial.from: starting from another run's snapshots is "
        "done by `granule run`, not by "
        "granule.Simulation (which has no run directory)");
  }
  return *parsed.config;
}

// The coarse-graining grid of T̄ and κ, as the time series of `granule run` has
// it.
FieldGrid diagnostics_grid(const RunConfig& config) {
  const SystemParams& s = config.system;
  if (s.dimension == 3) return default_field_grid_3d(s.length_x, s.length_y, s.length_z, s.particles);
  return FieldGrid{config.diagnostic_cells.first, config.diagnostic_cells.second, s.length_x, s.length_y};
}

std::int64_t collisions_for(const RunConfig& config, std::optional<double> c) {
  return c ? std::llround(*c * static_cast<double>(config.system.particles)) : driver::kNoLimit;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

RunConfig parse_run_config(const std::string& toml_text, const std::vector<std::string>& overrides) {
  return parsed_or_thrown(parse_config(toml_text, overrides));
}

RunConfig load_run_config(const std::string& path, const std::vector<std::string>& overrides) {
  return parsed_or_thrown(load_config_file(path, overrides));
}

template <int D>
InteractiveRun<D>::InteractiveRun(const RunConfig& config) : config_(config) {
  NewRunState start = new_run_state(config);
  grid_ = start.grid;
  sim_ = std::make_unique<Simulation<D>>(elastic_prerun(config.system), grid_, start.particles, start.clock);
  equilibrate_collisions_ = std::llround(config.equilibrate * static_cast<double>(config.system.particles));
}

template <int D>
StopReason InteractiveRun<D>::equilibrate(const std::function<bool()>& keep_going) {
  const auto start = std::chrono::steady_clock::now();
  const std::int64_t chunk = std::max<std::int64_t>(1000, config_.system.particles / 4);
  StopReason reason = StopReason::kCollisionsReached;
  // The same sequence of engine calls as RunSession::run before production.
  while (!in_production()) {
    if (!keep_going()) {
      reason = StopReason::kInterrupted;
      break;
    }
    reason = sim_->run(driver::kInf, std::min(equilibrate_collisions_, sim_->collisions() + chunk));
    if (reason == StopReason::kNoEvents || sim_->collisions() >= equilibrate_collisions_) start_production();
  }
  wall_seconds_ += seconds_since(start);
  return reason;
}

template <int D>
void InteractiveRun<D>::start_production() {
  const SystemParams& system = config_.system;
  prerun_collisions_ = sim_->collisions();
  sim_->start_production(system);
  diagnostics_ = std::make_unique<GlobalDiagnostics<D>>(system, diagnostics_grid(config_));
  sim_->add_observer(diagnostics_.get());
  diagnostics_->restart_interval(sim_->time(), sim_->collisions());
  take_sample();
  sampling_ = driver::Schedule{config_.sample_every_collisions_per_particle, config_.sample_every_time};
  sampling_.start(system.particles);
}

template <int D>
void InteractiveRun<D>::take_sample() {
  samples_.push_back(diagnostics_->sample(sim_->state_blocks(), sim_->time(), sim_->collisions(),
                                          sim_->image_velocity(), sim_->shear_offset()));
}

template <int D>
void InteractiveRun<D>::on_stop(Simulation<D>&) {
  if (!sampling_.due(*sim_)) return;
  take_sample();
  sampling_.advance(*sim_);
}

template <int D>
StopReason InteractiveRun<D>::run(const RunLimits& limits, const std::function<bool()>& keep_going) {
  if (!in_production()) throw std::logic_error("InteractiveRun::run before equilibrate");
  const auto start = std::chrono::steady_clock::now();
  const std::int64_t until_collisions = collisions_for(
      config_, limits.collisions_per_particle ? limits.collisions_per_particle : config_.until_collisions_per_particle);
  const double until_time = limits.time ? *limits.time : config_.until_time.value_or(driver::kInf);
  const std::int64_t chunk = std::max<std::int64_t>(1000, config_.system.particles / 4);
  // A limit already reached (the loop runs no event) is reported as such.
  StopReason reason = sim_->time() >= until_time ? StopReason::kTimeReached : StopReason::kCollisionsReached;
  while (sim_->collisions() < until_collisions && sim_->time() < until_time) {
    if (!keep_going()) {
      reason = StopReason::kInterrupted;
      break;
    }
    reason = driver::advance_to_next_stop(*sim_, {this},
                                          {std::min(until_collisions, sim_->collisions() + chunk), until_time});
    if (reason == StopReason::kInelasticCollapse || reason == StopReason::kNoEvents) break;
  }
  // The last row of a run's end (RunSession::finish), unless a scheduled one
  // was taken here.
  if (samples_.back().c != sim_->collisions_per_particle() || samples_.back().t != sim_->time()) take_sample();
  wall_seconds_ += seconds_since(start);
  return reason;
}

template <int D>
nlohmann::json InteractiveRun<D>::summary(StopReason reason) const {
  const driver::RunFacts facts{wall_seconds_,      wall_seconds_,           sim_->collisions(),
                               prerun_collisions_, equilibrate_collisions_, 0};
  return driver::summary_json(config_, *sim_, grid_, reason, facts, samples_);
}

template <int D>
void InteractiveRun<D>::write_snapshot(const std::string& path) const {
  const ParticleState now = sim_->state();
  const SnapshotFrame frame{now,
                            sim_->clock_state(),
                            sim_->collisions_per_particle(),
                            sim_->shear_offset(),
                            sim_->strain(),
                            sim_->image_velocity()};
  if (std::filesystem::exists(path)) {
    SnapshotWriter writer(path);
    writer.append(frame);
    writer.finish();
    return;
  }
  SnapshotMetadata metadata;
  metadata.system = config_.system;
  metadata.packing_fraction = config_.packing_fraction;
  metadata.boundary = boundary_kind_name(config_);
  metadata.seed = config_.seed;
  metadata.version = kVersion;
  metadata.diameters = now.diameter;
  metadata.masses = now.mass;
  SnapshotWriter writer(path, metadata);
  writer.append(frame);
  writer.finish();
}

template class InteractiveRun<2>;
template class InteractiveRun<3>;

}  // namespace granule::bindings
