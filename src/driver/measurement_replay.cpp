#include "driver/measurement_replay.hpp"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>

#include "driver/run_beginnings.hpp"
#include "driver/run_directory.hpp"
#include "driver/run_measurements.hpp"
#include "driver/run_start.hpp"
#include "observers/schedule.hpp"
#include "driver/stop_loop.hpp"
#include "io/atomic_file.hpp"

namespace granule::driver {

namespace {

template <int D>
ReplayOutcome replay(const RunConfig& config, const SnapshotRead& snapshot, double collisions_per_particle,
                     const std::function<std::string(double)>& out_dir) {
  const SystemParams& system = config.system;
  ReplayOutcome outcome;
  const CellGridChoice choice = choose_cell_grid(engine_grid_request(config));
  if (!choice.grid) {
    outcome.error = choice.error;
    return outcome;
  }
  // The measurements' grids are set by --set (fields.cells up to 16384²): counted with the engine.
  require_memory(estimated_run_bytes(config, *choice.grid),
                 fmt::format("a replay of N = {} with fields.cells = [{}, {}]", system.particles, config.fields.cells.first,
                             config.fields.cells.second));
  Simulation<D> sim(system, *choice.grid, snapshot.frame.particles, snapshot.frame.clock);
  outcome.out = out_dir(sim.collisions_per_particle());
  std::filesystem::create_directories(outcome.out);
  RunMeasurements<D> measurements(config, outcome.out);
  measurements.start(sim);
  const std::int64_t target =
      sim.collisions() + std::llround(collisions_per_particle * static_cast<double>(system.particles));
  while (true) {
    const StopReason reason = advance_to_next_stop<D>(sim, {&measurements}, {target, kInf});
    if (sim.collisions() >= target || reason == StopReason::kNoEvents || reason == StopReason::kInelasticCollapse) break;
  }
  measurements.after_step(sim, true);
  const nlohmann::json figures = measurements.finish(sim);
  write_file_atomically(outcome.out + "/summary.json", figures.dump(2) + "\n");
  outcome.collisions_per_particle = sim.collisions_per_particle();
  return outcome;
}

}  // namespace

ReplayStart replay_start(const std::string& run_dir, std::int64_t frame, const std::vector<std::string>& overrides) {
  const ConfigResult parsed = load_config_file(run_dir + "/config.toml", overrides);
  if (!parsed.config) throw ConfigError(parsed.error);
  ReplayStart start{*parsed.config, {}};
  try {
    start.snapshot = read_snapshot(run_dir + "/snapshots.h5", frame);
  } catch (const std::exception& error) {
    throw RunDirectoryRefused(fmt::format("--frame {}: cannot read {}/snapshots.h5: {}", frame, run_dir, error.what()));
  }
  const SystemParams &system = start.config.system, &theirs = start.snapshot.metadata.system;
  if (theirs.dimension != system.dimension || theirs.particles != system.particles || theirs.diameter != system.diameter) {
    throw RunDirectoryRefused(fmt::format("{}/snapshots.h5 does not match its config.toml", run_dir));
  }
  return start;
}

ReplayOutcome replay_with_measurements(const RunConfig& config, const SnapshotRead& snapshot,
                                       double collisions_per_particle,
                                       const std::function<std::string(double c_start)>& out_dir) {
  return config.system.dimension == 3 ? replay<3>(config, snapshot, collisions_per_particle, out_dir)
                                      : replay<2>(config, snapshot, collisions_per_particle, out_dir);
}

}  // namespace granule::driver
