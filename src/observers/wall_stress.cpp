#include "observers/wall_stress.hpp"

#include <vector>

namespace granule {

template <int D>
WallStress<D>::WallStress(const SystemParams& params) {
  const std::array<double, 3> length{params.length_x, params.length_y, params.length_z};
  for (int axis = 0; axis < D; ++axis) {
    double area = 1.0;
    for (int other = 0; other < D; ++other) {
      if (other != axis) area *= length[static_cast<std::size_t>(other)];
    }
    for (int side = 0; side < 2; ++side) {
      const auto face = static_cast<std::size_t>(2 * axis + side);
      present_[face] = params.walls[static_cast<std::size_t>(axis)];
      area_[face] = area;
      const double outward_gravity = (side == 0 ? -1.0 : 1.0) * params.gravity[static_cast<std::size_t>(axis)];
      if (params.rest.on() && present_[face] && outward_gravity > floor_gravity_) {
        floor_ = 2 * axis + side;
        floor_gravity_ = outward_gravity;
      }
    }
  }
}

template <int D>
void WallStress<D>::add(const SurfaceHitRecord<D>& r) {
  const bool on_bed = r.surface.resting_grain() >= 0 && floor_ >= 0;
  if (!r.surface.wall() && !on_bed) return;
  const int face = on_bed ? floor_ : r.surface.face();
  FaceSums& sums = sums_[static_cast<std::size_t>(face)];
  // The outward normal of face (axis, side) is −ê_axis at 0 and +ê_axis at L.
  const int axis = face / 2;
  sums.normal += face % 2 == 0 ? -r.impulse_on_surface[axis] : r.impulse_on_surface[axis];
  sums.tangential += r.impulse_on_surface[wall_shear_axis(axis)];
  if (on_bed) return;  // the energy a bed takes is dissipated in it, not given by the wall
  sums.energy += r.energy_change;
  sums.collisions += 1.0;
}

template <int D>
void WallStress<D>::add(const RestRecord<D>& r) {
  weight_impulse_ += resting_mass_ * floor_gravity_ * (r.time - weight_since_);
  weight_since_ = r.time;
  resting_mass_ += r.at_rest ? r.mass : -r.mass;
}

template <int D>
std::array<std::optional<WallFaceSample>, 6> WallStress<D>::sample(double t, double dt) const {
  std::array<std::optional<WallFaceSample>, 6> out;
  for (std::size_t face = 0; face < 6; ++face) {
    if (!present_[face]) continue;
    const FaceSums& s = sums_[face];
    double normal = s.normal;
    if (static_cast<int>(face) == floor_) normal += weight_impulse_ + resting_mass_ * floor_gravity_ * (t - weight_since_);
    const double per_area_time = dt > 0.0 ? 1.0 / (area_[face] * dt) : 0.0;
    out[face] = WallFaceSample{normal * per_area_time, s.tangential * per_area_time, s.energy * per_area_time, s.collisions};
  }
  return out;
}

template <int D>
void WallStress<D>::save(StateArchive& archive, const std::string& prefix) const {
  std::vector<double> flat;
  for (const FaceSums& s : sums_) flat.insert(flat.end(), {s.normal, s.tangential, s.energy, s.collisions});
  archive.put(prefix + "wall_sums", std::move(flat));
  if (floor_ >= 0) archive.put(prefix + "wall_rest", std::vector<double>{resting_mass_, weight_impulse_, weight_since_});
}

template <int D>
void WallStress<D>::restore(const StateArchive& archive, const std::string& prefix) {
  const std::vector<double>& flat = archive.get_sized<double>(prefix + "wall_sums", 4 * sums_.size());
  for (std::size_t face = 0; face < sums_.size(); ++face) {
    sums_[face] = {flat[4 * face], flat[4 * face + 1], flat[4 * face + 2], flat[4 * face + 3]};
  }
  if (floor_ >= 0) {
    const std::vector<double>& rest = archive.get_sized<double>(prefix + "wall_rest", 3);
    resting_mass_ = rest[0];
    weight_impulse_ = rest[1];
    weight_since_ = rest[2];
  }
}

template class WallStress<2>;
template class WallStress<3>;

}  // namespace granule
