// `granule analyze collisions RUN_DIR`: collision statistics (impact parameters, free paths) and
// fields with the collisional stress, measured after the fact.  Collisions are not stored, so the
// run is continued from a chosen snapshot frame — the same physical state and clock, with new
// round-off, hence a statistically equivalent trajectory rather than the same bits — with the
// measurements of [fields] and [collisions] attached (settable with --set), for as many collisions
// per particle as asked.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <filesystem>
#include <memory>

#include "app/exit_codes.hpp"
#include "app/analyze/analyze_command.hpp"
#include "driver/stop_loop.hpp"
#include "driver/run_measurements.hpp"
#include "observers/schedule.hpp"
#include "io/atomic_file.hpp"
#include "io/snapshot_file.hpp"

namespace granule::app {

namespace {

struct CollisionsOptions {
  std::string run_dir;
  std::int64_t frame = 0;
  double collisions_per_particle = 1.0;
  std::vector<std::string> overrides;
  std::string out;
};

// The continuation itself, for disks (D = 2) or spheres (D = 3).
template <int D>
int continue_and_measure(const CollisionsOptions& o, const RunConfig& config, const SnapshotRead& snapshot) {
  const SystemParams& system = config.system;
  const CellGridChoice choice = choose_cell_grid(engine_grid_request(config));
  if (!choice.grid) {
    fmt::print(stderr, "granule analyze collisions: error: {}\n", choice.error);
    return kExitBadInput;
  }
  Simulation<D> sim(system, *choice.grid, snapshot.frame.particles, snapshot.frame.clock);
  const std::string out = o.out.empty() ? fmt::format("{}/replay_from_c{:g}", o.run_dir, sim.collisions_per_particle()) : o.out;
  std::filesystem::create_directories(out);
  driver::RunMeasurements<D> measurements(config, out);
  measurements.start(sim);
  const std::int64_t target =
      sim.collisions() + std::llround(o.collisions_per_particle * static_cast<double>(system.particles));
  while (true) {
    const StopReason reason = driver::advance_to_next_stop<D>(sim, {&measurements}, {target, driver::kInf});
    if (sim.collisions() >= target || reason == StopReason::kNoEvents || reason == StopReason::kInelasticCollapse) break;
  }
  measurements.after_step(sim, true);
  const nlohmann::json figures = measurements.finish(sim);
  write_file_atomically(out + "/summary.json", figures.dump(2) + "\n");
  fmt::print("continued {} from frame {} (c = {:.6g}) to c = {:.6g}: measurements in {}\n", o.run_dir, o.frame,
             snapshot.frame.collisions_per_particle, sim.collisions_per_particle(), out);
  return 0;
}

int analyze_collisions(const CollisionsOptions& o) {
  const ConfigResult parsed = load_config_file(o.run_dir + "/config.toml", o.overrides);
  if (!parsed.config) {
    fmt::print(stderr, "granule analyze collisions: error: {}\n", parsed.error);
    return kExitBadInput;
  }
  const RunConfig& config = *parsed.config;
  const SystemParams& system = config.system;
  SnapshotRead snapshot;
  try {
    snapshot = read_snapshot(o.run_dir + "/snapshots.h5", o.frame);
  } catch (const std::exception& error) {
    fmt::print(stderr, "granule analyze collisions: error: --frame {}: cannot read {}/snapshots.h5: {}\n", o.frame,
               o.run_dir, error.what());
    return kExitBadInput;
  }
  const SystemParams& theirs = snapshot.metadata.system;
  if (theirs.dimension != system.dimension || theirs.particles != system.particles || theirs.diameter != system.diameter) {
    fmt::print(stderr, "granule analyze collisions: error: {}/snapshots.h5 does not match its config.toml\n", o.run_dir);
    return kExitBadInput;
  }
  return system.dimension == 3 ? continue_and_measure<3>(o, config, snapshot) : continue_and_measure<2>(o, config, snapshot);
}

}  // namespace

void add_analyze_collisions(CLI::App& analyze) {
  auto o = std::make_shared<CollisionsOptions>();
  CLI::App* command = analyze.add_subcommand(
      "collisions", "Impact parameters, free paths and the collisional stress field measured by continuing a run exactly "
                    "from one of its snapshots (schemas: README, collisions.h5 and fields.h5)");
  command->add_option("run_dir", o->run_dir, "Output directory of a run (config.toml, snapshots.h5)")
      ->required()
      ->check(CLI::ExistingDirectory);
  command->add_option("--frame", o->frame, "Snapshot frame to start from (negative counts from the end)")->default_val(0);
  command->add_option("--collisions-per-particle", o->collisions_per_particle, "How long to measure, in c")
      ->default_val(1.0)
      ->check(CLI::Range(1e-6, 1e9));
  command->add_option("--set", o->overrides,
                      "Measurement settings, e.g. --set collisions.density_windows=[[0,2e4]] --set fields.cells=[40,40]");
  command->add_option("--out", o->out, "Output directory (default RUN_DIR/replay_from_c<c>)");
  command->callback([o] { throw CLI::RuntimeError(analyze_collisions(*o)); });
}

}  // namespace granule::app
