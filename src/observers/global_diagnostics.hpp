// The global time series of a run (thesis §1.4.3, §2.1, Figs 2.5–2.7, 3.6): kinetic energy,
// the granular temperature T̄ (mean of cell temperatures, eq 1.3, with velocities relative to the
// imposed shear profile; the thesis's plain cell definition beside it), the global fluctuation
// temperature, flatness κ (1.8), two asymmetry measures, kinetic and collisional pressures
// (half traces of 1.4 and 1.6), the collision rate, and the scalars that classify the flow states
// of Chapter 4 (analysis/flow_classification.hpp).  Collisional quantities are accumulated from
// every collision record over the sampling interval.  Runs with rough grains, gravity or walls
// add columns: the rotational temperature, the potential and total energy, and what each wall took
// and gave (observers/wall_stress.hpp), the force on each obstacle (observers/obstacle_forces.hpp);
// runs without them write none of these columns.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "analysis/cell_fields.hpp"
#include "analysis/field_grid.hpp"
#include "analysis/flow_classification.hpp"
#include "boundary/shear_frame.hpp"
#include "engine/observer.hpp"
#include "archive/state_archive.hpp"
#include "engine/system_params.hpp"
#include "observers/obstacle_forces.hpp"
#include "observers/wall_stress.hpp"

namespace granule {

// Rough grains: T_rot = ⟨I|ω|²⟩/d_rot (I = q m σ²/4; d_rot = 1 for disks, 3 for spheres), and its
// ratio to the translational temperature_global (both per degree of freedom: 1 at equipartition).
struct RotationSample {
  double rotational_temperature = 0.0;
  double rotational_temperature_ratio = 0.0;
};

// Gravity g: the potential energy per particle −⟨m g·r⟩ (zero at the origin of the box) and the
// total energy per particle, kinetic (lab frame) + rotational ½⟨I|ω|²⟩ + potential.
struct GravitySample {
  double potential_energy = 0.0;
  double total_energy = 0.0;
};

struct DiagnosticsSample {
  double t = 0.0;
  double c = 0.0;                     // collisions per particle, thesis convention (total / N)
  double shear_velocity = 0.0;        // U(t): the images' velocity (Lees–Edwards protocol; 0 if periodic)
  double kinetic_energy = 0.0;        // ½⟨m v²⟩ per particle, lab frame
  double temperature = 0.0;           // T̄: mean over occupied cells of T(r) (eq 1.3), v − u(y) in place of v
  double temperature_thesis_cells = 0.0;  // the same with lab velocities (the thesis's T̄; = T̄ if periodic)
  double temperature_global = 0.0;    // ⟨m v'²⟩/d with v' = v − u(y) (u = 0 for periodic boxes)
  double flatness = 0.0;              // κ = ⟨v'⁴⟩ / ⟨v'²⟩², v' = v − u(y) − V(r) as in T̄
  double asymmetry_x = 0.0;           // ⟨v'_x³⟩ / ⟨v'²⟩^{3/2}
  double asymmetry_y = 0.0;           // ⟨v'_y³⟩ / ⟨v'²⟩^{3/2}
  double pressure_kinetic = 0.0;      // n T_global: trace/d of (1.4) over the whole box
  double pressure_collisional = 0.0;  // Σ σ_ij J / (d V Δt) over the interval: trace/d of (1.6)
  double shear_stress_collisional = 0.0;  // xy component of (1.6) over the interval
  double shear_stress_kinetic = 0.0;      // xy component of (1.4), whole box
  double collision_rate = 0.0;        // Δc / Δt over the interval
  FlowClassification flow;            // density contrast, densest band, V_x(y) deviation, largest cluster
  std::optional<RotationSample> rotation;  // rough grains only
  std::optional<GravitySample> gravity;    // with gravity only
  std::array<std::optional<WallFaceSample>, 6> walls;  // the faces with a wall (2·axis + side)
  std::optional<ObstacleForcesSample> obstacles;       // with obstacles only
};

// The columns of the time series, in their order (timeseries.csv, checkpoints).
template <typename Sample, typename Visit>
void for_each_column(Sample& s, Visit&& visit) {
  visit("t", s.t);
  visit("c", s.c);
  visit("shear_velocity", s.shear_velocity);
  visit("kinetic_energy", s.kinetic_energy);
  visit("temperature", s.temperature);
  visit("temperature_thesis_cells", s.temperature_thesis_cells);
  visit("temperature_global", s.temperature_global);
  visit("flatness", s.flatness);
  visit("asymmetry_x", s.asymmetry_x);
  visit("asymmetry_y", s.asymmetry_y);
  visit("pressure_kinetic", s.pressure_kinetic);
  visit("pressure_collisional", s.pressure_collisional);
  visit("shear_stress_kinetic", s.shear_stress_kinetic);
  visit("shear_stress_collisional", s.shear_stress_collisional);
  visit("collision_rate", s.collision_rate);
  for_each_flow_measure(s.flow, visit);
  if (s.rotation) {
    visit("rotational_temperature", s.rotation->rotational_temperature);
    visit("rotational_temperature_ratio", s.rotation->rotational_temperature_ratio);
  }
  if (s.gravity) {
    visit("potential_energy", s.gravity->potential_energy);
    visit("total_energy", s.gravity->total_energy);
  }
  for (int face = 0; face < 6; ++face) {
    if (s.walls[static_cast<std::size_t>(face)]) for_each_wall_column(face, *s.walls[static_cast<std::size_t>(face)], visit);
  }
  if (s.obstacles) for_each_obstacle_column(*s.obstacles, visit);
}

// The column layout of a run with `params` (its optional groups present, values 0).
DiagnosticsSample diagnostics_layout(const SystemParams& params);
// The layout whose columns are the names of a file's header, in any order of groups the writer
// uses; std::nullopt when the names are not the columns of any layout of this version.
std::optional<DiagnosticsSample> diagnostics_layout_of(const std::vector<std::string>& names);

// In 3D the Chapter 4 flow measures (2D pictures of bands and clusters) are NaN.
template <int D>
class GlobalDiagnostics final : public EventObserver<D> {
 public:
  // `cells` is the coarse-graining grid of T̄ and κ (independent of the engine's cells).
  GlobalDiagnostics(const SystemParams& params, const FieldGrid& cells);
  // 2D: a grid of cells_x × cells_y.
  GlobalDiagnostics(const SystemParams& params, int cells_x, int cells_y)
      : GlobalDiagnostics(params, FieldGrid{cells_x, cells_y, params.length_x, params.length_y}) {}

  void on_collision(const CollisionRecord<D>& record) override;
  void on_surface_hit(const SurfaceHitRecord<D>& record) override {
    walls_.add(record);
    obstacles_.add(record);
  }
  void on_rest_change(const RestRecord<D>& record) override { walls_.add(record); }
  // An empty sample with this run's columns (for readers of checkpoints).
  DiagnosticsSample layout() const { return diagnostics_layout(params_); }
  // Measure the configuration `state` at time t (collisions since production started) and
  // close the current interval.  `shear_velocity` and `shear_offset` are the image velocity U and
  // offset Δ at time t (they change with time under a shear protocol).
  DiagnosticsSample sample(const StateBlocks& state, double t, std::int64_t collisions, double shear_velocity,
                           double shear_offset);
  // Forget the open interval's collisions (e.g. after the elastic pre-run).
  void restart_interval(double t, std::int64_t collisions);
  // The open interval (a checkpoint).
  void save(StateArchive& archive, const std::string& prefix) const;
  void restore(const StateArchive& archive, const std::string& prefix);

 private:
  // Fields of the coarse-graining cells, optionally of the velocities relative to u(y).
  CellFields cell_fields(const StateBlocks& state, bool subtract_shear_profile) const;

  SystemParams params_;
  ShearFrame frame_;
  FieldGrid grid_;  // coarse-graining cells of T̄ and κ
  double impulse_sum_ = 0.0;     // Σ J σ_ij/σ over the interval (Σ J when monodisperse)
  double impulse_xy_sum_ = 0.0;  // Σ σ_ij/σ k_y P_x, P = J k̂ + P_t (J k_x k_y for smooth grains)
  double interval_start_ = 0.0;
  std::int64_t interval_collisions_ = 0;
  WallStress<D> walls_;
  ObstacleForces<D> obstacles_;
};

}  // namespace granule
