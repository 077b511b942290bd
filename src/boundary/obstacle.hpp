// A fixed obstacle (thesis Appendix A.1, "obstacles"): an immobile disk (2D) or sphere (3D) of
// infinite mass, which a grain touches when their centres are (D + σ)/2 apart.  It reflects the
// grain's velocity at the contact point as a wall does (physics/collision_law.hpp): normal part ×
// −restitution, tangential part × −tangential_restitution.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

namespace granule {

struct Obstacle {
  std::array<double, 3> centre{};        // x, y (, z): inside the box
  double diameter = 0.0;                 // D > 0
  double restitution = 1.0;              // e_o ∈ (0, 1]
  double tangential_restitution = -1.0;  // β_o ∈ [−1, 1]: −1 smooth, +1 perfectly rough
};

// The square of the distance between a point and an obstacle's centre, through the nearest
// periodic image along the axes with images (`lengths` of the box; walled axes have none).
inline double distance_squared_to(const Obstacle& obstacle, const std::array<double, 3>& point, int dimension,
                                  const std::array<bool, 3>& images, const std::array<double, 3>& lengths) {
  double sum = 0.0;
  for (std::size_t a = 0; a < static_cast<std::size_t>(dimension); ++a) {
    double delta = point[a] - obstacle.centre[a];
    if (images[a]) {
      if (delta > 0.5 * lengths[a]) delta -= lengths[a];
      if (delta < -0.5 * lengths[a]) delta += lengths[a];
    }
    sum += delta * delta;
  }
  return sum;
}

// Whether a grain of diameter `sigma` at `point` would overlap any of the obstacles.
inline bool overlaps_obstacle(const std::vector<Obstacle>& obstacles, const std::array<double, 3>& point, double sigma,
                              int dimension, const std::array<bool, 3>& images, const std::array<double, 3>& lengths) {
  for (const Obstacle& obstacle : obstacles) {
    const double contact = 0.5 * (obstacle.diameter + sigma);
    if (distance_squared_to(obstacle, point, dimension, images, lengths) < contact * contact * (1.0 + 1e-9)) return true;
  }
  return false;
}

}  // namespace granule
