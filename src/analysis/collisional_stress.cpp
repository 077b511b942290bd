#include "analysis/collisional_stress.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

namespace granule {

namespace {

// The per-cell sums with their checkpoint names, in one list.
template <typename Sums>
auto sum_arrays(Sums& s) {
  return std::array{std::pair{"sum_xx", &s.xx},         std::pair{"sum_xy", &s.xy},
                    std::pair{"sum_yy", &s.yy},         std::pair{"sum_energy_x", &s.energy_x},
                    std::pair{"sum_energy_y", &s.energy_y}, std::pair{"count", &s.collisions}};
}

}  // namespace

Vec2 pair_velocity_at_contact(const CollisionRecord<2>& r, double diameter, double length_y) {
  // Before mapping into the box the contact point lies σ/2 from disk 1 along k̂; the recorded
  // one is a box height away from there when it was mapped to disk 2's side.
  const double unmapped_y = r.first_position.y + 0.5 * diameter * r.contact_normal.y;
  const bool on_second_side = std::abs(unmapped_y - r.contact_point.y) > 0.5 * length_y;
  const Vec2 half_relative = 0.5 * r.relative_velocity;  // v₂₁/2 = (v₁ − v₂)/2
  return on_second_side ? r.second_velocity_before + half_relative : r.first_velocity_before - half_relative;
}

CollisionalStressField::CollisionalStressField(const FieldGrid& grid, double diameter) : grid_(grid), diameter_(diameter) {
  for (const auto& [name, values] : sum_arrays(sums_)) values->assign(grid.cells(), 0.0);
}

void CollisionalStressField::on_collision(const CollisionRecord<2>& r) {
  const std::size_t c = grid_.index(r.contact_point.x, r.contact_point.y);
  const double j = r.impulse;
  const Vec2 k = r.contact_normal;
  const Vec2 s = pair_velocity_at_contact(r, diameter_, grid_.length_y);
  const double carried = j * (k.x * s.x + k.y * s.y);  // J k̂·s
  sums_.xx[c] += j * k.x * k.x;
  sums_.xy[c] += j * k.x * k.y;
  sums_.yy[c] += j * k.y * k.y;
  sums_.energy_x[c] += carried * k.x;
  sums_.energy_y[c] += carried * k.y;
  sums_.collisions[c] += 1.0;
}

void CollisionalStressField::restart(double t) {
  start_ = t;
  for (const auto& [name, values] : sum_arrays(sums_)) std::fill(values->begin(), values->end(), 0.0);
}

CollisionalStress CollisionalStressField::stress(double t) const {
  CollisionalStress out = sums_;
  out.interval = t - start_;
  const double scale = out.interval > 0.0 ? diameter_ / (grid_.cell_area() * out.interval) : 0.0;
  for (auto* v : {&out.xx, &out.xy, &out.yy, &out.energy_x, &out.energy_y}) {
    for (double& x : *v) x *= scale;
  }
  return out;
}

void CollisionalStressField::save(StateArchive& archive, const std::string& prefix) const {
  archive.put_scalar(prefix + "start", start_);
  for (const auto& [name, values] : sum_arrays(sums_)) archive.put(prefix + name, *values);
}

void CollisionalStressField::restore(const StateArchive& archive, const std::string& prefix) {
  start_ = archive.scalar(prefix + "start");
  for (const auto& [name, values] : sum_arrays(sums_)) *values = archive.get_sized<double>(prefix + name, grid_.cells());
}

HeatFlux collisional_heat_flux(const CollisionalStress& s, const std::vector<double>& reference_x,
                               const std::vector<double>& reference_y) {
  HeatFlux q{s.energy_x, s.energy_y};
  for (std::size_t c = 0; c < q.x.size(); ++c) {
    // σ/(V t) Σ J k̂ k̂·(s − V) = σ/(V t) E − τ^(c)·V.
    q.x[c] -= s.xx[c] * reference_x[c] + s.xy[c] * reference_y[c];
    q.y[c] -= s.xy[c] * reference_x[c] + s.yy[c] * reference_y[c];
  }
  return q;
}

HeatFlux collisional_heat_flux(const CollisionalStress& stress, const CellFields& average, const ShearFrame& frame,
                               bool shear_profile_subtracted) {
  const FieldGrid& g = average.grid;
  std::vector<double> reference_x = average.velocity_x;
  if (shear_profile_subtracted) {
    for (std::size_t c = 0; c < g.cells(); ++c) {
      reference_x[c] += frame.mean_flow(g.center_y(static_cast<int>(c / static_cast<std::size_t>(g.nx))));
    }
  }
  return collisional_heat_flux(stress, reference_x, average.velocity_y);
}

}  // namespace granule
