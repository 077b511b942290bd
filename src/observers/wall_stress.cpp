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
    }
  }
}

template <int D>
void WallStress<D>::add(const SurfaceHitRecord<D>& r) {
  if (!r.surface.wall()) return;
  FaceSums& sums = sums_[static_cast<std::size_t>(r.surface.face())];
  // The outward normal of face (axis, side) is −ê_axis at 0 and +ê_axis at L.
  const int axis = r.surface.axis();
  sums.normal += r.surface.side() == 0 ? -r.impulse_on_surface[axis] : r.impulse_on_surface[axis];
  sums.tangential += r.impulse_on_surface[wall_shear_axis(axis)];
  sums.energy += r.energy_change;
  sums.collisions += 1.0;
}

template <int D>
std::array<std::optional<WallFaceSample>, 6> WallStress<D>::sample(double dt) const {
  std::array<std::optional<WallFaceSample>, 6> out;
  for (std::size_t face = 0; face < 6; ++face) {
    if (!present_[face]) continue;
    const FaceSums& s = sums_[face];
    const double per_area_time = dt > 0.0 ? 1.0 / (area_[face] * dt) : 0.0;
    out[face] = WallFaceSample{s.normal * per_area_time, s.tangential * per_area_time, s.energy * per_area_time, s.collisions};
  }
  return out;
}

template <int D>
void WallStress<D>::save(StateArchive& archive, const std::string& prefix) const {
  std::vector<double> flat;
  for (const FaceSums& s : sums_) flat.insert(flat.end(), {s.normal, s.tangential, s.energy, s.collisions});
  archive.put(prefix + "wall_sums", std::move(flat));
}

template <int D>
void WallStress<D>::restore(const StateArchive& archive, const std::string& prefix) {
  const std::vector<double>& flat = archive.get_sized<double>(prefix + "wall_sums", 4 * sums_.size());
  for (std::size_t face = 0; face < sums_.size(); ++face) {
    sums_[face] = {flat[4 * face], flat[4 * face + 1], flat[4 * face + 2], flat[4 * face + 3]};
  }
}

template class WallStress<2>;
template class WallStress<3>;

}  // namespace granule
