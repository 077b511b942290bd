#include "driver/measurement_replay.hpp"

#include <cmath>
#include <filesystem>

#include "driver/run_measurements.hpp"
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

ReplayOutcome replay_with_measurements(const RunConfig& config, const SnapshotRead& snapshot,
                                       double collisions_per_particle,
                                       const std::function<std::string(double c_start)>& out_dir) {
  return config.system.dimension == 3 ? replay<3>(config, snapshot, collisions_per_particle, out_dir)
                                      : replay<2>(config, snapshot, collisions_per_particle, out_dir);
}

}  // namespace granule::driver
