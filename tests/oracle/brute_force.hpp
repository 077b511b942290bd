// Slow reference for the engine: the next collision of a configuration found by testing every
// pair against every nearby periodic image, O(N²), written directly from the thesis's
// Lees–Edwards rule (§1.4.2: the image above sits at x + U t mod L_x and moves at v_x + U)
// without the engine's cells, sheared frame or queue.  Disks or spheres (the dimension of the
// state), equal or per-particle diameters and masses.
#pragma once

#include <array>
#include <cmath>
#include <limits>
#include <utility>

#include "engine/system_params.hpp"

namespace granule::oracle {

using Point = std::array<double, 3>;  // z = 0 in 2D

inline Point position(const ParticleState& s, int k) {
  return {s.x[k], s.y[k], s.dimension == 3 ? s.z[k] : 0.0};
}
inline Point velocity(const ParticleState& s, int k) {
  return {s.vx[k], s.vy[k], s.dimension == 3 ? s.vz[k] : 0.0};
}
inline double dot(const Point& a, const Point& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline double contact(const SystemParams& p, const ParticleState& s, int i, int j) {
  return s.polydisperse() ? 0.5 * (s.diameter[i] + s.diameter[j]) : p.diameter;
}

// The smaller root of |r + v τ| = σ on approach, from the textbook quadratic (no cancellation
// guard: the reference must not share the engine's numerics).
inline double contact_time(const Point& r, const Point& v, double sigma) {
  const double b = dot(r, v);
  if (b >= 0.0) return std::numeric_limits<double>::infinity();
  const double a = dot(v, v), c = dot(r, r) - sigma * sigma;
  const double disc = b * b - a * c;
  if (disc < 0.0) return std::numeric_limits<double>::infinity();
  return std::max(0.0, (-b - std::sqrt(disc)) / a);
}

// Calls visit(r, v_rel, image_y) for the relevant images of j seen from i at time t: the three
// vertical images (Lees–Edwards offset i_y U t), and for each the nearest x image and its two
// neighbours, and in 3D the same in z.
template <typename Visit>
void for_each_image(const SystemParams& p, const ParticleState& s, double t, int i, int j, Visit&& visit) {
  const double lx = p.length_x, ly = p.length_y, lz = p.length_z, u = p.shear_velocity;
  const double offset = std::fmod(u * t, lx);
  const Point ri = position(s, i), rj = position(s, j), vi = velocity(s, i), vj = velocity(s, j);
  const int z_images = s.dimension == 3 ? 1 : 0;
  for (int iy = -1; iy <= 1; ++iy) {
    const double x_image = rj[0] + iy * offset;
    const double nearest_x = std::round((x_image - ri[0]) / lx);
    const double nearest_z = s.dimension == 3 ? std::round((rj[2] - ri[2]) / lz) : 0.0;
    for (int ix = -1; ix <= 1; ++ix) {
      for (int iz = -z_images; iz <= z_images; ++iz) {
        const Point r{x_image - (nearest_x + ix) * lx - ri[0], rj[1] + iy * ly - ri[1], rj[2] - (nearest_z + iz) * lz - ri[2]};
        const Point v{vj[0] + iy * u - vi[0], vj[1] - vi[1], vj[2] - vi[2]};
        visit(r, v, iy);
      }
    }
  }
}

struct NextCollision {
  double delay = std::numeric_limits<double>::infinity();
  int first = -1;
  int second = -1;
  double runner_up_delay = std::numeric_limits<double>::infinity();  // second-earliest pair
};

// `state` holds positions inside the box at absolute time t (image offset U t mod L_x).
inline NextCollision brute_force_next_collision(const SystemParams& p, const ParticleState& state, double t) {
  NextCollision best;
  const int n = static_cast<int>(state.size());
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) {
      double pair_best = std::numeric_limits<double>::infinity();
      const double sigma = contact(p, state, i, j);
      for_each_image(p, state, t, i, j, [&](const Point& r, const Point& v, int) {
        pair_best = std::min(pair_best, contact_time(r, v, sigma));
      });
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

// The lab velocities of particles i and j after they collide `delay` after t, from the thesis's
// rule (1.2) for masses m1, m2 applied directly: both streamed to contact, j's nearest image (at
// x + i_y U t, moving at v_x + i_y U), J = (1 + ẽ) m1 m2/(m1 + m2) ((v₁ − v₂)·k̂),
// v₁' = v₁ − J/m1 k̂, v₂' = v₂ + J/m2 k̂.
struct PairVelocities {
  Point v1, v2;
};
inline PairVelocities brute_force_collide(const SystemParams& p, const ParticleState& s, double t, int i, int j,
                                          double delay, double restitution) {
  // A particle that left through the top by the time of contact came in at the bottom, shifted by
  // −Δ with v_x − U (and the reverse): its lab velocity is the one inside the box.
  const double offset = std::fmod(p.shear_velocity * (t + delay), p.length_x);
  ParticleState streamed = s;
  for (int k : {i, j}) {
    streamed.x[k] += s.vx[k] * delay;
    streamed.y[k] += s.vy[k] * delay;
    if (s.dimension == 3) streamed.z[k] += s.vz[k] * delay;
    const int out = streamed.y[k] >= p.length_y ? 1 : (streamed.y[k] < 0.0 ? -1 : 0);
    streamed.y[k] -= out * p.length_y;
    streamed.x[k] -= out * offset;
    streamed.vx[k] -= out * p.shear_velocity;
  }
  // The nearest image at contact (positions a hair outside the box are fine: images cover them).
  double best = std::numeric_limits<double>::infinity();
  Point k_hat{}, v_rel{};
  for_each_image(p, streamed, t + delay, i, j, [&](const Point& r, const Point& v, int) {
    if (const double d = std::sqrt(dot(r, r)); d < best) {
      best = d;
      k_hat = {r[0] / d, r[1] / d, r[2] / d};
      v_rel = v;
    }
  });
  const double m1 = s.mass_of(static_cast<std::size_t>(i)), m2 = s.mass_of(static_cast<std::size_t>(j));
  const double impulse = (1.0 + restitution) * m1 * m2 / (m1 + m2) * -dot(v_rel, k_hat);
  // j's image moves at v_x + i_y U, but its own velocity changes by the same impulse.
  Point v1 = velocity(streamed, i), v2 = velocity(streamed, j);
  for (int a = 0; a < 3; ++a) {
    v1[a] -= impulse / m1 * k_hat[a];
    v2[a] += impulse / m2 * k_hat[a];
  }
  return {v1, v2};
}

// Smallest centre distance over all pairs and images, divided by σ_ij (≥ 1 without overlaps).
inline double min_distance_ratio(const SystemParams& p, const ParticleState& state, double t) {
  double best = std::numeric_limits<double>::infinity();
  const int n = static_cast<int>(state.size());
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) {
      const double sigma = contact(p, state, i, j);
      for_each_image(p, state, t, i, j, [&](const Point& r, const Point&, int) { best = std::min(best, std::sqrt(dot(r, r)) / sigma); });
    }
  }
  return best;
}

}  // namespace granule::oracle
