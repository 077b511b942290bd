// The contacts that go beyond smooth spheres (ARCHITECTURE.md, "Spin, walls and gravity"): the
// spin of rough grains and their collisions (physics/rough_collision_rule.hpp), and grains hitting
// flat walls (thesis Appendix A.1: a reflection executed as a boundary event).
#include <limits>

#include "engine/simulation.hpp"

namespace granule {

namespace {
inline std::size_t at(std::int32_t i) { return static_cast<std::size_t>(i); }
}  // namespace

template <int D>
Spin<D> Simulation<D>::spin(std::int32_t i) const {
  if constexpr (D == 2) {
    return spin_[0][at(i)];
  } else {
    return {spin_[0][at(i)], spin_[1][at(i)], spin_[2][at(i)]};
  }
}

template <int D>
void Simulation<D>::set_spin(std::int32_t i, const Spin<D>& w) {
  if constexpr (D == 2) {
    spin_[0][at(i)] = w;
  } else {
    for (int k = 0; k < 3; ++k) spin_[static_cast<std::size_t>(k)][at(i)] = w[k];
  }
}

template <int D>
double Simulation<D>::kinetic_energy(std::int32_t i, const Vector& velocity) const {
  const double m = mass_of(i);
  double energy = 0.5 * m * norm2(velocity);
  if (params_.roughness.rough) {
    const double radius = radius_of(i);
    energy += 0.5 * params_.roughness.inertia_factor * m * radius * radius * spin_norm2(spin(i));
  }
  return energy;
}

template <int D>
RoughBody<D> Simulation<D>::rough_body(std::int32_t i, const Vector& velocity) const {
  const double m = mass_of(i);
  RoughBody<D> body{velocity, {}, radius_of(i), 1.0 / m, 0.0};
  if (params_.roughness.rough) {
    body.spin = spin(i);
    body.radius2_over_inertia = 1.0 / (params_.roughness.inertia_factor * m);  // a²/I with I = q m a²
  }
  return body;
}

template <int D>
RoughImpulse<D> Simulation<D>::collide_rough(std::int32_t i, std::int32_t j, Vector& v1, Vector& v2,
                                             const Vector& k_hat, double e) {
  RoughBody<D> first = rough_body(i, v1);
  RoughBody<D> second = rough_body(j, v2);
  const TangentialLaw law{params_.roughness.tangential_restitution, params_.roughness.friction};
  const RoughImpulse<D> impulse = rough_impulse(first, second, k_hat, e, law);
  apply_rough_impulse(first, second, k_hat, impulse);
  v1 = first.velocity;
  v2 = second.velocity;
  set_spin(i, first.spin);
  set_spin(j, second.spin);
  return impulse;
}

template <int D>
void Simulation<D>::execute_wall_hit(std::int32_t i, int face) {
  const int axis = face / 2;
  const WallParams& wall = params_.wall[static_cast<std::size_t>(face)];
  Vector k_hat;  // from the grain towards the wall
  k_hat[axis] = face % 2 == 0 ? -1.0 : 1.0;
  Vector wall_velocity;
  for (int a = 0; a < D; ++a) wall_velocity[a] = wall.velocity[static_cast<std::size_t>(a)];
  const Vector before = velocity_now(i);
  // Re-validate as for pairs: a grain no longer moving into the wall is left alone.
  if (dot(before, k_hat) <= 0.0) {
    predict(i);
    return;
  }
  double e = wall.restitution;
  if (params_.tc_duration > 0.0) {  // the TC model holds at walls too (ARCHITECTURE.md)
    e = CollisionLaw{e, params_.tc_duration}.restitution_at(t_now_, last_collision_[at(i)], last_collision_[at(i)]);
    last_collision_[at(i)] = t_now_;
  }
  // The wall is a body of infinite mass and moment of inertia moving at its own velocity; a smooth
  // grain behaves as one of infinite moment of inertia (rough_body).
  RoughBody<D> grain = rough_body(i, before);
  RoughBody<D> surface{wall_velocity, {}, 0.0, 0.0, 0.0};
  const double energy_before = kinetic_energy(i, before);
  const TangentialLaw law{wall.tangential_restitution, std::numeric_limits<double>::infinity()};
  const RoughImpulse<D> impulse = rough_impulse(grain, surface, k_hat, e, law);
  apply_rough_impulse(grain, surface, k_hat, impulse);
  set_velocity_now(i, grain.velocity);
  if (params_.roughness.rough) set_spin(i, grain.spin);
  ++particles_[at(i)].count;  // its pending partners' predictions are stale

  if (!observers_.empty()) {
    WallCollisionRecord<D> record;
    record.time = time();
    record.particle = user_id(i);
    record.axis = axis;
    record.side = face % 2;
    record.position = position_now(i);
    record.velocity_before = before;
    record.velocity_after = grain.velocity;
    record.impulse_on_wall = impulse.total();
    record.energy_change = kinetic_energy(i, grain.velocity) - energy_before;
    record.restitution = e;
    record.mass = mass_of(i);
    for (EventObserver<D>* observer : observers_) observer->on_wall_collision(record);
  }
  predict(i);
}

// The members defined in this file, for both dimensions (the class is instantiated in
// simulation.cpp, once).
template Spin<2> Simulation<2>::spin(std::int32_t) const;
template void Simulation<2>::set_spin(std::int32_t, const Spin<2>&);
template double Simulation<2>::kinetic_energy(std::int32_t, const Vec<2>&) const;
template RoughBody<2> Simulation<2>::rough_body(std::int32_t, const Vec<2>&) const;
template RoughImpulse<2> Simulation<2>::collide_rough(std::int32_t, std::int32_t, Vec<2>&, Vec<2>&, const Vec<2>&, double);
template void Simulation<2>::execute_wall_hit(std::int32_t, int);
template Spin<3> Simulation<3>::spin(std::int32_t) const;
template void Simulation<3>::set_spin(std::int32_t, const Spin<3>&);
template double Simulation<3>::kinetic_energy(std::int32_t, const Vec<3>&) const;
template RoughBody<3> Simulation<3>::rough_body(std::int32_t, const Vec<3>&) const;
template RoughImpulse<3> Simulation<3>::collide_rough(std::int32_t, std::int32_t, Vec<3>&, Vec<3>&, const Vec<3>&, double);
template void Simulation<3>::execute_wall_hit(std::int32_t, int);

}  // namespace granule
