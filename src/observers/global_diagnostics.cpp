#include "observers/global_diagnostics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

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

DiagnosticsSample diagnostics_layout(const SystemParams& params) {
  DiagnosticsSample layout;
  if (params.roughness.rough) layout.rotation = RotationSample{};
  if (params.has_gravity()) layout.gravity = GravitySample{};
  for (std::size_t face = 0; face < layout.walls.size(); ++face) {
    if (params.walls[face / 2]) layout.walls[face] = WallFaceSample{};
  }
  if (!params.obstacles.empty()) {
    layout.obstacles = ObstacleForcesSample{params.dimension == 3, {}, std::vector<ObstacleForce>(params.obstacles.size())};
  }
  return layout;
}

std::optional<DiagnosticsSample> diagnostics_layout_of(const std::vector<std::string>& names) {
  const auto named = [&](const std::string& name) { return std::find(names.begin(), names.end(), name) != names.end(); };
  DiagnosticsSample layout;
  if (named("rotational_temperature")) layout.rotation = RotationSample{};
  if (named("potential_energy")) layout.gravity = GravitySample{};
  for (int face = 0; face < 6; ++face) {
    WallFaceSample probe;
    const char* first = nullptr;
    for_each_wall_column(face, probe, [&](const char* name, double&) { first = first ? first : name; });
    if (named(first)) layout.walls[static_cast<std::size_t>(face)] = probe;
  }
  if (named("obstacles_drag")) {
    layout.obstacles = ObstacleForcesSample{named("obstacles_force_z"), {}, {}};
    while (named("obstacle" + std::to_string(layout.obstacles->each.size()) + "_drag")) layout.obstacles->each.emplace_back();
  }
  std::vector<std::string> columns;
  for_each_column(layout, [&](const char* name, double&) { columns.emplace_back(name); });
  if (columns != names) return std::nullopt;
  return layout;
}

template <int D>
GlobalDiagnostics<D>::GlobalDiagnostics(const SystemParams& params, const FieldGrid& cells)
    : params_(params), frame_{params.length_x, params.length_y, params.shear_velocity}, grid_(cells), walls_(params), obstacles_(params) {}

template <int D>
void GlobalDiagnostics<D>::on_collision(const CollisionRecord<D>& record) {
  // The virial of the pair is J σ_ij; in units of σ so that equal sizes add J itself (ratio 1).
  const double weight = record.impulse * (record.contact_distance / params_.diameter);
  impulse_sum_ += weight;
  impulse_xy_sum_ += weight * record.contact_normal.x * record.contact_normal.y;
  if (params_.roughness.rough) {
    // The tangential impulse moves x momentum across planes of constant y too: the stress is
    // then not symmetric, and this column is the flux of x momentum along y (τ_yx, as a y wall feels).
    impulse_xy_sum_ += (record.contact_distance / params_.diameter) * record.contact_normal.y * record.tangential_impulse.x;
  }
}

template <int D>
void GlobalDiagnostics<D>::restart_interval(double t, std::int64_t collisions) {
  impulse_sum_ = 0.0;
  impulse_xy_sum_ = 0.0;
  interval_start_ = t;
  interval_collisions_ = collisions;
  walls_.clear(t);
  obstacles_.clear();
}

template <int D>
CellFields GlobalDiagnostics<D>::cell_fields(const StateBlocks& state, bool subtract_shear_profile) const {
  CellMoments moments(grid_, spin_inertia(params_));
  moments.add(state, frame_, subtract_shear_profile);
  return fields_from_moments(moments, frame_, 0.0, subtract_shear_profile);
}

template <int D>
DiagnosticsSample GlobalDiagnostics<D>::sample(const StateBlocks& state, double t, std::int64_t collisions,
                                               double shear_velocity, double shear_offset) {
  frame_.shear_velocity = shear_velocity;  // u(y) of the images' velocity now (shear protocols)
  const std::size_t n = state.size();
  const double nd = static_cast<double>(n);
  const double volume = params_.length_x * params_.length_y * (D == 3 ? params_.length_z : 1.0);
  constexpr double kPerDegree = 1.0 / D;  // T per degree of freedom (½ in 2D: eq 1.3)
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

  // One pass over the particles, block by block (each sum runs in particle order).  Lab velocity
  // v, fluctuation v − u(y), and v' = v − u(y) − V(r) with V(r) the cell mean of v − u (κ, eq 1.8;
  // §2.1): the same fluctuation whose cell variances make T̄; components summed x, y, z in order.
  double kinetic = 0.0, fluct = 0.0, fluct_xy = 0.0;
  double m2 = 0.0, m4 = 0.0, m3x = 0.0, m3y = 0.0;
  double spin_sum = 0.0, potential_sum = 0.0;  // Σ I|ω|², −Σ m g·r
  const SpinInertia inertia = spin_inertia(params_);
  state.for_each([&](const ParticleState& s, std::size_t) {
    const auto fluctuation = [&](std::size_t i, int axis) {
      return axis == 0 ? s.vx[i] - frame_.mean_flow(s.y[i]) : s.velocity(axis)[i];
    };
    for (std::size_t i = 0; i < s.size(); ++i) {
      double v2 = s.vx[i] * s.vx[i];
      double f2 = fluctuation(i, 0) * fluctuation(i, 0);
      for (int a = 1; a < D; ++a) {
        v2 += s.velocity(a)[i] * s.velocity(a)[i];
        f2 += fluctuation(i, a) * fluctuation(i, a);
      }
      const double m = s.mass_of(i);
      kinetic += m * v2;
      fluct += m * f2;
      fluct_xy += m * fluctuation(i, 0) * s.vy[i];

      const std::size_t c = D == 3 ? grid_.index(s.x[i], s.y[i], s.z[i]) : grid_.index(s.x[i], s.y[i]);
      const double ux = fluctuation(i, 0) - cells.velocity_x[c];
      const double uy = s.vy[i] - cells.velocity_y[c];
      double u2 = ux * ux + uy * uy;
      if constexpr (D == 3) {
        const double uz = s.vz[i] - cells.velocity_z[c];
        u2 += uz * uz;
      }
      m2 += u2;
      m4 += u2 * u2;
      m3x += ux * ux * ux;
      m3y += uy * uy * uy;

      if (params_.roughness.rough) {
        double w2 = 0.0;
        for (int k = first_spin_axis(D); k < 3; ++k) w2 += s.spin(k)[i] * s.spin(k)[i];
        spin_sum += inertia.of(s, i) * w2;
      }
      if (params_.has_gravity()) {
        double g_dot_r = 0.0;
        for (int a = 0; a < D; ++a) g_dot_r += params_.gravity[static_cast<std::size_t>(a)] * s.position(a)[i];
        potential_sum -= m * g_dot_r;
      }
    }
  });
  out.kinetic_energy = 0.5 * kinetic / nd;
  out.temperature_global = kPerDegree * fluct / nd;
  out.pressure_kinetic = kPerDegree * fluct / volume;
  out.shear_stress_kinetic = fluct_xy / volume;
  m2 /= nd;
  m4 /= nd;
  out.flatness = m2 > 0.0 ? m4 / (m2 * m2) : 0.0;
  const double scale = m2 > 0.0 ? std::pow(m2, 1.5) : 1.0;
  out.asymmetry_x = m3x / nd / scale;
  out.asymmetry_y = m3y / nd / scale;

  const double dt = t - interval_start_;
  if (dt > 0.0) {
    out.pressure_collisional = params_.diameter * impulse_sum_ / (static_cast<double>(D) * volume * dt);
    out.shear_stress_collisional = params_.diameter * impulse_xy_sum_ / (volume * dt);
    out.collision_rate = static_cast<double>(collisions - interval_collisions_) / nd / dt;
  }
  // The Chapter 4 flow measures, with ρ(y) and V_x(y) on the rows of the coarse-graining grid.
  if constexpr (D == 2) {
    FlowClassificationSettings classification;
    classification.rows = grid_.ny;
    out.flow = classify_flow(state, {params_.length_x, params_.length_y, shear_velocity}, shear_offset, params_.diameter,
                             classification);
  } else {
    for_each_flow_measure(out.flow, [](const char*, double& value) { value = std::numeric_limits<double>::quiet_NaN(); });
  }
  const double spin_energy = spin_sum / nd;  // ⟨I|ω|²⟩: twice the rotational kinetic energy per particle
  if (params_.roughness.rough) {
    const double rotational = spin_energy / (D == 3 ? 3.0 : 1.0);  // d_rot = 1 (disks), 3 (spheres)
    out.rotation = RotationSample{rotational, rotational / out.temperature_global};
  }
  if (params_.has_gravity()) {
    const double potential = potential_sum / nd;  // −⟨m g·r⟩, zero at the box's origin
    out.gravity = GravitySample{potential, out.kinetic_energy + 0.5 * spin_energy + potential};
  }
  out.walls = walls_.sample(t, dt);
  if (!params_.obstacles.empty()) out.obstacles = obstacles_.sample(dt);
  restart_interval(t, collisions);
  return out;
}

template <int D>
void GlobalDiagnostics<D>::save(StateArchive& archive, const std::string& prefix) const {
  archive.put_scalar(prefix + "impulse_sum", impulse_sum_);
  archive.put_scalar(prefix + "impulse_xy_sum", impulse_xy_sum_);
  archive.put_scalar(prefix + "interval_start", interval_start_);
  archive.put_integer(prefix + "interval_collisions", interval_collisions_);
  if (params_.has_walls()) walls_.save(archive, prefix);
  if (!params_.obstacles.empty()) obstacles_.save(archive, prefix);
}

template <int D>
void GlobalDiagnostics<D>::restore(const StateArchive& archive, const std::string& prefix) {
  impulse_sum_ = archive.scalar(prefix + "impulse_sum");
  impulse_xy_sum_ = archive.scalar(prefix + "impulse_xy_sum");
  interval_start_ = archive.scalar(prefix + "interval_start");
  interval_collisions_ = archive.integer(prefix + "interval_collisions");
  if (params_.has_walls()) walls_.restore(archive, prefix);
  if (!params_.obstacles.empty()) obstacles_.restore(archive, prefix);
}

template class GlobalDiagnostics<2>;
template class GlobalDiagnostics<3>;

}  // namespace granule
