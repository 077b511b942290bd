// Contacts as the collision law sees them (physics/collision_law.hpp): a grain as one side of a
// contact, with its spin when grains are rough, and the TC model's history of contacts.
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
bool Simulation<D>::recent_contact(const CollisionLaw& law, std::int32_t i, std::int32_t j) const {
  if (!law.keeps_history()) return false;
  return law.within_contact_duration(t_now_, last_collision_[at(i)], last_collision_[at(j < 0 ? i : j)]);
}

template <int D>
void Simulation<D>::mark_contact(std::int32_t i, std::int32_t j) {
  if (last_collision_.empty()) return;  // no TC model
  last_collision_[at(i)] = t_now_;
  last_collision_[at(j < 0 ? i : j)] = t_now_;
}

// The members defined in this file, for both dimensions (the class is instantiated in
// simulation.cpp, once).
template Spin<2> Simulation<2>::spin(std::int32_t) const;
template void Simulation<2>::set_spin(std::int32_t, const Spin<2>&);
template ContactSide<2> Simulation<2>::contact_side(std::int32_t, const Vec<2>&) const;
template bool Simulation<2>::recent_contact(const CollisionLaw&, std::int32_t, std::int32_t) const;
template void Simulation<2>::mark_contact(std::int32_t, std::int32_t);
template Spin<3> Simulation<3>::spin(std::int32_t) const;
template void Simulation<3>::set_spin(std::int32_t, const Spin<3>&);
template ContactSide<3> Simulation<3>::contact_side(std::int32_t, const Vec<3>&) const;
template bool Simulation<3>::recent_contact(const CollisionLaw&, std::int32_t, std::int32_t) const;
template void Simulation<3>::mark_contact(std::int32_t, std::int32_t);

}  // namespace granule
