// Collisions of rough (spinning) inelastic disks and spheres — with each other and with flat walls
// — in the constant-restitution model with Coulomb friction (Walton 1993; Lun 1991, the model of
// thesis Fig C.4; Luding et al., PRE 58, 3416 (1998)).
//
// The contact points of bodies 1 and 2 (k̂ the unit vector from 1 to 2, radii a1, a2) move
// relative to each other at g = v1 − v2 + (a1 ω1 + a2 ω2) × k̂.  The collision reverses and scales
// its normal part, g_n' = −e g_n, and its tangential part, g_t' = −β g_t (β = −1: smooth, no
// tangential impulse; β = +1: perfectly rough, elastic in the tangential direction), unless that
// needs a tangential impulse above μ times the normal one: then the contact slides and the
// tangential impulse is μ|P_n| along g_t (Walton's sliding branch).  The impulse P acts on 2,
// −P on 1; spins change by −a (k̂ × P)/I for both bodies.  Momentum and the angular momentum about
// the contact point are conserved exactly in exact arithmetic.
#pragma once

#include <cmath>
#include <type_traits>

#include "geometry/vec.hpp"

namespace granule {

// The angular velocity: ω_z for disks, a vector for spheres.
template <int D>
using Spin = std::conditional_t<D == 2, double, Vec3>;

// ω × r (for disks ω ẑ × r, in the plane).
inline Vec2 spin_cross(double w, Vec2 r) { return {-w * r.y, w * r.x}; }
inline Vec3 spin_cross(Vec3 w, Vec3 r) {
  return {w.y * r.z - w.z * r.y, w.z * r.x - w.x * r.z, w.x * r.y - w.y * r.x};
}
// r × p as an angular quantity (its z component for disks).
inline double torque(Vec2 r, Vec2 p) { return cross(r, p); }
inline Vec3 torque(Vec3 r, Vec3 p) { return spin_cross(r, p); }

inline double spin_norm2(double w) { return w * w; }
inline double spin_norm2(Vec3 w) { return norm2(w); }

// One side of a contact: its velocity and spin, its inverse mass, and a²/I = 1/(q m) (0 for a
// body that cannot spin or a wall: infinite moment of inertia).
template <int D>
struct RoughBody {
  Vec<D> velocity;
  Spin<D> spin{};
  double radius = 0.0;
  double inverse_mass = 1.0;
  double radius2_over_inertia = 0.0;
};

struct TangentialLaw {
  double restitution = -1.0;  // β ∈ [−1, 1]
  double friction = INFINITY;  // μ ≥ 0
};

template <int D>
struct RoughImpulse {
  Vec<D> normal;      // P_n, along k̂
  Vec<D> tangential;  // P_t, perpendicular to k̂
  Vec<D> total() const { return normal + tangential; }
};

// The velocity of 1's contact point relative to 2's (k̂ from 1 to 2).
template <int D>
Vec<D> contact_velocity(const RoughBody<D>& first, const RoughBody<D>& second, Vec<D> k_hat) {
  return first.velocity - second.velocity + spin_cross(first.radius * first.spin + second.radius * second.spin, k_hat);
}

// The impulse on body 2 for normal restitution e and the tangential law.
template <int D>
RoughImpulse<D> rough_impulse(const RoughBody<D>& first, const RoughBody<D>& second, Vec<D> k_hat, double restitution,
                              const TangentialLaw& law) {
  const Vec<D> g = contact_velocity(first, second, k_hat);
  const double g_n = dot(g, k_hat);
  const Vec<D> g_t = g - g_n * k_hat;
  const double normal_inverse_mass = first.inverse_mass + second.inverse_mass;
  // The contact points' tangential response to an impulse: 1/m1 + 1/m2 + a1²/I1 + a2²/I2.
  const double tangential_inverse_mass =
      normal_inverse_mass + first.radius2_over_inertia + second.radius2_over_inertia;
  RoughImpulse<D> p;
  const double p_n = (1.0 + restitution) * g_n / normal_inverse_mass;
  p.normal = p_n * k_hat;
  p.tangential = ((1.0 + law.restitution) / tangential_inverse_mass) * g_t;
  const double cap = law.friction * std::abs(p_n);
  if (const double p_t = norm(p.tangential); p_t > cap) p.tangential = (cap / p_t) * p.tangential;
  return p;
}

// Applies impulse P (on body 2, −P on body 1) to velocities and spins.
template <int D>
void apply_rough_impulse(RoughBody<D>& first, RoughBody<D>& second, Vec<D> k_hat, const RoughImpulse<D>& impulse) {
  const Vec<D> p = impulse.total();
  first.velocity = first.velocity - first.inverse_mass * p;
  second.velocity = second.velocity + second.inverse_mass * p;
  // Δω = (±a k̂) × (∓P)/I for both: −a (k̂ × P)/I, with a/I = (a²/I)/a.
  const Spin<D> turn = torque(k_hat, impulse.tangential);
  if (first.radius > 0.0) first.spin = first.spin - (first.radius2_over_inertia / first.radius) * turn;
  if (second.radius > 0.0) second.spin = second.spin - (second.radius2_over_inertia / second.radius) * turn;
}

}  // namespace granule
