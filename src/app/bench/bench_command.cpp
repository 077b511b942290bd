// `granule bench`: the options of the benchmark workloads (driver/bench_workloads.hpp) and their
// table of collisions and events per second and bytes per particle.
#include "app/bench/bench_command.hpp"

#include <fmt/format.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "driver/bench_workloads.hpp"

namespace granule::app {

namespace {

using driver::BenchWorkload;

struct BenchOptions {
  std::int64_t particles = 100000;
  std::int64_t particles_3d = 108000;
  std::string dimensions = "both";
  double collisions_per_particle = 20.0;
  std::optional<double> particles_per_cell;  // default: that of runs
  std::optional<double> renumber_every;  // default: that of runs
  std::uint64_t seed = 7;
  bool observers = false;
  std::vector<std::string> only;  // run only the workloads whose names contain one of these
};

void run_case(const driver::BenchCase& c, const BenchOptions& o) {
  const BenchWorkload& w = c.workload;
  const driver::BenchSettings settings{c.dimension == 2 ? o.particles : o.particles_3d, o.collisions_per_particle,
                                       o.particles_per_cell, o.renumber_every, o.seed};
  const driver::BenchResult r = driver::run_bench_workload(w, c.dimension, settings, c.measure);
  if (!r.error.empty()) {
    fmt::print("{:<28} cannot be set up: {}\n", w.name, r.error);
    return;
  }
  static const char* const kMeasured[] = {"", " +diagnostics", " +stress field", " +impacts", " +free paths"};
  fmt::print("{:<28} {:>8} {:>6.3g} {:>5.3g} {:>11} {:>8.3f} {:>13.4g} {:>12.4g} {:>9.1f}{}\n", w.name, r.particles,
             w.area_fraction, w.restitution, r.collisions, r.seconds, static_cast<double>(r.collisions) / r.seconds,
             static_cast<double>(r.events) / r.seconds, r.bytes_per_particle, kMeasured[static_cast<int>(c.measure)]);
}

}  // namespace

void add_bench_command(CLI::App& root) {
  auto options = std::make_shared<BenchOptions>();
  CLI::App* command = root.add_subcommand("bench", "Time the standard workloads on one core and print collisions per "
                                                   "second and bytes per particle");
  command->add_option("--particles", options->particles, "Disks per 2D workload")->default_val(100000)->check(CLI::Range(100, 100000000));
  command->add_option("--particles-3d", options->particles_3d, "Spheres per 3D workload")
      ->default_val(108000)
      ->check(CLI::Range(100, 100000000));
  command->add_option("--dimensions", options->dimensions, "Which workloads: 2, 3 or both")
      ->default_val("both")
      ->check(CLI::IsMember({"2", "3", "both"}));
  command->add_option("--collisions-per-particle", options->collisions_per_particle, "Timed collisions per particle (c)")
      ->default_val(20.0)
      ->check(CLI::Range(0.1, 1e6));
  command->add_option("--particles-per-cell", options->particles_per_cell,
                      "Target cell occupancy of the engine grid (default: that of runs, 0.6)")
      ->check(CLI::Range(0.1, 20.0));
  command->add_option("--renumber-every", options->renumber_every,
                      "Events per particle between renumberings of the engine's particles along its cells (0: never; "
                      "default: that of runs, 4 from 2 MiB of particle records on, else 0)")
      ->check(CLI::Range(0.0, 1e6));
  command->add_option("--seed", options->seed, "Seed of the initial states")->default_val(7);
  command->add_option("--only", options->only,
                      "Run only the workloads whose names contain one of these texts (e.g. --only \"elastic, nu\")");
  command->add_flag("--observers", options->observers,
                    "Also time the free-cooling and Lees–Edwards workloads with the default measurements of a run "
                    "added one at a time (their cost)");
  command->callback([options] {
    fmt::print("{:<28} {:>8} {:>6} {:>5} {:>11} {:>8} {:>13} {:>12} {:>9}\n", "workload", "N", "nu", "e", "collisions",
               "seconds", "collisions/s", "events/s", "bytes/N");
    for (const driver::BenchCase& c : driver::bench_cases(options->dimensions, options->observers, options->only)) {
      run_case(c, *options);
    }
  });
}

}  // namespace granule::app
