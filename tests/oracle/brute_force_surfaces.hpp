// Slow reference for walls, gravity and spin: the next event of a configuration — a pair
// collision (every pair, every image along the periodic axes) or a wall hit (every grain, every
// wall) — found by solving the textbook quadratics on parabolic flights, and the velocities and
// spins after it from the rough-grain rule written out in 3-vectors (no cells, no queue, none of
// the engine's numerics).  Lees–Edwards shear is left to brute_force.hpp; here the periodic axes
// are plain.
#pragma once

#include <array>
#include <cmath>
#include <limits>

#include "engine/system_params.hpp"
#include "oracle/brute_force.hpp"

namespace granule::oracle {

inline constexpr double kNoEvent = std::numeric_limits<double>::infinity();

inline Point cross3(const Point& a, const Point& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline Point spin_of(const ParticleState& s, int k) {
  if (!s.rough()) return {0.0, 0.0, 0.0};
  if (s.dimension == 2) return {0.0, 0.0, s.wz[k]};
  return {s.wx[k], s.wy[k], s.wz[k]};
}
inline double box_length(const SystemParams& p, int axis) {
  return axis == 0 ? p.length_x : (axis == 1 ? p.length_y : p.length_z);
}

// The earliest τ ≥ 0 at which a τ² + b τ + c (a distance, c ≥ 0) falls through zero: the textbook
// roots, the smallest non-negative one where the function decreases.
inline double first_root_approaching(double a, double b, double c) {
  if (a == 0.0) {
    if (b >= 0.0) return kNoEvent;
    return std::max(0.0, -c / b);
  }
  const double disc = b * b - 4.0 * a * c;
  if (disc < 0.0) return kNoEvent;
  const double s = std::sqrt(disc);
  double r1 = (-b - s) / (2.0 * a), r2 = (-b + s) / (2.0 * a);
  if (r1 > r2) std::swap(r1, r2);
  for (double r : {r1, r2}) {
    if (r >= -1e-13 && 2.0 * a * r + b < 0.0) return std::max(0.0, r);
  }
  return kNoEvent;
}

struct SurfaceEvent {
  double delay = kNoEvent;
  int first = -1;
  int second = -1;   // −1: a wall hit
  int face = -1;     // the wall's face for a wall hit
  double runner_up_delay = kNoEvent;
  void offer(double d, int i, int j, int f) {
    if (d < delay) {
      runner_up_delay = delay;
      delay = d;
      first = i;
      second = j;
      face = f;
    } else if (d < runner_up_delay) {
      runner_up_delay = d;
    }
  }
};

// Images of j seen from i along the periodic axes (no images across wall axes).
template <typename Visit>
void for_each_plain_image(const SystemParams& p, int dimension, Visit&& visit) {
  const int reach[3] = {p.walls[0] ? 0 : 1, p.walls[1] ? 0 : 1, dimension == 3 && !p.walls[2] ? 1 : 0};
  for (int ix = -reach[0]; ix <= reach[0]; ++ix) {
    for (int iy = -reach[1]; iy <= reach[1]; ++iy) {
      for (int iz = -reach[2]; iz <= reach[2]; ++iz) visit(Point{ix * p.length_x, iy * p.length_y, iz * p.length_z});
    }
  }
}

inline SurfaceEvent brute_force_next_surface_event(const SystemParams& p, const ParticleState& s) {
  SurfaceEvent best;
  const int n = static_cast<int>(s.size());
  const int d = s.dimension;
  for (int i = 0; i < n; ++i) {
    const double radius = 0.5 * s.diameter_of(static_cast<std::size_t>(i), p.diameter);
    const Point r = position(s, i), v = velocity(s, i);
    for (int axis = 0; axis < d; ++axis) {
      if (!p.walls[static_cast<std::size_t>(axis)]) continue;
      const double g = p.gravity[static_cast<std::size_t>(axis)];
      // Lower wall: distance r − ρ falls to 0; upper: (L − ρ) − r falls to 0.
      best.offer(first_root_approaching(0.5 * g, v[axis], r[axis] - radius), i, -1, 2 * axis);
      best.offer(first_root_approaching(-0.5 * g, -v[axis], box_length(p, axis) - radius - r[axis]), i, -1, 2 * axis + 1);
    }
    for (int j = i + 1; j < n; ++j) {
      const double sigma = contact(p, s, i, j);
      const Point rj = position(s, j), vj = velocity(s, j);
      for_each_plain_image(p, d, [&](const Point& shift) {
        Point dr{}, dv{};
        for (int a = 0; a < 3; ++a) {
          dr[a] = rj[a] + shift[a] - r[a];  // positions are in the box: ±1 period covers the nearest
          dv[a] = vj[a] - v[a];
        }
        best.offer(contact_time(dr, dv, sigma), i, j, -1);
      });
    }
  }
  return best;
}

// Streams grain k by τ on its parabola.
inline void stream(const SystemParams& p, ParticleState& s, int k, double tau) {
  for (int a = 0; a < s.dimension; ++a) {
    const double g = p.gravity[static_cast<std::size_t>(a)];
    s.position(a)[k] += s.velocity(a)[k] * tau + 0.5 * g * tau * tau;
    s.velocity(a)[k] += g * tau;
  }
}

struct Kinematics {
  Point v, w;
};

// One side of a contact for the rule below: velocity, spin, radius, mass and moment of inertia
// (infinite for a wall, and for a smooth grain's spin).
struct Side {
  Point v, w;
  double radius, mass, inertia;
};

// The rough rule: g = v1 − v2 + (a1 ω1 + a2 ω2) × k̂; P_n = (1 + e) g_n / (1/m1 + 1/m2),
// P_t = (1 + β) g_t / (1/m1 + 1/m2 + a1²/I1 + a2²/I2), capped at μ |P_n|; P acts on side 2.
inline std::array<Kinematics, 2> rough_rule(const Side& one, const Side& two, const Point& k, double e, double beta,
                                            double mu) {
  Point spin_sum{};
  for (int a = 0; a < 3; ++a) spin_sum[a] = one.radius * one.w[a] + two.radius * two.w[a];
  const Point turn = cross3(spin_sum, k);
  Point g{};
  for (int a = 0; a < 3; ++a) g[a] = one.v[a] - two.v[a] + turn[a];
  const double g_n = dot(g, k);
  Point g_t{};
  for (int a = 0; a < 3; ++a) g_t[a] = g[a] - g_n * k[a];
  const double inverse = 1.0 / one.mass + 1.0 / two.mass;
  const double tangential = inverse + one.radius * one.radius / one.inertia + two.radius * two.radius / two.inertia;
  const double p_n = (1.0 + e) * g_n / inverse;
  double scale = (1.0 + beta) / tangential;
  const double g_t_norm = std::sqrt(dot(g_t, g_t));
  if (scale * g_t_norm > mu * std::abs(p_n)) scale = mu * std::abs(p_n) / g_t_norm;
  Point impulse{}, p_t{};
  for (int a = 0; a < 3; ++a) {
    p_t[a] = scale * g_t[a];
    impulse[a] = p_n * k[a] + p_t[a];
  }
  const Point torque = cross3(k, p_t);
  std::array<Kinematics, 2> out;
  for (int a = 0; a < 3; ++a) {
    out[0].v[a] = one.v[a] - impulse[a] / one.mass;
    out[1].v[a] = two.v[a] + impulse[a] / two.mass;
    out[0].w[a] = one.w[a] - one.radius * torque[a] / one.inertia;
    out[1].w[a] = two.w[a] - two.radius * torque[a] / two.inertia;
  }
  return out;
}

inline Side side_of(const SystemParams& p, const ParticleState& s, int k) {
  const double radius = 0.5 * s.diameter_of(static_cast<std::size_t>(k), p.diameter);
  const double mass = s.mass_of(static_cast<std::size_t>(k));
  const double inertia = p.roughness.rough ? p.roughness.inertia_factor * mass * radius * radius : kNoEvent;
  return {velocity(s, k), spin_of(s, k), radius, mass, inertia};
}

// Velocities and spins of the grains of `event` just after it, `event.delay` after the state.
inline std::array<Kinematics, 2> brute_force_execute(const SystemParams& p, const ParticleState& state,
                                                     const SurfaceEvent& event, double restitution) {
  ParticleState s = state;
  stream(p, s, event.first, event.delay);
  if (event.second < 0) {
    const int axis = event.face / 2;
    Point k{};
    k[axis] = event.face % 2 == 0 ? -1.0 : 1.0;
    const WallParams& wall = p.wall[static_cast<std::size_t>(event.face)];
    const Side surface{{wall.velocity[0], wall.velocity[1], wall.velocity[2]}, {}, 0.0, kNoEvent, kNoEvent};
    return rough_rule(side_of(p, s, event.first), surface, k, restitution, wall.tangential_restitution, kNoEvent);
  }
  stream(p, s, event.second, event.delay);
  Point best_r{};
  double best = kNoEvent;
  const Point r1 = position(s, event.first), r2 = position(s, event.second);
  for_each_plain_image(p, s.dimension, [&](const Point& shift) {
    Point dr{};
    for (int a = 0; a < 3; ++a) dr[a] = r2[a] + shift[a] - r1[a];
    if (const double dist = std::sqrt(dot(dr, dr)); dist < best) {
      best = dist;
      best_r = dr;
    }
  });
  const Point k{best_r[0] / best, best_r[1] / best, best_r[2] / best};
  const double beta = p.roughness.rough ? p.roughness.tangential_restitution : -1.0;
  return rough_rule(side_of(p, s, event.first), side_of(p, s, event.second), k, restitution, beta, p.roughness.friction);
}

}  // namespace granule::oracle
