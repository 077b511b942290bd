#include "observers/obstacle_forces.hpp"

namespace granule {

template <int D>
void ObstacleForces<D>::add(const SurfaceHitRecord<D>& r) {
  if (r.surface.obstacle() < 0) return;
  ObstacleForce& sums = sums_[static_cast<std::size_t>(r.surface.obstacle())];
  sums.drag += r.impulse_on_surface[0];
  sums.lift += r.impulse_on_surface[1];
  if constexpr (D == 3) sums.force_z += r.impulse_on_surface[2];
  sums.collisions += 1.0;
}

template <int D>
ObstacleForcesSample ObstacleForces<D>::sample(double dt) const {
  ObstacleForcesSample out{D == 3, {}, {}};
  const double per_time = dt > 0.0 ? 1.0 / dt : 0.0;
  for (const ObstacleForce& s : sums_) {
    out.each.push_back({s.drag * per_time, s.lift * per_time, s.force_z * per_time, s.collisions});
    out.total.drag += s.drag * per_time;
    out.total.lift += s.lift * per_time;
    out.total.force_z += s.force_z * per_time;
    out.total.collisions += s.collisions;
  }
  return out;
}

template <int D>
void ObstacleForces<D>::clear() {
  for (ObstacleForce& s : sums_) s = {};
}

template <int D>
void ObstacleForces<D>::save(StateArchive& archive, const std::string& prefix) const {
  std::vector<double> flat;
  for (const ObstacleForce& s : sums_) flat.insert(flat.end(), {s.drag, s.lift, s.force_z, s.collisions});
  archive.put(prefix + "obstacle_sums", std::move(flat));
}

template <int D>
void ObstacleForces<D>::restore(const StateArchive& archive, const std::string& prefix) {
  const std::vector<double>& flat = archive.get_sized<double>(prefix + "obstacle_sums", 4 * sums_.size());
  for (std::size_t k = 0; k < sums_.size(); ++k) sums_[k] = {flat[4 * k], flat[4 * k + 1], flat[4 * k + 2], flat[4 * k + 3]};
}

template class ObstacleForces<2>;
template class ObstacleForces<3>;

}  // namespace granule
