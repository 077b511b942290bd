// The force on each fixed obstacle of a run over a sampling interval, from the obstacle collision
// records: the momentum the grains gave it per unit time, its drag along x (the flow direction of
// a flow past it, or of a shear), its lift along y (against gravity in a bed) and, for spheres,
// its force along z; with the hits counted.  In 2D a force is per unit length of the cylinder.
// The columns of the time series: obstacles_drag, obstacles_lift (, obstacles_force_z),
// obstacles_collisions for all of them together, then obstacle<k>_drag, … for each, k from 0 in
// the order of the configuration.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "archive/state_archive.hpp"
#include "engine/observer.hpp"
#include "engine/system_params.hpp"

namespace granule {

struct ObstacleForce {
  double drag = 0.0;
  double lift = 0.0;
  double force_z = 0.0;  // 3D only
  double collisions = 0.0;
};

struct ObstacleForcesSample {
  bool spheres = false;  // force_z is a column
  ObstacleForce total;
  std::vector<ObstacleForce> each;
};

template <typename Sample, typename Visit>
void for_each_obstacle_column(Sample& s, Visit&& visit) {
  const auto columns = [&](const std::string& prefix, auto& f) {
    visit((prefix + "_drag").c_str(), f.drag);
    visit((prefix + "_lift").c_str(), f.lift);
    if (s.spheres) visit((prefix + "_force_z").c_str(), f.force_z);
    visit((prefix + "_collisions").c_str(), f.collisions);
  };
  columns("obstacles", s.total);
  for (std::size_t k = 0; k < s.each.size(); ++k) columns("obstacle" + std::to_string(k), s.each[k]);
}

template <int D>
class ObstacleForces {
 public:
  explicit ObstacleForces(const SystemParams& params) : sums_(params.obstacles.size()) {}
  // A hit of an obstacle (other surfaces' hits are not its business).
  void add(const SurfaceHitRecord<D>& record);
  // Over an interval of length dt > 0.
  ObstacleForcesSample sample(double dt) const;
  void clear();
  void save(StateArchive& archive, const std::string& prefix) const;
  void restore(const StateArchive& archive, const std::string& prefix);

 private:
  std::vector<ObstacleForce> sums_;  // momenta and hits over the open interval
};

}  // namespace granule
