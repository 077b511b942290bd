// The collision law: the one place where the outcome of a contact is decided, for two grains and
// for a grain and a wall alike.  A law is a normal restitution ẽ (thesis eq 1.2) and how it
// depends on the impact speed (physics/restitution_law.hpp), optionally the TC model against
// inelastic collapse (Luding & McNamara 1998), and a tangential law for rough grains and rough
// walls (β and Coulomb μ, physics/rough_collision_rule.hpp).  The arithmetic
// follows the sides: two smooth grains collide by thesis eq (1.2) (physics/collision_rule.hpp),
// anything that spins, and every wall, by Walton's rule, which reduces to it.
#pragma once

#include <cmath>
#include <limits>

#include "geometry/vec.hpp"
#include "physics/collision_rule.hpp"
#include "physics/restitution_law.hpp"
#include "physics/rough_collision_rule.hpp"

namespace granule {

// One side of a contact: a grain (mass m, radius a, spin ω when rough, moment of inertia
// I = q m a²) or a wall (infinite mass, no spin, moving at `velocity`).
template <int D>
struct ContactSide {
  Vec<D> velocity;
  Spin<D> spin{};
  double radius = 0.0;
  double mass = 1.0;            // +inf: a wall
  double inertia_factor = 0.0;  // q; 0: the side does not spin (a smooth grain or a wall)

  static ContactSide wall(const Vec<D>& velocity) {
    return {velocity, {}, 0.0, std::numeric_limits<double>::infinity(), 0.0};
  }
  bool spins() const { return inertia_factor > 0.0; }
  // ½ m v² + ½ I ω².
  double kinetic_energy() const {
    double energy = 0.5 * mass * norm2(velocity);
    if (spins()) energy += 0.5 * inertia_factor * mass * radius * radius * spin_norm2(spin);
    return energy;
  }
};

// What a contact exchanged: the impulse on the second side (−impulse on the first), its normal
// part J·k̂ as a number, and the restitution applied.
template <int D>
struct ContactOutcome {
  RoughImpulse<D> impulse;
  double normal_impulse = 0.0;
  double restitution = 1.0;
};

struct CollisionLaw {
  double restitution = 1.0;  // ẽ ∈ (0, 1]
  // TC model: a contact is elastic if either grain collided less than tc_duration ago; 0 switches
  // it off (and then no per-particle history is kept).
  double tc_duration = 0.0;
  TangentialLaw tangential;  // β = −1 (and no spin): smooth
  // Equal unit masses (a monodisperse system): thesis eq (1.2) in its own form, whose bits the
  // golden tier fixes; other masses by the reduced mass.
  bool unit_masses = true;
  RestitutionLaw speed_law;  // ẽ of the impact speed; constant (the thesis) by default

  bool keeps_history() const { return tc_duration > 0.0; }
  // Whether a contact at `now` between grains whose last contacts were at `last_first` and
  // `last_second` (a wall's: pass the grain's twice) falls within the TC model's duration.
  bool within_contact_duration(double now, double last_first, double last_second) const {
    return keeps_history() && (now - last_first < tc_duration || now - last_second < tc_duration);
  }
  // The restitution of the contact of `first` and `second` along k̂: 1 within the TC model's
  // duration (`recent`), else ẽ of the speed law at the normal impact speed (v₁ − v₂)·k̂.
  template <int D>
  double restitution_of(const ContactSide<D>& first, const ContactSide<D>& second, const Vec<D>& k_hat, bool recent) const {
    if (recent) return 1.0;
    if (speed_law.constant()) return restitution;
    return speed_law.at(restitution, dot(first.velocity - second.velocity, k_hat), first.radius, first.mass, second.radius,
                        second.mass);
  }

  // The contact of `first` and `second` (k̂ the unit vector from first to second, approaching),
  // with restitution e: both sides leave with their new velocities and spins.
  template <int D>
  ContactOutcome<D> collide(ContactSide<D>& first, ContactSide<D>& second, const Vec<D>& k_hat, double e) const {
    ContactOutcome<D> out;
    out.restitution = e;
    const bool grains = std::isfinite(first.mass) && std::isfinite(second.mass);
    if (grains && !first.spins() && !second.spins()) {
      // Thesis eq (1.2): v1' = v1 − (J/m1) k̂, v2' = v2 + (J/m2) k̂ (physics/collision_rule.hpp).
      const Vec<D> v21 = first.velocity - second.velocity;
      const double j = unit_masses ? normal_impulse(v21, k_hat, e) : normal_impulse(v21, k_hat, e, first.mass, second.mass);
      out.normal_impulse = j;
      out.impulse.normal = j * k_hat;
      if (unit_masses) {
        first.velocity = first.velocity - j * k_hat;
        second.velocity = second.velocity + j * k_hat;
      } else {
        first.velocity = first.velocity - (j / first.mass) * k_hat;
        second.velocity = second.velocity + (j / second.mass) * k_hat;
      }
      return out;
    }
    RoughBody<D> a = body(first);
    RoughBody<D> b = body(second);
    out.impulse = rough_impulse(a, b, k_hat, e, tangential);
    apply_rough_impulse(a, b, k_hat, out.impulse);
    out.normal_impulse = dot(out.impulse.normal, k_hat);
    first.velocity = a.velocity;
    second.velocity = b.velocity;
    if (first.spins()) first.spin = a.spin;
    if (second.spins()) second.spin = b.spin;
    return out;
  }

 private:
  template <int D>
  static RoughBody<D> body(const ContactSide<D>& side) {
    // a²/I = 1/(q m); 0 for a side that cannot spin (infinite moment of inertia).
    return {side.velocity, side.spin, side.radius, 1.0 / side.mass, side.spins() ? 1.0 / (side.inertia_factor * side.mass) : 0.0};
  }
};

}  // namespace granule
