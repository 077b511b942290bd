// The three kinds of event, each in two parts (engine/event_plans.hpp): a plan computed from the
// state without changing it, and a commit that applies it and predicts the particles' next
// events.  Crossings of cell faces and of the box's faces (thesis §1.4.2), collisions of grains
// (thesis eq 1.2, Fig 1.3) and hits of flat walls (thesis Appendix A.1), the last two under the
// collision law (physics/collision_law.hpp).
#include "engine/simulation.hpp"

namespace granule {

namespace {
inline std::size_t at(std::int32_t i) { return static_cast<std::size_t>(i); }
}  // namespace

template <int D>
FlightState<D> Simulation<D>::flight_through_now(std::int32_t i, const Vector& velocity) const {
  FlightState<D> flight{particles_[at(i)].r, particles_[at(i)].v};
  motion_.start_flight(flight.r, flight.v, velocity, t_now_);
  return flight;
}

template <int D>
void Simulation<D>::set_flight(std::int32_t i, const FlightState<D>& flight) {
  particles_[at(i)].r = flight.r;
  particles_[at(i)].v = flight.v;
}

template <int D>
CrossingPlan<D> Simulation<D>::plan_crossing(std::int32_t i, EventKind kind) const {
  const int axis = crossing_axis(kind);
  const int direction = crossing_direction(kind);
  std::array<int, D> cell = cell_coordinates(slot(i).cell());
  int& c = cell[static_cast<std::size_t>(axis)];
  c += direction;
  std::optional<ImageEntry<D>> entry;
  if (c < 0 || c >= grid_.count(axis)) {
    // Out through a face of the box: in from the image on the other side.
    c -= direction * grid_.count(axis);
    entry = image_entry(i, axis, direction);
  }
  if constexpr (D == 2) {
    return {i, axis, direction, grid_.index(cell[0], cell[1]), entry};
  } else {
    return {i, axis, direction, grid_.index(cell[0], cell[1], cell[2]), entry};
  }
}

template <int D>
ImageEntry<D> Simulation<D>::image_entry(std::int32_t i, int axis, int direction) const {
  ImageEntry<D> entry;
  const auto image = boundaries_.image_across(axis, direction, strain());
  entry.flight = {particles_[at(i)].r, particles_[at(i)].v};
  for (int a = 0; a < D; ++a) entry.flight.r[a] -= image.position[a];
  if (boundaries_.moving_images(axis)) {
    entry.moving_image = true;
    Vector v = velocity_now(i);
    entry.velocity_x_before = v[0];
    v[0] -= image.velocity_x;
    entry.velocity_x_after = v[0];
    motion_.start_flight(entry.flight.r, entry.flight.v, v, t_now_);
  }
  return entry;
}

template <int D>
void Simulation<D>::commit(const CrossingPlan<D>& plan) {
  const std::int32_t i = plan.particle;
  if (plan.entry) {
    set_flight(i, plan.entry->flight);
    if (plan.entry->moving_image && !observers_.empty()) {
      const BoundaryCrossingRecord record{time(), user_id(i), plan.direction, plan.entry->velocity_x_before,
                                          plan.entry->velocity_x_after};
      for (EventObserver<D>* observer : observers_) observer->on_boundary_crossing(record);
    }
  }
  lists_.remove(particles_, i, slot(i).cell());
  lists_.insert(particles_, i, plan.new_cell);
  slot(i).set_cell(plan.new_cell);
  predict_after_crossing(i, plan.axis, plan.direction);
}

// Plans are built whole at the end, not filled in member by member: a plan default-constructed
// first would be zeroed (its vectors' initialisers) and then written again, on every collision.
template <int D>
CollisionPlan<D> Simulation<D>::plan_collision(std::int32_t i, std::int32_t j) const {
  const Vector ri = position_now(i);
  const Vector rj = position_now(j);
  const PartnerImage image = nearest_image(rj - ri);
  Vector r;
  for (int a = 0; a < D; ++a) r[a] = rj[a] + image.shift.position[a] - ri[a];
  const Vector v1 = velocity_now(i);
  Vector v2 = velocity_now(j);
  v2[0] += image.shift.velocity_x;
  // Re-validate (Bannerman et al. 2014): near-simultaneous events may have been reordered by
  // round-off; a pair that is no longer approaching must not collide.
  if (!approaching(r, v2 - v1)) {
    CollisionPlan<D> stale;  // nothing to apply
    stale.first = i;
    stale.second = j;
    return stale;
  }
  const Vector k_hat = (1.0 / norm(r)) * r;
  const CollisionLaw law = pair_law();
  ContactSide<D> first = contact_side(i, v1);
  ContactSide<D> second = contact_side(j, v2);
  const double energy_before = observers_.empty() ? 0.0 : first.kinetic_energy() + second.kinetic_energy();
  const ContactOutcome<D> outcome = law.collide(first, second, k_hat, law.restitution_of(first, second, k_hat, recent_contact(law, i, j)));
  Vector v2_after = second.velocity;
  v2_after[0] -= image.shift.velocity_x;  // its own velocity, not its image's
  return {i, j, true, flight_through_now(i, first.velocity), flight_through_now(j, v2_after), first, second, outcome,
          image, ri, k_hat, v1, v2, energy_before};
}

template <int D>
bool Simulation<D>::commit(const CollisionPlan<D>& plan) {
  const std::int32_t i = plan.first;
  const std::int32_t j = plan.second;
  if (!plan.approaching) {
    predict(i);
    return false;
  }
  set_flight(i, plan.first_flight);
  store_spin(i, plan.first_side);
  set_flight(j, plan.second_flight);
  store_spin(j, plan.second_side);
  mark_contact(i, j);
  ++particles_[at(i)].count;
  ++particles_[at(j)].count;
  ++collisions_;

  if (!observers_.empty()) {
    const auto& shift = plan.image.shift;
    CollisionRecord<D> record;
    record.time = time();
    record.first = user_id(i);
    record.second = user_id(j);
    record.first_position = plan.first_position;
    record.contact_point = plan.first_position + radius_of(i) * plan.k_hat;
    double unused_vx = 0.0;
    boundaries_.wrap_into_box(record.contact_point, unused_vx, strain());
    record.first_velocity_before = plan.first_velocity_before;
    record.second_velocity_before = plan.second_velocity_before;
    record.second_velocity_before[0] = plan.second_velocity_before[0] - shift.velocity_x;
    record.first_velocity_after = plan.first_side.velocity;
    record.second_velocity_after = velocity_now(j);
    record.contact_normal = plan.k_hat;
    record.relative_velocity = plan.first_velocity_before - plan.second_velocity_before;
    record.impulse = plan.outcome.normal_impulse;
    record.tangential_impulse = plan.outcome.impulse.tangential;
    record.energy_change = plan.first_side.kinetic_energy() + plan.second_side.kinetic_energy() - plan.energy_before;
    record.restitution = plan.outcome.restitution;
    record.contact_distance = contact_distance(i, j);
    record.first_mass = plan.first_side.mass;
    record.second_mass = plan.second_side.mass;
    record.image_y = plan.image.image_y;
    record.image_velocity_x = shift.velocity_x;
    for (EventObserver<D>* observer : observers_) observer->on_collision(record);
  }
  queue_.prefetch_removal(j);
  predict(i);
  queue_.prefetch_removal(j, 2);  // the first slot has arrived meanwhile
  predict(j);
  return true;
}

template <int D>
SurfaceHit<D> Simulation<D>::plan_surface_hit(std::int32_t i, const Vector& before, const Vector& k_hat, const CollisionLaw& law,
                                              const Vector& surface_velocity) const {
  // The surface is a body of infinite mass and moment of inertia moving at its own velocity, under
  // the same law as grains (the TC model holds at surfaces too).
  ContactSide<D> grain = contact_side(i, before);
  ContactSide<D> surface = ContactSide<D>::wall(surface_velocity);
  const double energy_before = observers_.empty() ? 0.0 : grain.kinetic_energy();
  const ContactOutcome<D> outcome =
      law.collide(grain, surface, k_hat, law.restitution_of(grain, surface, k_hat, recent_contact(law, i, -1)));
  return {i, true, flight_through_now(i, grain.velocity), grain, outcome, before, energy_before};
}

template <int D>
bool Simulation<D>::apply(const SurfaceHit<D>& hit) {
  const std::int32_t i = hit.particle;
  if (!hit.approaching) {
    predict(i);
    return false;
  }
  set_flight(i, hit.flight);
  store_spin(i, hit.side);
  mark_contact(i, -1);
  ++particles_[at(i)].count;  // its pending partners' predictions are stale
  return true;
}

template <int D>
SurfaceHitRecord<D> Simulation<D>::describe(const SurfaceHitPlan<D>& plan) const {
  const SurfaceHit<D>& hit = plan.hit;
  SurfaceHitRecord<D> record;
  record.time = time();
  record.particle = user_id(hit.particle);
  record.surface = plan.surface;
  record.position = position_now(hit.particle);
  record.normal = plan.normal;
  record.velocity_before = hit.velocity_before;
  record.velocity_after = hit.side.velocity;
  record.impulse_on_surface = hit.outcome.impulse.total();
  record.energy_change = hit.side.kinetic_energy() - hit.energy_before;
  record.restitution = hit.outcome.restitution;
  record.mass = hit.side.mass;
  record.comes_to_rest = plan.comes_to_rest;
  return record;
}

template <int D>
SurfaceHitPlan<D> Simulation<D>::plan_surface_hit(std::int32_t i, int kind) const {
  const Vector before = velocity_now(i);
  const auto contact = boundaries_.contact(kind, slot(i).cell(), position_now(i), before, radius_of(i), time());
  if (!contact.touching) return {{}, {}, {.particle = i}};  // nothing to apply
  // A grain at rest struck hard, or from below (its weight is held from below: pushed up, it is
  // lifted), moves again and the two collide.
  if (contact.grain && (dot(before, contact.k_hat) > params_.rest.wake_speed || dot(contact.k_hat, down()) < 0.0)) {
    return {contact.surface, contact.k_hat, {.particle = i}, false, contact.surface.index, true};
  }
  const CollisionLaw law = contact.grain ? resting_grain_law() : surface_law(contact.restitution, contact.tangential_restitution);
  SurfaceHitPlan<D> plan{contact.surface, contact.k_hat, plan_surface_hit(i, before, contact.k_hat, law, contact.velocity)};
  if (norm(contact.velocity) != 0.0) return plan;  // a moving surface: none of the rules below
  SurfaceHit<D>& hit = plan.hit;
  // Only a hit outside the TC model's window: a grain just set moving (woken, struck) bounces
  // once more before it may rest again, which keeps rest and wake from alternating in no time.
  if (rest_rule_active() && !recent_contact(law, i, -1) && comes_to_rest(i, hit)) {
    // Perfectly inelastic: the supports take the grain's momentum, its energy is dissipated.
    hit.outcome.impulse.normal = hit.side.mass * dot(before, contact.k_hat) * contact.k_hat;
    hit.outcome.impulse.tangential = hit.side.mass * before - hit.outcome.impulse.normal;
    hit.side.velocity = {};
    hit.side.spin = {};
    hit.flight = flight_through_now(i, {});
    plan.comes_to_rest = true;
    return plan;
  }
  if (const double lift = sliding_lift(hit.side.velocity, contact.k_hat); lift > 0.0) {
    hit.side.velocity = hit.side.velocity - lift * contact.k_hat;
    hit.outcome.impulse.normal = hit.outcome.impulse.normal + hit.side.mass * lift * contact.k_hat;
    hit.flight = flight_through_now(i, hit.side.velocity);
  }
  if (!rest_rule_active()) return plan;
  // Wedged between this surface and another static one it touches and would bounce into at once,
  // it would rattle between them in no time: a grain at rest among the two moves again, so that
  // the rattle is a sequence of collisions that take time.
  if (const SurfaceId wedge = wedging_support(i, hit.side.velocity, contact.surface); wedge.found()) {
    if (contact.grain) return {contact.surface, contact.k_hat, {.particle = i}, false, contact.surface.index, true};
    plan.wakes = wedge.resting_grain();
  }
  return plan;
}

template <int D>
void Simulation<D>::commit(const SurfaceHitPlan<D>& plan) {
  if (plan.wakes_struck) {
    wake(plan.wakes);
    commit(plan_collision(plan.hit.particle, plan.wakes));
    return;
  }
  if (!apply(plan.hit)) return;
  if (!observers_.empty()) {
    const SurfaceHitRecord<D> record = describe(plan);
    for (EventObserver<D>* observer : observers_) observer->on_surface_hit(record);
  }
  if (plan.wakes >= 0) wake(plan.wakes);
  if (plan.comes_to_rest) {
    put_at_rest(plan.hit.particle);
  } else {
    predict(plan.hit.particle);
  }
}

// The members defined in this file, for both dimensions (the class is instantiated in
// simulation.cpp, once).
template FlightState<2> Simulation<2>::flight_through_now(std::int32_t, const Vec<2>&) const;
template void Simulation<2>::set_flight(std::int32_t, const FlightState<2>&);
template CrossingPlan<2> Simulation<2>::plan_crossing(std::int32_t, EventKind) const;
template ImageEntry<2> Simulation<2>::image_entry(std::int32_t, int, int) const;
template void Simulation<2>::commit(const CrossingPlan<2>&);
template CollisionPlan<2> Simulation<2>::plan_collision(std::int32_t, std::int32_t) const;
template bool Simulation<2>::commit(const CollisionPlan<2>&);
template SurfaceHit<2> Simulation<2>::plan_surface_hit(std::int32_t, const Vec<2>&, const Vec<2>&, const CollisionLaw&,
                                                           const Vec<2>&) const;
template bool Simulation<2>::apply(const SurfaceHit<2>&);
template SurfaceHitRecord<2> Simulation<2>::describe(const SurfaceHitPlan<2>&) const;
template SurfaceHitPlan<2> Simulation<2>::plan_surface_hit(std::int32_t, int) const;
template void Simulation<2>::commit(const SurfaceHitPlan<2>&);
template FlightState<3> Simulation<3>::flight_through_now(std::int32_t, const Vec<3>&) const;
template void Simulation<3>::set_flight(std::int32_t, const FlightState<3>&);
template CrossingPlan<3> Simulation<3>::plan_crossing(std::int32_t, EventKind) const;
template ImageEntry<3> Simulation<3>::image_entry(std::int32_t, int, int) const;
template void Simulation<3>::commit(const CrossingPlan<3>&);
template CollisionPlan<3> Simulation<3>::plan_collision(std::int32_t, std::int32_t) const;
template bool Simulation<3>::commit(const CollisionPlan<3>&);
template SurfaceHit<3> Simulation<3>::plan_surface_hit(std::int32_t, const Vec<3>&, const Vec<3>&, const CollisionLaw&,
                                                           const Vec<3>&) const;
template bool Simulation<3>::apply(const SurfaceHit<3>&);
template SurfaceHitRecord<3> Simulation<3>::describe(const SurfaceHitPlan<3>&) const;
template SurfaceHitPlan<3> Simulation<3>::plan_surface_hit(std::int32_t, int) const;
template void Simulation<3>::commit(const SurfaceHitPlan<3>&);

}  // namespace granule
