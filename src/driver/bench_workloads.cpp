#include "driver/bench_workloads.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <string_view>

#include "cells/cell_grid.hpp"
#include "engine/simulation.hpp"
#include "init/initial_state.hpp"
#include "io/input_ranges.hpp"
#include "observers/collisional_stress.hpp"
#include "observers/free_paths.hpp"
#include "observers/global_diagnostics.hpp"
#include "observers/impact_parameters.hpp"
#include "theory/hard_spheres.hpp"
#include "theory/steady_shear.hpp"

namespace granule::driver {

namespace {

constexpr double kWallShearChannelDiameters = 40.0;  // a few dissipation lengths (λ/√(1 − e²) ≈ 12σ at ν = 0.05)


template <int D>
BenchResult run_workload(const BenchWorkload& w, const BenchSettings& o, BenchMeasurements measure) {
  const std::int64_t particles = o.particles;
  const SystemParams p =
      bench_workload_system(w, D, particles, o.renumber_every.value_or(default_renumber_every(D, particles)));
  constexpr double temperature = 1.0;
  CellGridRequest request{p.length_x, p.length_y, p.diameter, p.particles, w.lees_edwards,
                          o.particles_per_cell.value_or(kDefaultParticlesPerCell), std::nullopt};
  request.dimension = D;
  request.length_z = p.length_z;
  request.max_cells = kMaxEngineCells;
  const CellGridChoice grid = choose_cell_grid(request);
  const InitialStateResult init = make_initial_state(elastic_prerun(p), temperature, o.seed, Placement::kAuto);
  if (!grid.grid || !init.error.empty()) {
    BenchResult refused;
    refused.error = grid.error + init.error;
    return refused;
  }
  Simulation<D> sim(elastic_prerun(p), *grid.grid, init.state);
  // Melt lattices and forget the initial transient: 2 elastic collisions per particle, untimed.
  sim.run(std::numeric_limits<double>::infinity(), 2 * p.particles);
  SystemParams production = p;
  production.restitution = w.restitution;
  sim.start_production(production);
  const auto target = std::llround(o.collisions_per_particle * static_cast<double>(p.particles));
  const auto at_least = [&](BenchMeasurements m) { return static_cast<int>(measure) >= static_cast<int>(m); };
  const FieldGrid cells = D == 3 ? default_field_grid_3d(p.length_x, p.length_y, p.length_z, p.particles)
                                 : default_field_grid(p.length_x, p.length_y, p.particles);
  GlobalDiagnostics<D> diagnostics(p, cells);
  CollisionalStressField<D> stress(cells, p.diameter, p.roughness.rough);
  LocalDensity density(cells);
  ImpactParameterStatistics<D> impacts(p.diameter, 50, p.particles, {}, &density);
  FreePathStatistics<D> paths(p.particles, FreePathSettings{}, &density);
  paths.start();
  if (at_least(BenchMeasurements::kDiagnostics)) sim.add_observer(&diagnostics);
  if (at_least(BenchMeasurements::kStressField)) sim.add_observer(&stress);
  if (at_least(BenchMeasurements::kImpacts)) sim.add_observer(&impacts);
  if (at_least(BenchMeasurements::kFreePaths)) sim.add_observer(&paths);
  const auto start = std::chrono::steady_clock::now();
  while (sim.collisions() < target) {
    sim.run(std::numeric_limits<double>::infinity(), std::min<std::int64_t>(target, sim.collisions() + p.particles));
    if (at_least(BenchMeasurements::kDiagnostics)) {
      diagnostics.sample(sim.state(), sim.time(), sim.collisions(), sim.image_velocity(), sim.shear_offset());
    }
    if (at_least(BenchMeasurements::kImpacts)) density.update(sim.state());
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  BenchResult timed;
  timed.particles = p.particles;
  timed.collisions = sim.collisions();
  timed.events = sim.events();
  timed.seconds = seconds;
  timed.bytes_per_particle = sim.bytes_per_particle();
  return timed;
}

constexpr BenchWorkload kWorkloads2d[] = {
    {"elastic, nu=0.05", 0.05, 1.0, false},
    {"elastic, nu=0.5", 0.5, 1.0, false},
    {"free cooling e=0.9, nu=0.05", 0.05, 0.9, false},
    {"Lees-Edwards e=0.8, nu=0.05", 0.05, 0.8, true},
    {"rough cooling e=0.9 b=0.5", 0.05, 0.9, false, BenchSurfaces::kRough},
    {"walls+gravity elastic", 0.05, 1.0, false, BenchSurfaces::kWallsGravity},
    {"rough wall shear e=0.9", 0.05, 0.9, false, BenchSurfaces::kRoughWallShear},
    {"obstacles flow e=0.9", 0.05, 0.9, false, BenchSurfaces::kObstaclesFlow},
};
constexpr BenchWorkload kWorkloads3d[] = {
    {"3D elastic, phi=0.30", 0.30, 1.0, false},
    {"3D elastic, phi=0.05", 0.05, 1.0, false},
    {"3D free cooling e=0.9, 0.05", 0.05, 0.9, false},
    {"3D Lees-Edwards e=0.8, 0.05", 0.05, 0.8, true},
    {"3D rough cooling e=0.9 b=0.5", 0.05, 0.9, false, BenchSurfaces::kRough},
    {"3D walls+gravity elastic", 0.05, 1.0, false, BenchSurfaces::kWallsGravity},
    {"3D rough wall shear e=0.9", 0.05, 0.9, false, BenchSurfaces::kRoughWallShear},
    {"3D obstacles flow e=0.9", 0.05, 0.9, false, BenchSurfaces::kObstaclesFlow},
};

}  // namespace

std::span<const BenchWorkload> bench_workloads(int dimension) {
  if (dimension == 3) return kWorkloads3d;
  return kWorkloads2d;
}

std::vector<BenchCase> bench_cases(const std::string& dimensions, bool observers, const std::vector<std::string>& only) {
  const auto selected = [&](const BenchWorkload& w) {
    return only.empty() || std::any_of(only.begin(), only.end(), [&](const std::string& part) {
             return std::string_view(w.name).find(part) != std::string_view::npos;
           });
  };
  std::vector<BenchCase> cases;
  const auto add = [&](const BenchWorkload& w, int dimension, BenchMeasurements measure) {
    if (selected(w)) cases.push_back({w, dimension, measure});
  };
  const std::vector<int> chosen = dimensions == "2" ? std::vector<int>{2} : dimensions == "3" ? std::vector<int>{3}
                                                                                             : std::vector<int>{2, 3};
  for (int dimension : chosen) {
    for (const BenchWorkload& w : bench_workloads(dimension)) add(w, dimension, BenchMeasurements::kNone);
  }
  if (!observers) return cases;
  for (int dimension : chosen) {
    const std::span<const BenchWorkload> workloads = bench_workloads(dimension);
    for (const BenchWorkload& w : {workloads[2], workloads[3]}) {  // free cooling, Lees–Edwards
      for (BenchMeasurements m : {BenchMeasurements::kDiagnostics, BenchMeasurements::kStressField,
                                  BenchMeasurements::kImpacts, BenchMeasurements::kFreePaths}) {
        add(w, dimension, m);
      }
    }
  }
  return cases;
}

// In 2D the rate comes from the thesis's fit (3.1); in 3D from the dilute balance of viscous heating
// η γ² (η = 5/(16σ²)√(T/π)) and collisional cooling n ω (1 − e²) T/2 (ω the Enskog collision
// frequency), good to a factor of order one.
SystemParams bench_workload_system(const BenchWorkload& w, int dimension, std::int64_t particles,
                                   double renumber_every) {
  SystemParams p;
  p.renumber_every = renumber_every;
  p.dimension = dimension;
  p.particles = particles;
  p.length_x = p.length_y = p.length_z = 1.0;
  const auto n = static_cast<double>(particles);
  p.diameter = dimension == 2 ? std::sqrt(4.0 * w.area_fraction / (M_PI * n)) : std::cbrt(6.0 * w.area_fraction / (M_PI * n));
  p.restitution = 1.0;
  if (w.surfaces == BenchSurfaces::kRoughWallShear) {
    // A channel of fixed height in diameters, its area (volume) kept 1: walls ∓U/2 apart across a
    // unit box, U set for T ≈ 1 in uniform shear, would put a velocity difference growing as √N
    // thermal speeds across the box (L_y/σ ∝ √N), which concentrates in hot, dilute layers a
    // few dissipation lengths thick at the walls — events per collision grew with it, 19 at
    // 5·10³ disks to 146 at 4·10⁵ — so the workload would not be one workload at every N.
    p.length_y = std::min(1.0, kWallShearChannelDiameters * p.diameter);
    p.length_x = dimension == 2 ? 1.0 / p.length_y : std::sqrt(1.0 / p.length_y);
    p.length_z = dimension == 2 ? 1.0 : p.length_x;
  }
  const bool rough = w.surfaces == BenchSurfaces::kRough || w.surfaces == BenchSurfaces::kRoughWallShear;
  if (rough) {
    p.roughness.rough = true;
    p.roughness.tangential_restitution = 0.5;
    p.roughness.inertia_factor = dimension == 2 ? 0.5 : 0.4;
  }
  if (w.surfaces == BenchSurfaces::kWallsGravity || w.surfaces == BenchSurfaces::kRoughWallShear) {
    p.walls[1] = true;
    for (int side = 0; side < 2; ++side) {
      WallParams& wall = p.wall[static_cast<std::size_t>(2 + side)];
      wall.restitution = rough ? 0.9 : 1.0;
      wall.tangential_restitution = rough ? 0.5 : -1.0;
    }
  }
  if (w.surfaces == BenchSurfaces::kWallsGravity) p.gravity[1] = -2.0;  // barometric height T/g = L/2
  if (w.surfaces == BenchSurfaces::kObstaclesFlow) {
    // A flow along x driven by g between walls on y, through a square array of 4^d obstacles of
    // diameter 0.1 (a tenth of the box), e_o = 0.9: what the obstacle search and hits cost.
    p.walls[1] = true;
    p.gravity[0] = 1.0;
    for (int i = 0; i < 4; ++i) {
      for (int j = 0; j < 4; ++j) {
        for (int k = 0; k < (dimension == 3 ? 4 : 1); ++k) {
          p.obstacles.push_back({{0.25 * i + 0.125, 0.25 * j + 0.125, dimension == 3 ? 0.25 * k + 0.125 : 0.0}, 0.1, 0.9, -1.0});
        }
      }
    }
  }
  if (w.lees_edwards || w.surfaces == BenchSurfaces::kRoughWallShear) {
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

BenchResult run_bench_workload(const BenchWorkload& w, int dimension, const BenchSettings& settings,
                               BenchMeasurements measure) {
  return dimension == 3 ? run_workload<3>(w, settings, measure) : run_workload<2>(w, settings, measure);
}

}  // namespace granule::driver
