#include "analysis/cell_fields.hpp"

#include <array>
#include <cmath>
#include <utility>

namespace granule {

CellMoments::CellMoments(const FieldGrid& g)
    : grid(g), count(g.cells()), px(g.cells()), py(g.cells()), pxx(g.cells()), pxy(g.cells()), pyy(g.cells()),
      energy_flux_x(g.cells()), energy_flux_y(g.cells()) {}

namespace {

// The moment arrays with their checkpoint names, in one list.
template <typename Moments>
auto moment_arrays(Moments& m) {
  return std::array{std::pair{"count", &m.count}, std::pair{"px", &m.px},   std::pair{"py", &m.py},
                    std::pair{"pxx", &m.pxx},     std::pair{"pxy", &m.pxy}, std::pair{"pyy", &m.pyy},
                    std::pair{"energy_flux_x", &m.energy_flux_x}, std::pair{"energy_flux_y", &m.energy_flux_y}};
}

}  // namespace

void CellMoments::save(StateArchive& archive, const std::string& prefix) const {
  archive.put_integer(prefix + "configurations", configurations);
  for (const auto& [name, values] : moment_arrays(*this)) {
    archive.put(prefix + name, *values);
  }
}

void CellMoments::restore(const StateArchive& archive, const std::string& prefix) {
  configurations = static_cast<int>(archive.integer(prefix + "configurations"));
  for (const auto& [name, values] : moment_arrays(*this)) {
    *values = archive.get_sized<double>(prefix + name, grid.cells());
  }
}

void CellMoments::add(const ParticleState& state, const ShearFrame& frame, bool subtract_shear_profile) {
  for (std::size_t i = 0; i < state.size(); ++i) {
    const std::size_t c = grid.index(state.x[i], state.y[i]);
    const double vx = state.vx[i] - (subtract_shear_profile ? frame.mean_flow(state.y[i]) : 0.0);
    const double vy = state.vy[i];
    count[c] += 1.0;
    px[c] += vx;
    py[c] += vy;
    pxx[c] += vx * vx;
    pxy[c] += vx * vy;
    pyy[c] += vy * vy;
    energy_flux_x[c] += (vx * vx + vy * vy) * vx;
    energy_flux_y[c] += (vx * vx + vy * vy) * vy;
  }
  ++configurations;
}

namespace {

// Value of a cell-centred row field at abscissa x (periodic linear interpolation).
double row_value_at(const std::vector<double>& field, const FieldGrid& grid, int iy, double x) {
  const double u = x / grid.cell_width() - 0.5;
  const double left = std::floor(u);
  const double w = u - left;
  const auto wrap = [&](double ix) {
    const int k = static_cast<int>(ix) % grid.nx;
    return static_cast<std::size_t>(k < 0 ? k + grid.nx : k);
  };
  const std::size_t row = static_cast<std::size_t>(iy) * static_cast<std::size_t>(grid.nx);
  return (1.0 - w) * field[row + wrap(left)] + w * field[row + wrap(left + 1.0)];
}

}  // namespace

CellFields fields_from_moments(const CellMoments& m, const ShearFrame& frame, double shear_offset,
                               bool shear_profile_subtracted) {
  const FieldGrid& g = m.grid;
  const std::size_t n = g.cells();
  const double k = m.configurations > 0 ? static_cast<double>(m.configurations) : 1.0;
  CellFields f;
  f.grid = g;
  for_each_field(f, [n](const char*, std::vector<double>& v) { v.assign(n, 0.0); });
  for (std::size_t c = 0; c < n; ++c) {
    f.count[c] = m.count[c] / k;
    f.density[c] = f.count[c] / g.cell_area();
    if (m.count[c] == 0.0) continue;
    const double vx = m.px[c] / m.count[c], vy = m.py[c] / m.count[c];
    f.velocity_x[c] = vx;
    f.velocity_y[c] = vy;
    // Identity (1.5): ⟨v'_a v'_b⟩ = ⟨v_a v_b⟩ − ⟨v_a⟩⟨v_b⟩.
    const double xx = m.pxx[c] / m.count[c] - vx * vx;
    const double xy = m.pxy[c] / m.count[c] - vx * vy;
    const double yy = m.pyy[c] / m.count[c] - vy * vy;
    f.temperature[c] = 0.5 * (xx + yy);
    f.kinetic_xx[c] = f.density[c] * xx;
    f.kinetic_xy[c] = f.density[c] * xy;
    f.kinetic_yy[c] = f.density[c] * yy;
    f.pressure_kinetic[c] = 0.5 * (f.kinetic_xx[c] + f.kinetic_yy[c]);
    // q^(k) from raw moments, as (1.5) does for the stress: with S₂ = Σ v v and S₃ = Σ |v|² v,
    //   Σ |v − V|² (v − V) = S₃ − V Tr S₂ − 2 S₂·V + 2 n |V|² V   (using Σ v = n V).
    const double n_c = m.count[c];
    const double trace = m.pxx[c] + m.pyy[c];
    const double speed2 = vx * vx + vy * vy;
    const double third_x = m.energy_flux_x[c] - vx * trace - 2.0 * (m.pxx[c] * vx + m.pxy[c] * vy) + 2.0 * n_c * speed2 * vx;
    const double third_y = m.energy_flux_y[c] - vy * trace - 2.0 * (m.pxy[c] * vx + m.pyy[c] * vy) + 2.0 * n_c * speed2 * vy;
    f.heat_flux_kinetic_x[c] = 0.5 * third_x / (k * g.cell_area());
    f.heat_flux_kinetic_y[c] = 0.5 * third_y / (k * g.cell_area());
  }
  // Vorticity by central differences; across the top and bottom the neighbour row is the
  // Lees–Edwards image of the opposite row (shifted by Δ, moving at ±U in the lab frame).
  const double image_velocity = shear_profile_subtracted ? 0.0 : frame.shear_velocity;
  for (int iy = 0; iy < g.ny; ++iy) {
    for (int ix = 0; ix < g.nx; ++ix) {
      const std::size_t c = static_cast<std::size_t>(ix) + static_cast<std::size_t>(iy) * static_cast<std::size_t>(g.nx);
      const double x = g.center_x(ix);
      const double right = row_value_at(f.velocity_y, g, iy, x + g.cell_width());
      const double left = row_value_at(f.velocity_y, g, iy, x - g.cell_width());
      const double above = iy + 1 < g.ny ? row_value_at(f.velocity_x, g, iy + 1, x)
                                         : row_value_at(f.velocity_x, g, 0, x - shear_offset) + image_velocity;
      const double below = iy > 0 ? row_value_at(f.velocity_x, g, iy - 1, x)
                                  : row_value_at(f.velocity_x, g, g.ny - 1, x + shear_offset) - image_velocity;
      f.vorticity[c] = (right - left) / (2.0 * g.cell_width()) - (above - below) / (2.0 * g.cell_height());
    }
  }
  return f;
}

}  // namespace granule

namespace granule {

std::vector<double> row_means(const FieldGrid& g, const std::vector<double>& field) {
  if (field.empty()) return {};  // a field the caller did not fill (e.g. read from an older file)
  std::vector<double> means(static_cast<std::size_t>(g.ny), 0.0);
  for (std::size_t c = 0; c < g.cells(); ++c) means[c / static_cast<std::size_t>(g.nx)] += field[c];
  for (double& v : means) v /= g.nx;
  return means;
}

StreamwiseProfiles streamwise_profiles(const CellFields& f) {
  const FieldGrid& g = f.grid;
  StreamwiseProfiles p;
  p.heat_flux_kinetic_x = row_means(g, f.heat_flux_kinetic_x);
  p.heat_flux_kinetic_y = row_means(g, f.heat_flux_kinetic_y);
  for (int iy = 0; iy < g.ny; ++iy) {
    double rho = 0.0, vx = 0.0, vy = 0.0, t = 0.0;
    for (int ix = 0; ix < g.nx; ++ix) {
      const std::size_t c = static_cast<std::size_t>(ix) + static_cast<std::size_t>(iy) * static_cast<std::size_t>(g.nx);
      rho += f.density[c];
      vx += f.density[c] * f.velocity_x[c];
      vy += f.density[c] * f.velocity_y[c];
      t += f.density[c] * f.temperature[c];
    }
    p.y.push_back(g.center_y(iy));
    p.density.push_back(rho / g.nx);
    p.velocity_x.push_back(rho > 0.0 ? vx / rho : 0.0);
    p.velocity_y.push_back(rho > 0.0 ? vy / rho : 0.0);
    p.temperature.push_back(rho > 0.0 ? t / rho : 0.0);
  }
  return p;
}

}  // namespace granule
