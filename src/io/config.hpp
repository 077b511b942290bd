// The run configuration: a TOML file plus `--set section.key=value` overrides, validated in full
// before anything is written.  Every key, its range and default are listed in README.md.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "analysis/density_windows.hpp"
#include "observers/free_paths.hpp"
#include "cells/cell_grid.hpp"
#include "engine/system_params.hpp"
#include "init/initial_state.hpp"

namespace granule {

// [fields]: coarse-grained fields of §1.4.3 written to fields.h5 during the run.
struct FieldsConfig {
  bool enabled = true;
  std::pair<int, int> cells{0, 0};  // resolved (default: diagnostics.cells)
  std::optional<double> every_collisions_per_particle;  // default: with every snapshot
  std::optional<double> every_time;
  bool subtract_shear_profile = false;
};

// [collisions]: impact parameters (§3.2.2) and free paths (§3.2.3) written to collisions.h5.
struct CollisionStatisticsConfig {
  bool impact_parameters = true;
  bool free_paths = false;  // off by default: it costs ~20% of the collision rate (bench --observers)
  double window_collisions_per_particle = 1.0;  // W/N: impact-parameter window, density refresh
  double from_collisions_per_particle = 0.0;    // start of the measurement
  std::vector<DensityWindow> density_windows;   // particles per unit area
  std::vector<SpeedWindow> speed_windows;
  int impact_bins = 50;
  int length_bins = 100;
  int angle_bins = 72;
  double max_length = 0.0;  // resolved (default: 10 l with l = Lx Ly / (2 N σ), §3.1.2)
  bool widen_max_length = true;  // the default range widens as long paths come; a given one is fixed
};

// [initial] from = "DIR", frame = K: start from frame K of another run's snapshots.h5 (default its
// last frame) instead of a new gas, to change e, U or the protocol (thesis §4.3).
struct InitialSource {
  std::string directory;
  std::optional<std::int64_t> frame;
};

struct RunConfig {
  std::uint64_t seed = 1;
  SystemParams system;           // diameter always resolved: the largest diameter
  // ν = π Σσ_i^d / (k_d V), always resolved: the area fraction πNσ²/(4 L_x L_y) of disks (k_2 = 4),
  // the volume fraction of spheres (k_3 = 6).
  double packing_fraction = 0.0;
  double reference_diameter = 0.0;  // σ̄ (system.diameter): σ_i = σ̄ r_i; equal to system.diameter when monodisperse
  SizeDistribution diameters;       // system.diameters and system.masses
  bool lees_edwards = false;
  double initial_temperature = 1.0;  // resolved (also from initial.temperature_over_steady)
  std::optional<double> initial_temperature_over_steady;  // T_i / T₀ of (4.5), when given so
  bool initial_shear_profile = true;  // false: a static gas, sheared only from t = 0 on (§4.3)
  // T_rot per rotational degree of freedom of rough grains' initial spins (resolved: default T_i,
  // equipartition; 0 for smooth grains).
  double initial_rotational_temperature = 0.0;
  std::optional<InitialSource> initial_from;
  double equilibrate = 0.0;      // elastic collisions per particle before e is switched on
  Placement placement = Placement::kAuto;
  std::optional<double> until_collisions_per_particle;
  std::optional<double> until_time;
  std::optional<double> sample_every_collisions_per_particle;
  std::optional<double> sample_every_time;
  std::optional<double> snapshot_every_collisions_per_particle;  // 0: only the final state
  std::optional<double> snapshot_every_time;
  double checkpoint_every_seconds = 600.0;  // wall time between checkpoints
  double particles_per_cell = 1.0;
  std::optional<std::pair<int, int>> engine_cells;
  std::pair<int, int> diagnostic_cells{0, 0};  // resolved (auto: ~20 disks per cell)
  FieldsConfig fields;
  CollisionStatisticsConfig collisions;
};

struct ConfigResult {
  std::optional<RunConfig> config;
  std::string error;  // names the key, the value and the allowed range
};

// `text` is TOML (may be empty: the built-in defaults); `overrides` are "section.key=value".
ConfigResult parse_config(const std::string& text, const std::vector<std::string>& overrides);
ConfigResult load_config_file(const std::string& path, const std::vector<std::string>& overrides);

// What the engine's cell grid of this run is chosen from (choose_cell_grid); a parsed
// configuration has been checked to give a grid.
CellGridRequest engine_grid_request(const RunConfig& config);

// The per-particle diameters and masses of the run (drawn from its seed; empty when monodisperse),
// for make_initial_state.
ParticleSizes particle_sizes(const RunConfig& config);

// "periodic", "lees-edwards" or "walls" (boundary.kind).
std::string boundary_kind_name(const RunConfig& config);
// U of a wall-driven shear: the upper y wall's velocity along x minus the lower one's (0 without
// y walls; Lees–Edwards shear is SystemParams::shear_velocity).
double wall_shear_velocity(const SystemParams& system);

// The fully resolved configuration as TOML, so that any run can be repeated exactly.
std::string to_toml(const RunConfig& config);

// The built-in default example: a scaled-down System II of thesis §2.1 (free cooling, e = 0.6).
std::string default_example_toml();

}  // namespace granule
