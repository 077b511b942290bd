// The benchmark workloads: in 2D elastic disks at ν = 0.05 and 0.5, free cooling at e = 0.9 and
// Lees–Edwards shear at e = 0.8, N = 10^5 unless --particles says otherwise; in 3D elastic spheres
// at φ = 0.30 and 0.05, free cooling at e = 0.9 and Lees–Edwards shear at e = 0.8 (φ = 0.05),
// N = 108000 unless --particles-3d says otherwise; and in both rough free cooling (e = 0.9,
// β = 0.5), an elastic gas in gravity between a floor and a ceiling, and a rough gas sheared by
// walls moving at ∓U/2 (e = e_w = 0.9, β = β_w = 0.5) in a channel 40 diameters high, at ν = 0.05.
#include "app/bench/bench_command.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "observers/collisional_stress.hpp"
#include "observers/free_paths.hpp"
#include "observers/impact_parameters.hpp"
#include "cells/cell_grid.hpp"
#include "engine/simulation.hpp"
#include "init/initial_state.hpp"
#include "io/input_ranges.hpp"
#include "observers/global_diagnostics.hpp"
#include "theory/hard_spheres.hpp"
#include "theory/steady_shear.hpp"

namespace granule::app {

namespace {

// What a workload adds to smooth grains in a periodic or Lees–Edwards box.
enum class Surfaces { kNone, kRough, kWallsGravity, kRoughWallShear };

struct Workload {
  const char* name;
  double area_fraction;  // ν: area fraction in 2D, volume fraction in 3D
  double restitution;
  bool lees_edwards;
  Surfaces surfaces = Surfaces::kNone;
};

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

bool selected(const Workload& w, const BenchOptions& o) {
  return o.only.empty() || std::any_of(o.only.begin(), o.only.end(), [&](const std::string& part) {
           return std::string_view(w.name).find(part) != std::string_view::npos;
         });
}

// The measurements a run makes by default, added one at a time (observer_cost below).
enum class Measurements { kNone, kDiagnostics, kStressField, kImpacts, kFreePaths };

constexpr double kWallShearChannelDiameters = 40.0;  // a few dissipation lengths (λ/√(1 − e²) ≈ 12σ at ν = 0.05)

// The system of a workload: a unit square or cube (a flat channel for the wall shear) at packing
// fraction ν.  Lees–Edwards workloads shear at the rate whose steady temperature is the initial
// T = 1 — in 2D from the thesis's fit (3.1); in 3D from the dilute balance of viscous heating η γ² (η = 5/(16σ²)√(T/π)) and collisional
// cooling n ω (1 − e²) T/2 (ω the Enskog collision frequency), good to a factor of order one —
// so that the run compares per collision with the periodic workloads at the same temperature.
SystemParams workload_system(const Workload& w, int dimension, std::int64_t particles, double renumber_every) {
  SystemParams p;
  p.renumber_every = renumber_every;
  p.dimension = dimension;
  p.particles = particles;
  p.length_x = p.length_y = p.length_z = 1.0;
  const auto n = static_cast<double>(particles);
  p.diameter = dimension == 2 ? std::sqrt(4.0 * w.area_fraction / (M_PI * n)) : std::cbrt(6.0 * w.area_fraction / (M_PI * n));
  p.restitution = 1.0;
  if (w.surfaces == Surfaces::kRoughWallShear) {
    // A channel of fixed height in diameters, its area (volume) kept 1: walls ∓U/2 apart across a
    // unit box, U set for T ≈ 1 in uniform shear, would put a velocity difference growing as √N
    // thermal speeds across the box (L_y/σ ∝ √N), which concentrates in hot, dilute layers a
    // few dissipation lengths thick at the walls — events per collision grew with it, 19 at
    // 5·10³ disks to 146 at 4·10⁵ — so the workload would not be one workload at every N.
    p.length_y = std::min(1.0, kWallShearChannelDiameters * p.diameter);
    p.length_x = dimension == 2 ? 1.0 / p.length_y : std::sqrt(1.0 / p.length_y);
    p.length_z = dimension == 2 ? 1.0 : p.length_x;
  }
  const bool rough = w.surfaces == Surfaces::kRough || w.surfaces == Surfaces::kRoughWallShear;
  if (rough) {
    p.roughness.rough = true;
    p.roughness.tangential_restitution = 0.5;
    p.roughness.inertia_factor = dimension == 2 ? 0.5 : 0.4;
  }
  if (w.surfaces == Surfaces::kWallsGravity || w.surfaces == Surfaces::kRoughWallShear) {
    p.walls[1] = true;
    for (int side = 0; side < 2; ++side) {
      WallParams& wall = p.wall[static_cast<std::size_t>(2 + side)];
      wall.restitution = rough ? 0.9 : 1.0;
      wall.tangential_restitution = rough ? 0.5 : -1.0;
    }
  }
  if (w.surfaces == Surfaces::kWallsGravity) p.gravity[1] = -2.0;  // barometric height T/g = L/2
  if (w.lees_edwards || w.surfaces == Surfaces::kRoughWallShear) {
    double rate = 0.0;
    if (dimension == 2) {
      rate = std::sqrt(1.0 / theory::steady_shear_temperature_tan_fit(w.restitution, 1.0, p.diameter, w.area_fraction));
    } else {
      const double omega = theory::hard_sphere_collision_frequency(3, n, p.diameter, theory::hard_sphere_contact_value(3, w.area_fraction), 1.0, 1.0);
      const double viscosity = 5.0 / (16.0 * p.diameter * p.diameter) * std::sqrt(1.0 / M_PI);
      rate = std::sqrt(n * omega * (1.0 - w.restitution * w.restitution) * 0.5 / viscosity);
    }
    if (w.lees_edwards) {
      p.shear_velocity = rate * p.length_y;
    } else {  // the same velocity difference, carried by the y walls
      p.wall[2].velocity[0] = -0.5 * rate * p.length_y;
      p.wall[3].velocity[0] = 0.5 * rate * p.length_y;
    }
  }
  return p;
}

// Times `o.collisions_per_particle` after the untimed start, in chunks of one collision per particle;
// at each chunk the run loop's O(N) work of the chosen measurements (diagnostics sample, density
// refresh) is done as in `granule run`.
template <int D>
void run_workload(const Workload& w, const BenchOptions& o, Measurements measure = Measurements::kNone) {
  if (!selected(w, o)) return;
  const std::int64_t particles = D == 2 ? o.particles : o.particles_3d;
  const SystemParams p = workload_system(w, D, particles, o.renumber_every.value_or(default_renumber_every(D, particles)));
  constexpr double temperature = 1.0;
  CellGridRequest request{p.length_x, p.length_y, p.diameter, p.particles, w.lees_edwards,
                          o.particles_per_cell.value_or(kDefaultParticlesPerCell), std::nullopt};
  request.dimension = D;
  request.length_z = p.length_z;
  request.max_cells = kMaxEngineCells;
  const CellGridChoice grid = choose_cell_grid(request);
  const InitialStateResult init = make_initial_state(elastic_prerun(p), temperature, o.seed, Placement::kAuto);
  if (!grid.grid || !init.error.empty()) {
    fmt::print("{:<28} cannot be set up: {}{}\n", w.name, grid.error, init.error);
    return;
  }
  Simulation<D> sim(elastic_prerun(p), *grid.grid, init.state);
  // Melt lattices and forget the initial transient: 2 elastic collisions per particle, untimed.
  sim.run(std::numeric_limits<double>::infinity(), 2 * p.particles);
  SystemParams production = p;
  production.restitution = w.restitution;
  sim.start_production(production);
  const auto target = std::llround(o.collisions_per_particle * static_cast<double>(p.particles));
  const auto at_least = [&](Measurements m) { return static_cast<int>(measure) >= static_cast<int>(m); };
  const FieldGrid cells = D == 3 ? default_field_grid_3d(p.length_x, p.length_y, p.length_z, p.particles)
                                 : default_field_grid(p.length_x, p.length_y, p.particles);
  GlobalDiagnostics<D> diagnostics(p, cells);
  CollisionalStressField<D> stress(cells, p.diameter, p.roughness.rough);
  LocalDensity density(cells);
  ImpactParameterStatistics<D> impacts(p.diameter, 50, p.particles, {}, &density);
  FreePathStatistics<D> paths(p.particles, FreePathSettings{}, &density);
  paths.start();
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
    const Workload workloads[] = {
        {"elastic, nu=0.05", 0.05, 1.0, false},
        {"elastic, nu=0.5", 0.5, 1.0, false},
        {"free cooling e=0.9, nu=0.05", 0.05, 0.9, false},
        {"Lees-Edwards e=0.8, nu=0.05", 0.05, 0.8, true},
        {"rough cooling e=0.9 b=0.5", 0.05, 0.9, false, Surfaces::kRough},
        {"walls+gravity elastic", 0.05, 1.0, false, Surfaces::kWallsGravity},
        {"rough wall shear e=0.9", 0.05, 0.9, false, Surfaces::kRoughWallShear},
    };
    const Workload workloads_3d[] = {
        {"3D elastic, phi=0.30", 0.30, 1.0, false},
        {"3D elastic, phi=0.05", 0.05, 1.0, false},
        {"3D free cooling e=0.9, 0.05", 0.05, 0.9, false},
        {"3D Lees-Edwards e=0.8, 0.05", 0.05, 0.8, true},
        {"3D rough cooling e=0.9 b=0.5", 0.05, 0.9, false, Surfaces::kRough},
        {"3D walls+gravity elastic", 0.05, 1.0, false, Surfaces::kWallsGravity},
        {"3D rough wall shear e=0.9", 0.05, 0.9, false, Surfaces::kRoughWallShear},
    };
    if (options->dimensions != "3") {
      for (const Workload& w : workloads) run_workload<2>(w, *options);
    }
    if (options->dimensions != "2") {
      for (const Workload& w : workloads_3d) run_workload<3>(w, *options);
    }
    if (!options->observers) return;
    const Measurements added[] = {Measurements::kDiagnostics, Measurements::kStressField, Measurements::kImpacts,
                                  Measurements::kFreePaths};
    if (options->dimensions != "3") {
      for (const Workload& w : {workloads[2], workloads[3]}) {
        for (Measurements m : added) run_workload<2>(w, *options, m);
      }
    }
    if (options->dimensions != "2") {
      for (const Workload& w : {workloads_3d[2], workloads_3d[3]}) {
        for (Measurements m : added) run_workload<3>(w, *options, m);
      }
    }
  });
}

}  // namespace granule::app
