// The engine's particles in and out: the initial state loaded, and the state and clock read at
// the current time (extrapolated from each particle's last event, wrapped into the box), by the
// user's ids, whatever the engine's numbering.
#include <memory>
#include <stdexcept>

#include "engine/simulation.hpp"

namespace granule {

template <int D>
void Simulation<D>::load(const ParticleState& state) {
  // Loaded at t_now_ = 0 (by the constructor), where a false position is the position itself.
  if (state.dimension != D) throw std::invalid_argument("the initial state has another dimension than the engine");
  particles_.assign(state.size(), ParticleRecord<D>{});
  for (std::size_t i = 0; i < state.size(); ++i) {
    ParticleRecord<D>& p = particles_[i];
    for (int a = 0; a < D; ++a) {
      p.r[a] = state.position(a)[i];
      p.v[a] = state.velocity(a)[i];
    }
  }
  diameter_ = state.diameter;
  mass_ = state.mass;
  if (params_.roughness.rough) {
    if (!state.rough()) throw std::invalid_argument("rough grains need angular velocities in the initial state");
    for (int k = 0; k < kSpinComponents; ++k) spin_[static_cast<std::size_t>(k)] = state.spin(k);
  }
}

template <int D>
ParticleState Simulation<D>::state() const {
  return state(0, particles_.size(), engine_ids());
}

template <int D>
StateBlocks Simulation<D>::state_blocks() const {
  // The inverse numbering is made once for all the blocks (4 bytes per particle while they are read).
  auto engine_id = std::make_shared<const std::vector<std::int32_t>>(engine_ids());
  return StateBlocks(particles_.size(), [this, engine_id](std::size_t first, std::size_t count) {
    return state(first, count, *engine_id);
  });
}

template <int D>
ParticleState Simulation<D>::state(std::size_t first, std::size_t count, const std::vector<std::int32_t>& engine_id) const {
  const auto id_of = [&](std::size_t user) {
    return engine_id.empty() ? static_cast<std::int32_t>(user) : engine_id[user];
  };
  ParticleState out;
  out.dimension = D;
  const auto part = [&](const std::vector<double>& all) {
    std::vector<double> values;
    if (all.empty()) return values;
    values.resize(count);
    for (std::size_t k = 0; k < count; ++k) values[k] = all[static_cast<std::size_t>(id_of(first + k))];
    return values;
  };
  out.diameter = part(diameter_);
  out.mass = part(mass_);
  for (int k = 0; k < kSpinComponents && params_.roughness.rough; ++k) out.spin(k) = part(spin_[static_cast<std::size_t>(k)]);
  out.resize(count);
  const double s = strain();
  for (std::size_t i = 0; i < count; ++i) {
    const std::int32_t id = id_of(first + i);
    Vector r = position_now(id);
    Vector v = velocity_now(id);
    boundaries_.wrap_into_box(r, v[0], s);
    for (int a = 0; a < D; ++a) {
      out.position(a)[i] = r[a];
      out.velocity(a)[i] = v[a];
    }
  }
  return out;
}

template <int D>
ClockState Simulation<D>::clock_state() const {
  ClockState clock;
  clock.time = time();
  clock.strain_reference = t_ref_ - t_now_;
  clock.strain_at_reference = strain_ref_;
  clock.protocol_running = protocol_running_;
  clock.held_shear_velocity = image_velocity();
  clock.collisions = collisions_;
  clock.events = events_;
  clock.last_collision = by_user_id(last_collision_);
  for (auto& t : clock.last_collision) t -= t_now_;
  return clock;
}

// The members defined in this file, for both dimensions (the class is instantiated in
// simulation.cpp, once).
template void Simulation<2>::load(const ParticleState&);
template ParticleState Simulation<2>::state() const;
template StateBlocks Simulation<2>::state_blocks() const;
template ParticleState Simulation<2>::state(std::size_t, std::size_t, const std::vector<std::int32_t>&) const;
template ClockState Simulation<2>::clock_state() const;
template void Simulation<3>::load(const ParticleState&);
template ParticleState Simulation<3>::state() const;
template StateBlocks Simulation<3>::state_blocks() const;
template ParticleState Simulation<3>::state(std::size_t, std::size_t, const std::vector<std::int32_t>&) const;
template ClockState Simulation<3>::clock_state() const;

}  // namespace granule
