#include "analysis/cell_fields.hpp"

#include <array>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace granule {

namespace {

// The z arrays exist only on a 3D grid.
std::vector<double> cells_if(bool present, const FieldGrid& g) { return std::vector<double>(present ? g.cells() : 0); }

// The (a, b) entry, a ≤ b or not, of a symmetric tensor stored as six named members.
template <typename Tensor>
auto& symmetric_entry(Tensor& xx, Tensor& xy, Tensor& xz, Tensor& yy, Tensor& yz, Tensor& zz, int a, int b) {
  if (a > b) std::swap(a, b);
  if (a == 0) return b == 0 ? xx : (b == 1 ? xy : xz);
  return a == 1 ? (b == 1 ? yy : yz) : zz;
}

}  // namespace

CellMoments::CellMoments(const FieldGrid& g, const SpinInertia& spin_inertia)
    : grid(g), inertia(spin_inertia), count(g.cells()), px(g.cells()), py(g.cells()), pxx(g.cells()), pxy(g.cells()), pyy(g.cells()),
      energy_flux_x(g.cells()), energy_flux_y(g.cells()), pz(cells_if(g.dimension == 3, g)),
      pxz(cells_if(g.dimension == 3, g)), pyz(cells_if(g.dimension == 3, g)), pzz(cells_if(g.dimension == 3, g)),
      energy_flux_z(cells_if(g.dimension == 3, g)) {}

std::vector<double>& CellMoments::second_moment(int a, int b) { return symmetric_entry(pxx, pxy, pxz, pyy, pyz, pzz, a, b); }

std::vector<double>& CellFields::kinetic(int a, int b) {
  return symmetric_entry(kinetic_xx, kinetic_xy, kinetic_xz, kinetic_yy, kinetic_yz, kinetic_zz, a, b);
}

namespace {

constexpr const char* kSpinMomentNames[3] = {"spin_x", "spin_y", "spin_z"};

// The moment arrays with their checkpoint names, in one list: the 2D set (all a 2D checkpoint
// holds), the z components in 3D, Σm when masses were seen.
template <typename Moments>
auto moment_arrays(Moments& m) {
  std::vector<std::pair<const char*, decltype(&m.count)>> arrays{
      {"count", &m.count}, {"px", &m.px}, {"py", &m.py}, {"pxx", &m.pxx}, {"pxy", &m.pxy}, {"pyy", &m.pyy},
      {"energy_flux_x", &m.energy_flux_x}, {"energy_flux_y", &m.energy_flux_y}};
  if (m.grid.dimension == 3) {
    arrays.insert(arrays.end(), {{"pz", &m.pz}, {"pxz", &m.pxz}, {"pyz", &m.pyz}, {"pzz", &m.pzz}, {"energy_flux_z", &m.energy_flux_z}});
  }
  if (!m.mass.empty()) arrays.emplace_back("mass", &m.mass);
  if (m.rough()) {
    arrays.emplace_back("inertia_sum", &m.inertia_sum);
    for (int k = first_spin_axis(m.grid.dimension); k < 3; ++k) arrays.emplace_back(kSpinMomentNames[k], &m.spin(k));
    arrays.emplace_back("spin_square", &m.spin_square);
  }
  return arrays;
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
  if (archive.contains(prefix + "mass")) mass.resize(grid.cells());
  if (archive.contains(prefix + "inertia_sum")) start_spin_moments();
  for (const auto& [name, values] : moment_arrays(*this)) {
    *values = archive.get_sized<double>(prefix + name, grid.cells());
  }
}

double cell_moments_bytes(const FieldGrid& grid, bool masses, bool rough) {
  FieldGrid one_cell;
  one_cell.dimension = grid.dimension;
  CellMoments probe(one_cell);
  if (masses) probe.mass.resize(1);
  if (rough) probe.inertia_sum.resize(1);
  return static_cast<double>(sizeof(double) * moment_arrays(probe).size()) * static_cast<double>(grid.cells());
}

double cell_fields_bytes(const FieldGrid& grid, bool rough) {
  CellFields probe;
  probe.grid.dimension = grid.dimension;
  probe.rough = rough;
  double arrays = 0.0;
  for_each_field(probe, [&arrays](const char*, const std::vector<double>&) { arrays += 1.0; });
  return sizeof(double) * arrays * static_cast<double>(grid.cells());
}

void CellMoments::add(const StateBlocks& blocks, const ShearFrame& frame, bool subtract_shear_profile) {
  blocks.for_each([&](const ParticleState& state, std::size_t) { add_particles(state, frame, subtract_shear_profile); });
  ++configurations;
}

void CellMoments::add_particles(const ParticleState& state, const ShearFrame& frame, bool subtract_shear_profile) {
  const int d = grid.dimension;
  if (state.dimension != d) {
    throw std::invalid_argument("a " + std::to_string(state.dimension) + "D configuration on a " + std::to_string(d) + "D field grid");
  }
  if (!state.mass.empty() && mass.empty()) mass = count;  // the unit masses added so far
  // Spins are summed when the moment of inertia is known (analyses that need no spin fields pass none).
  const bool with_spin = state.rough() && inertia.inertia_factor > 0.0;
  if (with_spin && !rough()) start_spin_moments();  // the smooth configurations added so far did not spin
  std::array<std::vector<double>*, 3> p{}, flux{};
  std::array<std::array<std::vector<double>*, 3>, 3> second{};
  for (int a = 0; a < d; ++a) {
    p[a] = &momentum(a);
    flux[a] = &energy_flux(a);
    for (int b = a; b < d; ++b) second[a][b] = &second_moment(a, b);
  }
  for (std::size_t i = 0; i < state.size(); ++i) {
    const std::size_t c = d == 3 ? grid.index(state.x[i], state.y[i], state.z[i]) : grid.index(state.x[i], state.y[i]);
    const std::array<double, 3> v{state.vx[i] - (subtract_shear_profile ? frame.mean_flow(state.y[i]) : 0.0), state.vy[i],
                                  d == 3 ? state.vz[i] : 0.0};
    const double m = state.mass_of(i);  // 1 for unit masses: every product below is then exact
    double speed2 = v[0] * v[0];
    for (int a = 1; a < d; ++a) speed2 += v[a] * v[a];
    count[c] += 1.0;
    if (!mass.empty()) mass[c] += m;
    for (int a = 0; a < d; ++a) {
      (*p[a])[c] += m * v[a];
      for (int b = a; b < d; ++b) (*second[a][b])[c] += m * v[a] * v[b];
      (*flux[a])[c] += m * speed2 * v[a];
    }
    if (with_spin) add_spin(state, i, c);
  }
}

void CellMoments::start_spin_moments() {
  inertia_sum.assign(grid.cells(), 0.0);
  for (int k = first_spin_axis(grid.dimension); k < 3; ++k) spin(k).assign(grid.cells(), 0.0);
  spin_square.assign(grid.cells(), 0.0);
}

void CellMoments::add_spin(const ParticleState& state, std::size_t i, std::size_t c) {
  const double moment = inertia.of(state, i);
  inertia_sum[c] += moment;
  for (int k = first_spin_axis(grid.dimension); k < 3; ++k) {
    const double w = state.spin(k)[i];
    spin(k)[c] += moment * w;
    spin_square[c] += moment * w * w;
  }
}

namespace {

// Value of a cell-centred row field at abscissa x (periodic linear interpolation), in layer iz.
double row_value_at(const std::vector<double>& field, const FieldGrid& grid, int iy, int iz, double x) {
  const double u = x / grid.cell_width() - 0.5;
  const double left = std::floor(u);
  const double w = u - left;
  const auto wrap = [&](double ix) {
    const int k = static_cast<int>(ix) % grid.nx;
    return k < 0 ? k + grid.nx : k;
  };
  return (1.0 - w) * field[grid.index_of_cell(wrap(left), iy, iz)] + w * field[grid.index_of_cell(wrap(left + 1.0), iy, iz)];
}

// ω_z by central differences in each layer; across the top and bottom the neighbour row is the
// Lees–Edwards image of the opposite row (shifted by Δ, moving at ±U in the lab frame).
void fill_vorticity(CellFields& f, const ShearFrame& frame, double shear_offset, bool shear_profile_subtracted) {
  const FieldGrid& g = f.grid;
  const double image_velocity = shear_profile_subtracted ? 0.0 : frame.shear_velocity;
  for (int iz = 0; iz < g.nz; ++iz) {
    for (int iy = 0; iy < g.ny; ++iy) {
      for (int ix = 0; ix < g.nx; ++ix) {
        const double x = g.center_x(ix);
        const double right = row_value_at(f.velocity_y, g, iy, iz, x + g.cell_width());
        const double left = row_value_at(f.velocity_y, g, iy, iz, x - g.cell_width());
        const double above = iy + 1 < g.ny ? row_value_at(f.velocity_x, g, iy + 1, iz, x)
                                           : row_value_at(f.velocity_x, g, 0, iz, x - shear_offset) + image_velocity;
        const double below = iy > 0 ? row_value_at(f.velocity_x, g, iy - 1, iz, x)
                                    : row_value_at(f.velocity_x, g, g.ny - 1, iz, x + shear_offset) - image_velocity;
        f.vorticity[g.index_of_cell(ix, iy, iz)] = (right - left) / (2.0 * g.cell_width()) - (above - below) / (2.0 * g.cell_height());
      }
    }
  }
}

// Ω(r) = Σ I ω / Σ I and T_rot(r) = (Σ I|ω|² − Σ I |Ω|²) / (d_rot · count), the rotational
// analogue of (1.3) with (1.5)'s identity.
void fill_spin_fields(CellFields& f, const CellMoments& m) {
  const FieldGrid& g = f.grid;
  const int first = first_spin_axis(g.dimension);
  const double rotational_degrees = 3 - first;
  f.rough = true;
  for (int k = first; k < 3; ++k) f.spin(k).assign(g.cells(), 0.0);
  f.rotational_temperature.assign(g.cells(), 0.0);
  for (std::size_t c = 0; c < g.cells(); ++c) {
    if (m.inertia_sum[c] == 0.0) continue;
    double mean_square = 0.0;
    for (int k = first; k < 3; ++k) {
      const double mean = f.spin(k)[c] = m.spin(k)[c] / m.inertia_sum[c];
      mean_square += mean * mean;
    }
    f.rotational_temperature[c] = (m.spin_square[c] - m.inertia_sum[c] * mean_square) / (rotational_degrees * m.count[c]);
  }
}

}  // namespace

CellFields fields_from_moments(const CellMoments& m, const ShearFrame& frame, double shear_offset,
                               bool shear_profile_subtracted) {
  const FieldGrid& g = m.grid;
  const int d = g.dimension;
  const std::size_t n = g.cells();
  const double k = m.configurations > 0 ? static_cast<double>(m.configurations) : 1.0;
  CellFields f;
  f.grid = g;
  for_each_field(f, [n](const char*, std::vector<double>& v) { v.assign(n, 0.0); });
  for (std::size_t c = 0; c < n; ++c) {
    f.count[c] = m.count[c] / k;
    f.density[c] = f.count[c] / g.cell_volume();
    if (m.count[c] == 0.0) continue;
    const double n_c = m.count[c];
    const double mass = m.mass.empty() ? n_c : m.mass[c];
    const double mass_density = m.mass.empty() ? f.density[c] : mass / k / g.cell_volume();
    std::array<double, 3> v{};
    for (int a = 0; a < d; ++a) v[a] = f.velocity(a)[c] = m.momentum(a)[c] / mass;
    // Identity (1.5): ⟨v'_a v'_b⟩ = ⟨v_a v_b⟩ − ⟨v_a⟩⟨v_b⟩ (averages weighted by mass).
    // The diagonal terms are never −0 (Σ m v_a² ≥ 0), so sums from +0 are the 2D code's xx + yy bit for bit.
    double trace = 0.0, kinetic_trace = 0.0;
    for (int a = 0; a < d; ++a) {
      for (int b = a; b < d; ++b) {
        const double covariance = m.second_moment(a, b)[c] / mass - v[a] * v[b];
        f.kinetic(a, b)[c] = mass_density * covariance;
        if (a == b) {
          trace += covariance;
          kinetic_trace += f.kinetic(a, a)[c];
        }
      }
    }
    // T per degree of freedom: Σ m|v'|² / (d · count) = (M / count) Tr⟨v'v'⟩ / d (1.3).
    f.temperature[c] = (mass / n_c) * trace / d;
    f.pressure_kinetic[c] = kinetic_trace / d;
    // q^(k) from raw moments, as (1.5) does for the stress: with S₂ = Σ m v v, S₃ = Σ m|v|² v and
    // M = Σ m,  Σ m|v − V|² (v − V) = S₃ − V Tr S₂ − 2 S₂·V + 2 M |V|² V   (using Σ m v = M V).
    double raw_trace = m.pxx[c], speed2 = v[0] * v[0];
    for (int a = 1; a < d; ++a) {
      raw_trace += m.second_moment(a, a)[c];
      speed2 += v[a] * v[a];
    }
    for (int a = 0; a < d; ++a) {
      double second_dot_v = m.second_moment(a, 0)[c] * v[0];
      for (int b = 1; b < d; ++b) second_dot_v += m.second_moment(a, b)[c] * v[b];
      const double third = m.energy_flux(a)[c] - v[a] * raw_trace - 2.0 * second_dot_v + 2.0 * mass * speed2 * v[a];
      f.heat_flux_kinetic(a)[c] = 0.5 * third / (k * g.cell_volume());
    }
  }
  fill_vorticity(f, frame, shear_offset, shear_profile_subtracted);
  if (m.rough()) fill_spin_fields(f, m);
  return f;
}

}  // namespace granule

namespace granule {

std::vector<double> row_means(const FieldGrid& g, const std::vector<double>& field) {
  if (field.empty()) return {};  // a field the caller did not fill (e.g. read from an older file)
  std::vector<double> means(static_cast<std::size_t>(g.ny), 0.0);
  const auto nx = static_cast<std::size_t>(g.nx), ny = static_cast<std::size_t>(g.ny);
  for (std::size_t c = 0; c < g.cells(); ++c) means[c / nx % ny] += field[c];
  for (double& v : means) v /= g.nx * g.nz;
  return means;
}

StreamwiseProfiles streamwise_profiles(const CellFields& f) {
  const FieldGrid& g = f.grid;
  StreamwiseProfiles p;
  p.heat_flux_kinetic_x = row_means(g, f.heat_flux_kinetic_x);
  p.heat_flux_kinetic_y = row_means(g, f.heat_flux_kinetic_y);
  for (int iy = 0; iy < g.ny; ++iy) {
    double rho = 0.0, vx = 0.0, vy = 0.0, t = 0.0;
    for (int iz = 0; iz < g.nz; ++iz) {
      for (int ix = 0; ix < g.nx; ++ix) {
        const std::size_t c = g.index_of_cell(ix, iy, iz);
        rho += f.density[c];
        vx += f.density[c] * f.velocity_x[c];
        vy += f.density[c] * f.velocity_y[c];
        t += f.density[c] * f.temperature[c];
      }
    }
    p.y.push_back(g.center_y(iy));
    p.density.push_back(rho / (g.nx * g.nz));
    p.velocity_x.push_back(rho > 0.0 ? vx / rho : 0.0);
    p.velocity_y.push_back(rho > 0.0 ? vy / rho : 0.0);
    p.temperature.push_back(rho > 0.0 ? t / rho : 0.0);
  }
  return p;
}

}  // namespace granule
