#include "observers/collisional_stress.hpp"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace granule {

namespace {

// The per-cell sums with their checkpoint names, in one list: the 2D set, then the z components in 3D.
// With `full`, the entries below the diagonal follow.
template <typename Sums>
auto sum_arrays(Sums& s, int dimension, bool full) {
  std::vector<std::pair<const char*, decltype(&s.xx)>> arrays{
      {"sum_xx", &s.xx},           {"sum_xy", &s.xy},           {"sum_yy", &s.yy},
      {"sum_energy_x", &s.energy_x}, {"sum_energy_y", &s.energy_y}, {"count", &s.collisions}};
  if (dimension == 3) {
    arrays.insert(arrays.end(), {{"sum_xz", &s.xz}, {"sum_yz", &s.yz}, {"sum_zz", &s.zz}, {"sum_energy_z", &s.energy_z}});
  }
  if (full) {
    arrays.emplace_back("sum_yx", &s.yx);
    if (dimension == 3) arrays.insert(arrays.end(), {{"sum_zx", &s.zx}, {"sum_zy", &s.zy}});
  }
  return arrays;
}

template <int D>
std::size_t cell_of(const FieldGrid& grid, const Vec<D>& p) {
  if constexpr (D == 2) {
    return grid.index(p.x, p.y);
  } else {
    return grid.index(p.x, p.y, p.z);
  }
}

}  // namespace

std::vector<double>& CollisionalStress::component(int a, int b) {
  if (a > b && full()) return a == 1 ? yx : (b == 0 ? zx : zy);
  if (a > b) std::swap(a, b);
  if (b == 2) return a == 0 ? xz : (a == 1 ? yz : zz);
  return a == 0 ? (b == 0 ? xx : xy) : yy;
}

double CollisionalStress::pressure(std::size_t c) const {
  return zz.empty() ? 0.5 * (xx[c] + yy[c]) : (xx[c] + yy[c] + zz[c]) / 3.0;
}

template <int D>
Vec<D> pair_velocity_at_contact(const CollisionRecord<D>& r, double diameter, double length_y) {
  // Before mapping into the box the contact point lies σ/2 from particle 1 along k̂; the recorded
  // one is a box height away from there when it was mapped to particle 2's side.
  const double unmapped_y = r.first_position.y + 0.5 * diameter * r.contact_normal.y;
  const bool on_second_side = std::abs(unmapped_y - r.contact_point.y) > 0.5 * length_y;
  const Vec<D> half_relative = 0.5 * r.relative_velocity;  // v₂₁/2 = (v₁ − v₂)/2
  return on_second_side ? r.second_velocity_before + half_relative : r.first_velocity_before - half_relative;
}

template <int D>
CollisionalStressField<D>::CollisionalStressField(const FieldGrid& grid, std::optional<double> diameter, bool rough)
    : grid_(grid), diameter_(diameter), rough_(rough) {
  if (rough_) sums_.yx.assign(grid.cells(), 0.0);  // full() before the list is taken
  for (const auto& [name, values] : sum_arrays(sums_, D, rough_)) values->assign(grid.cells(), 0.0);
}

template <int D>
void CollisionalStressField<D>::on_collision(const CollisionRecord<D>& r) {
  const std::size_t c = cell_of(grid_, r.contact_point);
  // σ_ij J, in units of the monodisperse σ (which the interval's scale multiplies in).
  const double j = diameter_ ? r.impulse : r.contact_distance * r.impulse;
  const Vec<D> k = r.contact_normal;
  const Vec<D> s = pair_velocity_at_contact(r, diameter_.value_or(r.contact_distance), grid_.length_y);
  double along = dot(k, s);  // k̂·s, plus the energy the unequal masses carry across (header)
  if (r.first_mass != r.second_mass) along += 0.25 * r.impulse * (1.0 / r.second_mass - 1.0 / r.first_mass);
  double carried = j * along;
  if (rough_) {
    // σ_ij k̂_a P_t,b on every entry, and the energy P_t moves (header).
    const double w = diameter_ ? 1.0 : r.contact_distance;
    const Vec<D>& pt = r.tangential_impulse;
    double tangential_along = dot(pt, s);
    if (r.first_mass != r.second_mass) tangential_along += 0.25 * dot(pt, pt) * (1.0 / r.second_mass - 1.0 / r.first_mass);
    carried += w * tangential_along;
    for (int a = 0; a < D; ++a) {
      for (int b = 0; b < D; ++b) sums_.component(a, b)[c] += j * k[a] * k[b] + w * k[a] * pt[b];
    }
  } else {
    for (int a = 0; a < D; ++a) {
      for (int b = a; b < D; ++b) sums_.component(a, b)[c] += j * k[a] * k[b];
    }
  }
  for (int a = 0; a < D; ++a) sums_.energy(a)[c] += carried * k[a];
  sums_.collisions[c] += 1.0;
}

template <int D>
void CollisionalStressField<D>::restart(double t) {
  start_ = t;
  for (const auto& [name, values] : sum_arrays(sums_, D, rough_)) std::fill(values->begin(), values->end(), 0.0);
}

template <int D>
CollisionalStress CollisionalStressField<D>::stress(double t) const {
  CollisionalStress out = sums_;
  out.interval = t - start_;
  const double scale = out.interval > 0.0 ? diameter_.value_or(1.0) / (grid_.cell_volume() * out.interval) : 0.0;
  for (const auto& [name, values] : sum_arrays(out, D, rough_)) {
    if (values == &out.collisions) continue;
    for (double& x : *values) x *= scale;
  }
  return out;
}

template <int D>
void CollisionalStressField<D>::save(StateArchive& archive, const std::string& prefix) const {
  archive.put_scalar(prefix + "start", start_);
  for (const auto& [name, values] : sum_arrays(sums_, D, rough_)) archive.put(prefix + name, *values);
}

template <int D>
void CollisionalStressField<D>::restore(const StateArchive& archive, const std::string& prefix) {
  start_ = archive.scalar(prefix + "start");
  for (const auto& [name, values] : sum_arrays(sums_, D, rough_)) *values = archive.get_sized<double>(prefix + name, grid_.cells());
}

HeatFlux collisional_heat_flux(const CollisionalStress& s, const std::vector<double>& reference_x,
                               const std::vector<double>& reference_y, const std::vector<double>& reference_z) {
  const int d = s.zz.empty() ? 2 : 3;
  const std::vector<const std::vector<double>*> reference{&reference_x, &reference_y, &reference_z};
  HeatFlux q{s.energy_x, s.energy_y, s.energy_z};
  for (int a = 0; a < d; ++a) {
    std::vector<double>& qa = q.component(a);
    for (std::size_t c = 0; c < qa.size(); ++c) {
      // 1/(V t) Σ σ_ij J k̂ k̂·(s − V) = E/(V t) − τ^(c)·V.
      double transported = s.component(a, 0)[c] * (*reference[0])[c];
      for (int b = 1; b < d; ++b) transported += s.component(a, b)[c] * (*reference[static_cast<std::size_t>(b)])[c];
      qa[c] -= transported;
    }
  }
  return q;
}

HeatFlux collisional_heat_flux(const CollisionalStress& stress, const CellFields& average, const ShearFrame& frame,
                               bool shear_profile_subtracted) {
  const FieldGrid& g = average.grid;
  std::vector<double> reference_x = average.velocity_x;
  if (shear_profile_subtracted) {
    for (std::size_t c = 0; c < g.cells(); ++c) {
      const auto row = static_cast<int>((c / static_cast<std::size_t>(g.nx)) % static_cast<std::size_t>(g.ny));
      reference_x[c] += frame.mean_flow(g.center_y(row));
    }
  }
  return collisional_heat_flux(stress, reference_x, average.velocity_y, average.velocity_z);
}

template class CollisionalStressField<2>;
template class CollisionalStressField<3>;
template Vec<2> pair_velocity_at_contact(const CollisionRecord<2>&, double, double);
template Vec<3> pair_velocity_at_contact(const CollisionRecord<3>&, double, double);

}  // namespace granule
