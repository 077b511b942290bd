// Slow reference for the engine: the next collision of a configuration found by testing every
// pair against every nearby periodic image, O(N²), written directly from the thesis's
// Lees–Edwards rule (§1.4.2: the image above sits at x + U t mod L_x and moves at v_x + U)
// without the engine's cells, sheared frame or queue.
#pragma once

#include <cmath>
#include <limits>
#include <utility>

#include "engine/system_params.hpp"
#include "physics/collision_time.hpp"

namespace granule::oracle {

struct NextCollision {
  double delay = std::numeric_limits<double>::infinity();
  int first = -1;
  int second = -1;
  double runner_up_delay = std::numeric_limits<double>::infinity();  // second-earliest pair
};

// `state` holds positions inside the box at absolute time t (image offset U t mod L_x).
inline NextCollision brute_force_next_collision(const SystemParams& p, const ParticleState& state, double t) {
  const double lx = p.length_x, ly = p.length_y, u = p.shear_velocity;
  const double offset = std::fmod(u * t, lx);
  NextCollision best;
  const int n = static_cast<int>(state.size());
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) {
      double pair_best = std::numeric_limits<double>::infinity();
      for (int iy = -1; iy <= 1; ++iy) {
        const double ry = state.y[j] + iy * ly - state.y[i];
        const double x_image = state.x[j] + iy * offset;
        const double vx_rel = state.vx[j] + iy * u - state.vx[i];
        const double nearest = std::round((x_image - state.x[i]) / lx);
        for (int ix = -1; ix <= 1; ++ix) {
          const double rx = x_image - (nearest + ix) * lx - state.x[i];
          pair_best = std::min(pair_best, collision_time({rx, ry}, {vx_rel, state.vy[j] - state.vy[i]}, p.diameter));
        }
      }
      if (pair_best < best.delay) {
        best.runner_up_delay = best.delay;
        best = {pair_best, i, j, best.runner_up_delay};
      } else if (pair_best < best.runner_up_delay) {
        best.runner_up_delay = pair_best;
      }
    }
  }
  return best;
}

// Smallest centre distance over all pairs and images, divided by σ (≥ 1 without overlaps).
inline double min_distance_ratio(const SystemParams& p, const ParticleState& state, double t) {
  const double lx = p.length_x, ly = p.length_y;
  const double offset = std::fmod(p.shear_velocity * t, lx);
  double best = std::numeric_limits<double>::infinity();
  const int n = static_cast<int>(state.size());
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) {
      for (int iy = -1; iy <= 1; ++iy) {
        const double ry = state.y[j] + iy * ly - state.y[i];
        double rx = state.x[j] + iy * offset - state.x[i];
        rx -= lx * std::round(rx / lx);
        best = std::min(best, std::sqrt(rx * rx + ry * ry));
      }
    }
  }
  return best / p.diameter;
}

}  // namespace granule::oracle
