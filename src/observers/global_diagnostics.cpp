#include "observers/global_diagnostics.hpp"

#include <cmath>

namespace granule {

namespace {

// T̄: the mean of T(r) over the occupied cells (thesis §1.4.3, after eq 1.7).
double mean_cell_temperature(const CellFields& cells) {
  double temperature_sum = 0.0;
  int occupied = 0;
  for (std::size_t c = 0; c < cells.grid.cells(); ++c) {
    if (cells.count[c] == 0.0) continue;
    temperature_sum += cells.temperature[c];
    ++occupied;
  }
  return occupied > 0 ? temperature_sum / occupied : 0.0;
}

}  // namespace

GlobalDiagnostics::GlobalDiagnostics(const SystemParams& params, int cells_x, int cells_y)
    : params_(params),
      frame_{params.length_x, params.length_y, params.shear_velocity},
      grid_{cells_x, cells_y, params.length_x, params.length_y} {}

void GlobalDiagnostics::on_collision(const CollisionRecord<2>& record) {
  impulse_sum_ += record.impulse;
  impulse_xy_sum_ += record.impulse * record.contact_normal.x * record.contact_normal.y;
}

void GlobalDiagnostics::restart_interval(double t, std::int64_t collisions) {
  impulse_sum_ = 0.0;
  impulse_xy_sum_ = 0.0;
  interval_start_ = t;
  interval_collisions_ = collisions;
}

CellFields GlobalDiagnostics::cell_fields(const ParticleState& state, bool subtract_shear_profile) const {
  CellMoments moments(grid_);
  moments.add(state, frame_, subtract_shear_profile);
  return fields_from_moments(moments, frame_, 0.0, subtract_shear_profile);
}

DiagnosticsSample GlobalDiagnostics::sample(const ParticleState& state, double t, std::int64_t collisions,
                                            double shear_velocity, double shear_offset) {
  frame_.shear_velocity = shear_velocity;  // u(y) of the images' velocity now (shear protocols)
  const std::size_t n = state.size();
  const double nd = static_cast<double>(n);
  const double area = params_.length_x * params_.length_y;
  DiagnosticsSample out;
  out.t = t;
  out.c = static_cast<double>(collisions) / nd;
  out.shear_velocity = shear_velocity;

  // V(r) and T(r) of the coarse-graining cells (§1.4.3, eq 1.3), with velocities taken relative to
  // the imposed mean flow u(y): otherwise the shear γ h across a cell of height h would count as
  // heat (γ² h²/24 per disk), and T̄ would depend on the grid.
  const CellFields cells = cell_fields(state, true);
  out.temperature = mean_cell_temperature(cells);
  out.temperature_thesis_cells = frame_.sheared() ? mean_cell_temperature(cell_fields(state, false)) : out.temperature;

  double kinetic = 0.0, fluct = 0.0, fluct_xy = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double vx = state.vx[i], vy = state.vy[i];
    kinetic += vx * vx + vy * vy;
    const double ux = vx - frame_.mean_flow(state.y[i]);
    fluct += ux * ux + vy * vy;
    fluct_xy += ux * vy;
  }
  out.kinetic_energy = 0.5 * kinetic / nd;
  out.temperature_global = 0.5 * fluct / nd;
  out.pressure_kinetic = 0.5 * fluct / area;
  out.shear_stress_kinetic = fluct_xy / area;

  // Moments of the fluctuating velocity v' = v − u(y) − V(r), V(r) the cell mean of v − u (κ,
  // eq 1.8; §2.1): the same fluctuation whose cell variances make T̄.
  double m2 = 0.0, m4 = 0.0, m3x = 0.0, m3y = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t c = grid_.index(state.x[i], state.y[i]);
    const double ux = state.vx[i] - frame_.mean_flow(state.y[i]) - cells.velocity_x[c];
    const double uy = state.vy[i] - cells.velocity_y[c];
    const double u2 = ux * ux + uy * uy;
    m2 += u2;
    m4 += u2 * u2;
    m3x += ux * ux * ux;
    m3y += uy * uy * uy;
  }
  m2 /= nd;
  m4 /= nd;
  out.flatness = m2 > 0.0 ? m4 / (m2 * m2) : 0.0;
  const double scale = m2 > 0.0 ? std::pow(m2, 1.5) : 1.0;
  out.asymmetry_x = m3x / nd / scale;
  out.asymmetry_y = m3y / nd / scale;

  const double dt = t - interval_start_;
  if (dt > 0.0) {
    out.pressure_collisional = params_.diameter * impulse_sum_ / (2.0 * area * dt);
    out.shear_stress_collisional = params_.diameter * impulse_xy_sum_ / (area * dt);
    out.collision_rate = static_cast<double>(collisions - interval_collisions_) / nd / dt;
  }
  // The Chapter 4 flow measures, with ρ(y) and V_x(y) on the rows of the coarse-graining grid.
  FlowClassificationSettings classification;
  classification.rows = grid_.ny;
  out.flow = classify_flow(state, {params_.length_x, params_.length_y, shear_velocity}, shear_offset, params_.diameter,
                           classification);
  restart_interval(t, collisions);
  return out;
}

void GlobalDiagnostics::save(StateArchive& archive, const std::string& prefix) const {
  archive.put_scalar(prefix + "impulse_sum", impulse_sum_);
  archive.put_scalar(prefix + "impulse_xy_sum", impulse_xy_sum_);
  archive.put_scalar(prefix + "interval_start", interval_start_);
  archive.put_integer(prefix + "interval_collisions", interval_collisions_);
}

void GlobalDiagnostics::restore(const StateArchive& archive, const std::string& prefix) {
  impulse_sum_ = archive.scalar(prefix + "impulse_sum");
  impulse_xy_sum_ = archive.scalar(prefix + "impulse_xy_sum");
  interval_start_ = archive.scalar(prefix + "interval_start");
  interval_collisions_ = archive.integer(prefix + "interval_collisions");
}

}  // namespace granule
