// The global time series of a run (thesis §1.4.3, §2.1, Figs 2.5–2.7, 3.6): kinetic energy,
// the granular temperature T̄ (mean of cell temperatures, eq 1.3, with velocities relative to the
// imposed shear profile; the thesis's plain cell definition beside it), the global fluctuation
// temperature, flatness κ (1.8), two asymmetry measures, kinetic and collisional pressures
// (half traces of 1.4 and 1.6), the collision rate, and the scalars that classify the flow states
// of Chapter 4 (analysis/flow_classification.hpp).  Collisional quantities are accumulated from
// every collision record over the sampling interval.
#pragma once

#include <cstdint>

#include "analysis/cell_fields.hpp"
#include "analysis/field_grid.hpp"
#include "analysis/flow_classification.hpp"
#include "boundary/shear_frame.hpp"
#include "engine/observer.hpp"
#include "engine/state_archive.hpp"
#include "engine/system_params.hpp"

namespace granule {

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
}

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
  // Measure the configuration `state` at time t (collisions since production started) and
  // close the current interval.  `shear_velocity` and `shear_offset` are the image velocity U and
  // offset Δ at time t (they change with time under a shear protocol).
  DiagnosticsSample sample(const ParticleState& state, double t, std::int64_t collisions, double shear_velocity,
                           double shear_offset);
  // Forget the open interval's collisions (e.g. after the elastic pre-run).
  void restart_interval(double t, std::int64_t collisions);
  // The open interval (a checkpoint).
  void save(StateArchive& archive, const std::string& prefix) const;
  void restore(const StateArchive& archive, const std::string& prefix);

 private:
  // Fields of the coarse-graining cells, optionally of the velocities relative to u(y).
  CellFields cell_fields(const ParticleState& state, bool subtract_shear_profile) const;

  SystemParams params_;
  ShearFrame frame_;
  FieldGrid grid_;  // coarse-graining cells of T̄ and κ
  double impulse_sum_ = 0.0;     // Σ J σ_ij/σ over the interval (Σ J when monodisperse)
  double impulse_xy_sum_ = 0.0;  // Σ J σ_ij/σ k_x k_y
  double interval_start_ = 0.0;
  std::int64_t interval_collisions_ = 0;
};

}  // namespace granule
