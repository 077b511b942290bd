// The benchmark workloads of issue 3: elastic disks at ν = 0.05 and 0.5, free cooling at e = 0.9
// and Lees–Edwards shear at e = 0.8, each N = 10^5 unless --particles says otherwise.
#include "app/bench_command.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <memory>

#include "analysis/collisional_stress.hpp"
#include "analysis/free_paths.hpp"
#include "analysis/impact_parameters.hpp"
#include "cells/cell_grid.hpp"
#include "engine/simulation.hpp"
#include "init/initial_state.hpp"
#include "observers/global_diagnostics.hpp"
#include "theory/steady_shear.hpp"

namespace granule::app {

namespace {

struct Workload {
  const char* name;
  double area_fraction;
  double restitution;
  bool lees_edwards;
};

struct BenchOptions {
  std::int64_t particles = 100000;
  double collisions_per_particle = 20.0;
  double particles_per_cell = 1.0;
  std::uint64_t seed = 7;
  bool observers = false;
};

// The measurements a run makes by default, added one at a time (observer_cost below).
enum class Measurements { kNone, kDiagnostics, kStressField, kImpacts, kFreePaths };

// Times `o.collisions_per_particle` after the untimed start, in chunks of one collision per particle;
// at each chunk the run loop's O(N) work of the chosen measurements (diagnostics sample, density
// refresh) is done as in `granule run`.
void run_workload(const Workload& w, const BenchOptions& o, Measurements measure = Measurements::kNone) {
  SystemParams p;
  p.particles = o.particles;
  p.length_x = p.length_y = 1.0;
  p.diameter = std::sqrt(4.0 * w.area_fraction / (M_PI * static_cast<double>(p.particles)));
  p.restitution = 1.0;
  double temperature = 1.0;
  if (w.lees_edwards) {
    // Shear at the rate whose steady temperature (thesis fit 3.1) is the initial T = 1, so that
    // the run compares per collision with the periodic workloads at the same temperature.
    const double t_per_gamma2 = theory::steady_shear_temperature_tan_fit(w.restitution, 1.0, p.diameter, w.area_fraction);
    p.shear_velocity = std::sqrt(temperature / t_per_gamma2) * p.length_y;
  }
  const CellGridChoice grid = choose_cell_grid({p.length_x, p.length_y, p.diameter, p.particles, w.lees_edwards,
                                                o.particles_per_cell, std::nullopt});
  const InitialStateResult init = make_initial_state(p, temperature, o.seed, Placement::kAuto);
  if (!grid.grid || !init.error.empty()) {
    fmt::print("{:<28} cannot be set up: {}{}\n", w.name, grid.error, init.error);
    return;
  }
  Simulation<2> sim(p, *grid.grid, init.state);
  // Melt lattices and forget the initial transient: 2 elastic collisions per particle, untimed.
  sim.run(std::numeric_limits<double>::infinity(), 2 * p.particles);
  sim.start_production(w.restitution);
  const auto target = std::llround(o.collisions_per_particle * static_cast<double>(p.particles));
  const FieldGrid cells = default_field_grid(p.length_x, p.length_y, p.particles);
  GlobalDiagnostics diagnostics(p, cells.nx, cells.ny);
  CollisionalStressField stress(cells, p.diameter);
  LocalDensity density(cells);
  ImpactParameterStatistics impacts(p.diameter, 50, p.particles, {}, &density);
  FreePathStatistics paths(p.particles, FreePathSettings{}, &density);
  paths.start();
  const auto at_least = [&](Measurements m) { return static_cast<int>(measure) >= static_cast<int>(m); };
  if (at_least(Measurements::kDiagnostics)) sim.add_observer(&diagnostics);
  if (at_least(Measurements::kStressField)) sim.add_observer(&stress);
  if (at_least(Measurements::kImpacts)) sim.add_observer(&impacts);
  if (at_least(Measurements::kFreePaths)) sim.add_observer(&paths);
  const auto start = std::chrono::steady_clock::now();
  while (sim.collisions() < target) {
    sim.run(std::numeric_limits<double>::infinity(), std::min<std::int64_t>(target, sim.collisions() + p.particles));
    if (at_least(Measurements::kDiagnostics)) {
      diagnostics.sample(sim.state(), sim.time(), sim.collisions(), sim.image_velocity(), sim.shear_offset());
    }
    if (at_least(Measurements::kImpacts)) density.update(sim.state());
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  static const char* const kMeasured[] = {"", " +diagnostics", " +stress field", " +impacts", " +free paths"};
  fmt::print("{:<28} {:>8} {:>6.3g} {:>5.3g} {:>11} {:>8.3f} {:>13.4g} {:>12.4g} {:>9.1f}{}\n", w.name, p.particles,
             w.area_fraction, w.restitution, sim.collisions(), seconds, static_cast<double>(sim.collisions()) / seconds,
             static_cast<double>(sim.events()) / seconds, sim.bytes_per_particle(), kMeasured[static_cast<int>(measure)]);
}

}  // namespace

void add_bench_command(CLI::App& root) {
  auto options = std::make_shared<BenchOptions>();
  CLI::App* command = root.add_subcommand("bench", "Time the standard workloads on one core and print collisions per "
                                                   "second and bytes per particle");
  command->add_option("--particles", options->particles, "Disks per workload")->default_val(100000)->check(CLI::Range(100, 100000000));
  command->add_option("--collisions-per-particle", options->collisions_per_particle, "Timed collisions per particle (c)")
      ->default_val(20.0)
      ->check(CLI::Range(0.1, 1e6));
  command->add_option("--particles-per-cell", options->particles_per_cell, "Target cell occupancy of the engine grid")
      ->default_val(1.0)
      ->check(CLI::Range(0.1, 20.0));
  command->add_option("--seed", options->seed, "Seed of the initial states")->default_val(7);
  command->add_flag("--observers", options->observers,
                    "Also time the free-cooling and Lees–Edwards workloads with the default measurements of a run "
                    "added one at a time (their cost)");
  command->callback([options] {
    fmt::print("{:<28} {:>8} {:>6} {:>5} {:>11} {:>8} {:>13} {:>12} {:>9}\n", "workload", "N", "nu", "e", "collisions",
               "seconds", "collisions/s", "events/s", "bytes/N");
    const Workload workloads[] = {
        {"elastic, nu=0.05", 0.05, 1.0, false},
        {"elastic, nu=0.5", 0.5, 1.0, false},
        {"free cooling e=0.9, nu=0.05", 0.05, 0.9, false},
        {"Lees-Edwards e=0.8, nu=0.05", 0.05, 0.8, true},
    };
    for (const Workload& w : workloads) run_workload(w, *options);
    if (!options->observers) return;
    for (const Workload& w : {workloads[2], workloads[3]}) {
      for (Measurements m : {Measurements::kDiagnostics, Measurements::kStressField, Measurements::kImpacts,
                             Measurements::kFreePaths}) {
        run_workload(w, *options, m);
      }
    }
  });
}

}  // namespace granule::app
