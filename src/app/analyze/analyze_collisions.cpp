// `granule analyze collisions RUN_DIR`: collision statistics (impact parameters, free paths) and
// fields with the collisional stress, measured after the fact by continuing the run from a chosen
// snapshot frame (driver/measurement_replay.hpp) with the measurements of [fields] and
// [collisions] attached (settable with --set), for as many collisions per particle as asked.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <memory>

#include "app/exit_codes.hpp"
#include "app/analyze/analysis_exit.hpp"
#include "app/analyze/analyze_command.hpp"
#include "driver/measurement_replay.hpp"
#include "driver/run_beginnings.hpp"
#include "driver/run_directory.hpp"
#include "driver/run_start.hpp"

namespace granule::app {

namespace {

struct CollisionsOptions {
  std::string run_dir;
  std::int64_t frame = 0;
  double collisions_per_particle = 1.0;
  std::vector<std::string> overrides;
  std::string out;
};

int bad_collisions_input(const std::string& message) { return refuse_analysis_input("collisions", message); }

int analyze_collisions(const CollisionsOptions& o) {
  driver::ReplayStart start;
  try {
    start = driver::replay_start(o.run_dir, o.frame, o.overrides);
  } catch (const driver::ConfigError& refused) {
    return bad_collisions_input(refused.what());
  } catch (const driver::RunDirectoryRefused& refused) {
    return bad_collisions_input(refused.what());
  }
  const SnapshotRead& snapshot = start.snapshot;
  driver::ReplayOutcome replay;
  try {
    replay = driver::replay_with_measurements(start.config, snapshot, o.collisions_per_particle, [&](double c_start) {
      return o.out.empty() ? fmt::format("{}/replay_from_c{:g}", o.run_dir, c_start) : o.out;
    });
  } catch (const driver::NotEnoughMemory& refused) {  // the grids of --set fields.cells, say
    fmt::print(stderr, "granule analyze collisions: error: {}\n", refused.what());
    return kExitOutOfMemory;
  }
  if (!replay.error.empty()) return bad_collisions_input(replay.error);
  fmt::print("continued {} from frame {} (c = {:.6g}) to c = {:.6g}: measurements in {}\n", o.run_dir, o.frame,
             snapshot.frame.collisions_per_particle, replay.collisions_per_particle, replay.out);
  return 0;
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
