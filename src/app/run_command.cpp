// `granule run`: validate a configuration, prepare the initial state of thesis §1.4.2 (elastic
// pre-run included), run the event loop and write the outputs documented in README.md.
#include "app/run_command.hpp"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>

#include "app/plot_run_picture.hpp"
#include "app/progress.hpp"
#include "app/run_measurements.hpp"
#include "app/schedule.hpp"
#include "engine/simulation.hpp"
#include "granule/version.hpp"
#include "io/atomic_file.hpp"
#include "io/config.hpp"
#include "io/snapshot_file.hpp"
#include "io/timeseries_csv.hpp"
#include "observers/global_diagnostics.hpp"
#include "theory/steady_shear.hpp"

namespace granule::app {

namespace {

// Exit codes: 2 bad input (nothing written), 3 stopped by inelastic collapse (outputs written).
constexpr int kExitBadInput = 2;
constexpr int kExitCollapse = 3;

struct RunOptions {
  std::string config_path;
  std::vector<std::string> overrides;
  std::string out_dir;
  std::string resume_dir;
};

const char* stop_text(StopReason reason) {
  switch (reason) {
    case StopReason::kTimeReached: return "time reached";
    case StopReason::kCollisionsReached: return "collisions reached";
    case StopReason::kNoEvents: return "no further events";
    case StopReason::kInelasticCollapse: return "inelastic collapse";
  }
  return "unknown";
}

nlohmann::json summary_json(const RunConfig& config, const Simulation& sim, const CellGrid& grid,
                            double wall_seconds, StopReason reason, std::int64_t equilibrate_collisions,
                            std::int64_t snapshots, const std::vector<DiagnosticsSample>& samples) {
  const SystemParams& s = config.system;
  nlohmann::json j;
  j["version"] = kVersion;
  j["particles"] = s.particles;
  j["diameter"] = s.diameter;
  j["area_fraction"] = config.area_fraction;
  j["box"] = {s.length_x, s.length_y};
  j["restitution"] = s.restitution;
  j["tc_duration"] = s.tc_duration;
  j["boundary"] = config.lees_edwards ? "lees-edwards" : "periodic";
  j["shear_velocity"] = s.shear_velocity;
  j["seed"] = config.seed;
  j["collisions"] = sim.collisions();
  j["events"] = sim.events();
  j["equilibrate_collisions"] = equilibrate_collisions;
  j["wall_seconds"] = wall_seconds;
  j["collisions_per_second"] = wall_seconds > 0.0 ? static_cast<double>(sim.collisions()) / wall_seconds : 0.0;
  j["t"] = sim.time();
  j["c"] = sim.collisions_per_particle();
  j["stop_reason"] = stop_text(reason);
  j["snapshots"] = snapshots;
  j["engine_cells"] = {grid.nx, grid.ny};
  j["bytes_per_particle"] = sim.bytes_per_particle();
  if (config.lees_edwards && !samples.empty()) {
    // Steady-shear temperature: measured T̄ (mean over the second half of the samples) beside
    // the thesis's fit (3.1) and the Jenkins–Richman dilute law (3.2).
    const std::size_t from = samples.size() / 2;
    double sum = 0.0;
    for (std::size_t k = from; k < samples.size(); ++k) sum += samples[k].temperature;
    const double gamma = s.shear_velocity / s.length_y;
    j["steady_shear"] = {
        {"temperature_measured", sum / static_cast<double>(samples.size() - from)},
        {"measured_over_c", {samples[from].c, samples.back().c}},
        {"temperature_tan_fit_eq_3_1", theory::steady_shear_temperature_tan_fit(s.restitution, gamma, s.diameter, config.area_fraction)},
        {"temperature_jenkins_richman_eq_3_2",
         theory::steady_shear_temperature_jenkins_richman(s.restitution, gamma, s.diameter, config.area_fraction)},
    };
  }
  return j;
}

int run(const RunOptions& options) {
  // 1. Everything that can be wrong with the input is found before anything is written.
  const bool resume = !options.resume_dir.empty();
  const std::string out = resume ? options.resume_dir : options.out_dir;
  const ConfigResult parsed = resume ? load_config_file(out + "/config.toml", options.overrides)
                              : options.config_path.empty()
                                  ? parse_config(default_example_toml(), options.overrides)
                                  : load_config_file(options.config_path, options.overrides);
  if (!parsed.config) {
    fmt::print(stderr, "granule run: error: {}\n", parsed.error);
    return kExitBadInput;
  }
  const RunConfig& config = *parsed.config;
  const SystemParams& system = config.system;
  const CellGridChoice choice = choose_cell_grid({system.length_x, system.length_y, system.diameter, system.particles,
                                                  config.lees_edwards, config.particles_per_cell, config.engine_cells});
  if (!choice.grid) {
    fmt::print(stderr, "granule run: error: {}\n", choice.error);
    return kExitBadInput;
  }
  std::unique_ptr<Simulation> simulation;
  std::int64_t equilibrate_collisions = 0;
  std::string previous_rows;  // time-series rows of the run being resumed
  if (resume) {
    // Continue from the last snapshot: the engine restarts bit for bit from a synchronised frame.
    SnapshotRead last;
    try {
      last = read_snapshot(out + "/snapshots.h5");
    } catch (const std::exception& error) {
      fmt::print(stderr, "granule run: error: cannot resume from {}: {}\n", out, error.what());
      return kExitBadInput;
    }
    if (last.metadata.system.particles != system.particles || last.metadata.system.diameter != system.diameter) {
      fmt::print(stderr, "granule run: error: {}/snapshots.h5 does not match {}/config.toml (--set may only change "
                         "run and output keys when resuming)\n", out, out);
      return kExitBadInput;
    }
    simulation = std::make_unique<Simulation>(system, *choice.grid, last.frame.particles, last.frame.clock);
    std::ifstream csv(out + "/timeseries.csv");
    std::string line;
    std::getline(csv, line);  // header
    while (std::getline(csv, line)) {
      if (std::stod(line.substr(line.find(',') + 1)) <= simulation->collisions_per_particle() + 1e-12) {
        previous_rows += line + "\n";
      }
    }
    fmt::print("resuming {} at t = {:.6g}, c = {:.6g}\n", out, simulation->time(), simulation->collisions_per_particle());
  } else {
    const InitialStateResult initial = make_initial_state(system, config.initial_temperature, config.seed, config.placement);
    if (!initial.error.empty()) {
      fmt::print(stderr, "granule run: error: {} (system.area_fraction = {:.4g})\n", initial.error, config.area_fraction);
      return kExitBadInput;
    }
    std::filesystem::create_directories(out);
    // 2. The elastic pre-run of thesis §1.4.2, then the restitution is switched on at t = c = 0.
    SystemParams elastic = system;
    elastic.restitution = 1.0;
    simulation = std::make_unique<Simulation>(elastic, *choice.grid, initial.state);
    equilibrate_collisions = std::llround(config.equilibrate * static_cast<double>(system.particles));
  }
  Simulation& sim = *simulation;
  write_file_atomically(out + "/config.toml", to_toml(config));
  fmt::print("granule {}: N = {}, ν = {:.4g}, σ = {:.6g}, e = {}, {} box {} × {}{}\n", kVersion, system.particles,
             config.area_fraction, system.diameter, system.restitution, config.lees_edwards ? "Lees–Edwards" : "periodic",
             system.length_x, system.length_y,
             config.lees_edwards ? fmt::format(", U = {}", system.shear_velocity) : std::string{});
  Progress progress;
  if (equilibrate_collisions > 0) {
    fmt::print("elastic pre-run: {} collisions per particle\n", config.equilibrate);
    if (sim.run(kInf, equilibrate_collisions) == StopReason::kNoEvents) {
      fmt::print(stderr, "granule run: the elastic pre-run has no events (all disks at rest?)\n");
    }
  }
  if (!resume) {
    sim.start_production(system.restitution);
    sim.synchronize();
  }

  GlobalDiagnostics diagnostics(system, config.diagnostic_cells.first, config.diagnostic_cells.second);
  sim.add_observer(&diagnostics);
  std::vector<DiagnosticsSample> samples;
  diagnostics.restart_interval(sim.time(), sim.collisions());
  if (!resume) samples.push_back(diagnostics.sample(sim.state(), sim.time(), sim.collisions()));
  auto snapshots = resume ? std::make_unique<SnapshotWriter>(out + "/snapshots.h5")
                          : std::make_unique<SnapshotWriter>(out + "/snapshots.h5",
                                                             SnapshotMetadata{system, config.area_fraction,
                                                                              config.lees_edwards ? "lees-edwards" : "periodic",
                                                                              config.seed, kVersion});
  std::int64_t last_snapshot_events = resume ? sim.events() : -1;
  auto write_snapshot = [&] {
    sim.synchronize();
    last_snapshot_events = sim.events();
    snapshots->append({sim.state(), sim.clock_state(), sim.collisions_per_particle(), sim.shear_offset(), sim.strain()});
  };
  if (!resume) write_snapshot();

  // Fields and collision statistics; a resumed run measures its new segment in a folder of its own.
  const std::string measurement_dir =
      resume ? fmt::format("{}/resumed_from_c{:g}", out, sim.collisions_per_particle()) : out;
  std::filesystem::create_directories(measurement_dir);
  RunMeasurements measurements(config, measurement_dir);
  measurements.start(sim);

  Schedule sampling{config.sample_every_collisions_per_particle, config.sample_every_time};
  Schedule snapshotting{config.snapshot_every_collisions_per_particle, config.snapshot_every_time};
  sampling.start(system.particles);
  snapshotting.start(system.particles);
  sampling.advance(sim);  // a resumed run has passed some outputs already
  snapshotting.advance(sim);
  const std::int64_t until_collisions = config.until_collisions_per_particle
                                            ? std::llround(*config.until_collisions_per_particle * static_cast<double>(system.particles))
                                            : kNoLimit;
  const double until_time = config.until_time.value_or(kInf);
  const std::int64_t chunk = std::max<std::int64_t>(1000, system.particles / 4);  // progress granularity

  // 3. The main loop: run to the next output, write it, repeat.
  const double wall_start = progress.seconds_since_start();
  double last_csv_write = wall_start;
  StopReason reason = StopReason::kCollisionsReached;
  while (true) {
    const std::int64_t target = std::min({until_collisions, sampling.next_collisions, snapshotting.next_collisions,
                                          measurements.next_collisions(), sim.collisions() + chunk});
    reason = sim.run(std::min({until_time, sampling.next_time, snapshotting.next_time, measurements.next_time()}), target);
    const bool finished = reason == StopReason::kInelasticCollapse || reason == StopReason::kNoEvents ||
                          sim.collisions() >= until_collisions || sim.time() >= until_time;
    if (snapshotting.due(sim)) {
      write_snapshot();
      snapshotting.advance(sim);
    }
    if (sampling.due(sim) || finished) {
      const ParticleState state = sim.state();
      samples.push_back(diagnostics.sample(state, sim.time(), sim.collisions()));
      measurements.on_sample(state, sim.collisions());
      sampling.advance(sim);
      const double now = progress.seconds_since_start();
      if (now - last_csv_write > 10.0) {  // keep the file current on long runs
        write_timeseries(out + "/timeseries.csv", samples, previous_rows);
        last_csv_write = now;
      }
    }
    measurements.after_step(sim, finished);
    const double elapsed = progress.seconds_since_start() - wall_start;
    const double fraction = std::max(until_collisions == kNoLimit ? 0.0 : static_cast<double>(sim.collisions()) / static_cast<double>(until_collisions),
                                     std::isfinite(until_time) ? sim.time() / until_time : 0.0);
    progress.update(std::min(1.0, fraction), sim.collisions_per_particle(), sim.time(),
                    elapsed > 0.0 ? static_cast<double>(sim.collisions()) / elapsed : 0.0);
    if (finished) break;
  }
  progress.finish();
  const double wall_seconds = progress.seconds_since_start() - wall_start;

  // 4. Final state, time series and summary.
  if (last_snapshot_events != sim.events()) write_snapshot();
  snapshots->finish();
  write_timeseries(out + "/timeseries.csv", samples, previous_rows);
  nlohmann::json summary = summary_json(config, sim, *choice.grid, wall_seconds, reason, equilibrate_collisions,
                                        snapshots->frames(), samples);
  summary["measurements"] = measurements.finish(sim);
  write_file_atomically(out + "/summary.json", summary.dump(2) + "\n");
  try {
    fmt::print("picture: {}\n", render_run_picture(out));
  } catch (const std::exception& error) {  // a missing picture must not lose the run's data
    fmt::print(stderr, "granule run: warning: could not draw the configuration picture: {}\n", error.what());
  }

  fmt::print("finished ({}): t = {:.6g}, c = {:.6g}, {} collisions in {:.3g} s ({:.3g} collisions/s)\n", stop_text(reason),
             sim.time(), sim.collisions_per_particle(), sim.collisions(), wall_seconds,
             summary["collisions_per_second"].get<double>());
  fmt::print("outputs in {}: config.toml, timeseries.csv, summary.json, snapshots.h5 ({} frames){}\n", out, snapshots->frames(),
             measurement_dir == out ? std::string{} : "; measurements in " + measurement_dir);
  if (reason == StopReason::kInelasticCollapse) {
    const CollapseReport& c = sim.collapse();
    fmt::print(stderr,
               "granule run: stopped by inelastic collapse at t = {:.9g} (c = {:.6g}): disks {} and {} near ({:.4g}, {:.4g})"
               " collided ever faster until the clock stopped advancing (McNamara & Young 1994).\n"
               "  The last state is saved in {}/snapshots.h5.  Switch on the TC model to continue, e.g.\n"
               "    --set system.tc_duration={:.3g}\n"
               "  (much shorter than the mean free time {:.3g}).\n",
               c.time, sim.collisions_per_particle(), c.first, c.second, c.position.x, c.position.y, out,
               1e-6 * (samples.back().collision_rate > 0 ? 1.0 / samples.back().collision_rate : 1.0),
               samples.back().collision_rate > 0 ? 1.0 / samples.back().collision_rate : 0.0);
    return kExitCollapse;
  }
  return 0;
}

}  // namespace

void add_run_command(CLI::App& root) {
  auto options = std::make_shared<RunOptions>();
  CLI::App* command = root.add_subcommand(
      "run", "Run a simulation from a TOML config (or the built-in example: free cooling of a scaled-down "
             "System II of Tan 1995, N = 40000, ν = 0.05, e = 0.6).");
  command->add_option("config", options->config_path, "TOML configuration file (keys: see README.md)")
      ->check(CLI::ExistingFile);
  command->add_option("--set", options->overrides, "Override a config key, e.g. --set system.restitution=0.8 (repeatable)");
  command->add_option("--out", options->out_dir, "Output directory")->default_val("granule-run");
  command->add_option("--resume", options->resume_dir,
                      "Continue the run in this output directory from its last snapshot (extend it with e.g. "
                      "--set run.until_collisions_per_particle=200)")
      ->check(CLI::ExistingDirectory);
  command->callback([options] { throw CLI::RuntimeError(run(*options)); });
}

}  // namespace granule::app
