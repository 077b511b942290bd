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

// The lab velocities of disks i and j after they collide `delay` after t, from the thesis's rule
// (1.2) applied directly: both disks streamed to contact, j's nearest image (at x + i_y U t,
// moving at v_x + i_y U), v₁' = v₁ − (1 + ẽ)/2 ((v₁ − v₂)·k̂) k̂ and the opposite for v₂.
struct PairVelocities {
  double v1x, v1y, v2x, v2y;
};
inline PairVelocities brute_force_collide(const SystemParams& p, const ParticleState& s, double t, int i, int j,
                                          double delay, double restitution) {
  const double lx = p.length_x, ly = p.length_y, u = p.shear_velocity;
  const double offset = std::fmod(u * (t + delay), lx);
  // A disk that left through the top by the time of contact came in at the bottom, shifted by
  // −Δ with v_x − U (and the reverse): its lab velocity is the one inside the box.
  struct Disk {
    double x, y, vx, vy;
  };
  const auto at_contact = [&](int k) {
    Disk d{s.x[k] + s.vx[k] * delay, s.y[k] + s.vy[k] * delay, s.vx[k], s.vy[k]};
    const int out = d.y >= ly ? 1 : (d.y < 0.0 ? -1 : 0);
    d.y -= out * ly;
    d.x -= out * offset;
    d.vx -= out * u;
    return d;
  };
  const Disk d1 = at_contact(i), d2 = at_contact(j);
  const double x1 = d1.x, y1 = d1.y, x2 = d2.x, y2 = d2.y;
  double best = std::numeric_limits<double>::infinity(), rx = 0.0, ry = 0.0;
  int image_y = 0;
  for (int iy = -1; iy <= 1; ++iy) {
    double dx = x2 + iy * offset - x1;
    dx -= lx * std::round(dx / lx);
    const double dy = y2 + iy * ly - y1;
    if (const double d = std::sqrt(dx * dx + dy * dy); d < best) {
      best = d;
      rx = dx;
      ry = dy;
      image_y = iy;
    }
  }
  const double kx = rx / best, ky = ry / best;
  const double v2x_image = d2.vx + image_y * u;
  const double vn = (d1.vx - v2x_image) * kx + (d1.vy - d2.vy) * ky;
  const double change = 0.5 * (1.0 + restitution) * vn;
  return {d1.vx - change * kx, d1.vy - change * ky, v2x_image + change * kx - image_y * u, d2.vy + change * ky};
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
