// Contacts as the collision law sees them (physics/collision_law.hpp): a grain as one side of a
// contact, with its spin when grains are rough; the TC model's history; and grains hitting flat
// walls (thesis Appendix A.1: a reflection executed as a boundary event, under the same law).
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
ContactSide<D> Simulation<D>::contact_side(std::int32_t i, const Vector& velocity) const {
  ContactSide<D> side{velocity, {}, radius_of(i), mass_of(i), 0.0};
  if (!spin_[0].empty()) {  // rough grains
    side.spin = spin(i);
    side.inertia_factor = params_.roughness.inertia_factor;
  }
  return side;
}

template <int D>
double Simulation<D>::contact_restitution(const CollisionLaw& law, std::int32_t i, std::int32_t j) {
  if (!law.keeps_history()) return law.restitution;
  double& last_i = last_collision_[at(i)];
  double& last_j = last_collision_[at(j < 0 ? i : j)];
  const double e = law.restitution_at(t_now_, last_i, last_j);
  last_i = t_now_;
  last_j = t_now_;
  return e;
}

template <int D>
void Simulation<D>::execute_wall_hit(std::int32_t i, int face) {
  const Vector k_hat = BoxBoundaries<D>::wall_normal(face);  // from the grain towards the wall
  const Vector before = velocity_now(i);
  // Re-validate as for pairs: a grain no longer moving into the wall is left alone.
  if (dot(before, k_hat) <= 0.0) {
    predict(i);
    return;
  }
  // The wall is a body of infinite mass and moment of inertia moving at its own velocity, under
  // the same law as grains (the TC model holds at walls too).
  const CollisionLaw law = wall_law(face);
  const double e = contact_restitution(law, i, -1);
  ContactSide<D> grain = contact_side(i, before);
  ContactSide<D> wall = ContactSide<D>::wall(boundaries_.wall_velocity(face));
  const double energy_before = grain.kinetic_energy();
  const ContactOutcome<D> outcome = law.collide(grain, wall, k_hat, e);
  set_velocity_now(i, grain.velocity);
  store_spin(i, grain);
  ++particles_[at(i)].count;  // its pending partners' predictions are stale

  if (!observers_.empty()) {
    WallCollisionRecord<D> record;
    record.time = time();
    record.particle = user_id(i);
    record.axis = face / 2;
    record.side = face % 2;
    record.position = position_now(i);
    record.velocity_before = before;
    record.velocity_after = grain.velocity;
    record.impulse_on_wall = outcome.impulse.total();
    record.energy_change = grain.kinetic_energy() - energy_before;
    record.restitution = e;
    record.mass = grain.mass;
    for (EventObserver<D>* observer : observers_) observer->on_wall_collision(record);
  }
  predict(i);
}

// The members defined in this file, for both dimensions (the class is instantiated in
// simulation.cpp, once).
template Spin<2> Simulation<2>::spin(std::int32_t) const;
template void Simulation<2>::set_spin(std::int32_t, const Spin<2>&);
template ContactSide<2> Simulation<2>::contact_side(std::int32_t, const Vec<2>&) const;
template double Simulation<2>::contact_restitution(const CollisionLaw&, std::int32_t, std::int32_t);
template void Simulation<2>::execute_wall_hit(std::int32_t, int);
template Spin<3> Simulation<3>::spin(std::int32_t) const;
template void Simulation<3>::set_spin(std::int32_t, const Spin<3>&);
template ContactSide<3> Simulation<3>::contact_side(std::int32_t, const Vec<3>&) const;
template double Simulation<3>::contact_restitution(const CollisionLaw&, std::int32_t, std::int32_t);
template void Simulation<3>::execute_wall_hit(std::int32_t, int);

}  // namespace granule
