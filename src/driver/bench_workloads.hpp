// The benchmark workloads of `granule bench`, timed on one core: in 2D elastic disks at ν = 0.05
// and 0.5, free cooling at e = 0.9 and Lees–Edwards shear at e = 0.8; in 3D elastic spheres at
// φ = 0.30 and 0.05, free cooling at e = 0.9 and Lees–Edwards shear at e = 0.8 (φ = 0.05); and in
// both rough free cooling (e = 0.9, β = 0.5), an elastic gas in gravity between a floor and a
// ceiling, and a rough gas sheared by walls moving at ∓U/2 (e = e_w = 0.9, β = β_w = 0.5) in a
// channel 40 diameters high, at ν = 0.05.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "engine/system_params.hpp"

namespace granule::driver {

// What a workload adds to smooth grains in a periodic or Lees–Edwards box.
enum class BenchSurfaces { kNone, kRough, kWallsGravity, kRoughWallShear, kObstaclesFlow };

struct BenchWorkload {
  const char* name;
  double area_fraction;  // ν: area fraction in 2D, volume fraction in 3D
  double restitution;
  bool lees_edwards;
  BenchSurfaces surfaces = BenchSurfaces::kNone;
};

// The workloads of disks (dimension 2) or spheres (3), in the order they are timed: elastic at two
// packings, free cooling, Lees–Edwards, rough cooling, walls and gravity, rough wall shear.
std::span<const BenchWorkload> bench_workloads(int dimension);

// The measurements a run makes by default, added one at a time (their cost); each includes those
// before it.
enum class BenchMeasurements { kNone, kDiagnostics, kStressField, kImpacts, kFreePaths };

// One timing of `granule bench`: a workload of disks or spheres with the measurements added.
struct BenchCase {
  BenchWorkload workload;
  int dimension = 2;
  BenchMeasurements measure = BenchMeasurements::kNone;
};

// What `granule bench` times, in order: every workload of the `dimensions` asked ("2", "3" or
// "both"), then, with `observers`, the free-cooling and Lees–Edwards workloads with each default
// measurement added in turn; only the workloads whose names contain one of `only` (all when empty).
std::vector<BenchCase> bench_cases(const std::string& dimensions, bool observers, const std::vector<std::string>& only);

struct BenchSettings {
  std::int64_t particles = 100000;
  double collisions_per_particle = 20.0;     // timed, after an untimed start
  std::optional<double> particles_per_cell;  // default: that of runs
  std::optional<double> renumber_every;      // default: that of runs
  std::uint64_t seed = 7;
};

// The system of a workload: a unit square or cube (a flat channel for the wall shear) at packing
// fraction ν.  Lees–Edwards workloads shear at the rate whose steady temperature is the initial
// T = 1, so that the run compares per collision with the periodic workloads at that temperature.
SystemParams bench_workload_system(const BenchWorkload& w, int dimension, std::int64_t particles,
                                   double renumber_every);

struct BenchResult {
  std::string error;  // non-empty: the workload could not be set up, nothing was timed
  std::int64_t particles = 0, collisions = 0, events = 0;
  double seconds = 0.0;
  double bytes_per_particle = 0.0;
};

// Times `settings.collisions_per_particle` after the untimed start, in chunks of one collision per
// particle; at each chunk the run loop's O(N) work of the chosen measurements (diagnostics sample,
// density refresh) is done as in `granule run`.
BenchResult run_bench_workload(const BenchWorkload& w, int dimension, const BenchSettings& settings,
                               BenchMeasurements measure = BenchMeasurements::kNone);

}  // namespace granule::driver
