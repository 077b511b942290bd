#include "engine/simulation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "memory/prefetch_lines.hpp"
#include "physics/collision_time.hpp"

namespace granule {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
// Re-base the clock every this many events per particle: cheap (O(N)) and keeps t_now small, so
// that a position now, r + v·t_now from the record's false position, keeps the precision of a
// position in arbitrarily long runs (particle_record.hpp).
constexpr std::int64_t kRebaseEventsPerParticle = 16;

inline std::size_t at(std::int32_t i) { return static_cast<std::size_t>(i); }
}  // namespace

template <int D>
Vec<D> Simulation<D>::position_at(std::int32_t i, double time) const {
  const ParticleRecord<D>& p = particles_[at(i)];
  if (p.partner == kAtRest) return p.r;
  return motion_.position_at(p.r, p.v, time);
}

template <int D>
Vec<D> Simulation<D>::position_now(std::int32_t i) const {
  return position_at(i, t_now_);
}

template <int D>
Vec<D> Simulation<D>::velocity_now(std::int32_t i) const {
  if (at_rest(i)) return {};
  return motion_.velocity_at(particles_[at(i)].v, t_now_);
}

template <int D>
Simulation<D>::Simulation(const SystemParams& params, const CellGrid& grid, const ParticleState& state,
                          const ClockState& clock)
    : params_(params),
      grid_(checked(grid)),
      by_columns_(static_cast<std::uint32_t>(grid.nx)),
      by_rows_(static_cast<std::uint32_t>(grid.ny)),
      boundaries_(boundaries_of(params, grid)),
      motion_(params.gravity),
      protocol_(image_protocol(params)) {
  load(state);
  if (params.tc_duration > 0.0) {
    last_collision_ = clock.last_collision;
    last_collision_.resize(static_cast<std::size_t>(params.particles), -kInf);
  }
  clock_base_ = clock.time;
  t_ref_ = clock.strain_reference;
  strain_ref_ = clock.strain_at_reference;
  collisions_ = clock.collisions;
  events_ = clock.events;
  protocol_running_ = clock.protocol_running;
  boundaries_.set_drives_running(protocol_running_);
  if (protocol_running_) {
    // The segment a run that got here would be in: the chain of segments is fixed by the protocol.
    const ShearSegment segment = protocol_.segment_containing(clock.time);
    boundaries_.set_image_velocity(segment.velocity);
    segment_end_ = segment.end;
    actions_.schedule(TimedAction::kShearSegment, segment.end - clock_base_);
  } else {
    boundaries_.set_image_velocity(clock.held_shear_velocity.value_or(protocol_.velocity(0.0)));
  }
  shear_rate_ = image_velocity() / params.length_y;
  rebuild();
  collapse_detector_.reset(collapse_window(), t_now_);
  renumber_interval_ = std::llround(params.renumber_every * static_cast<double>(params.particles));
  if (renumber_interval_ > 0) {
    number_by_user_id();
    queue_.set_tie_order(user_id_);
    renumber();
  }
}

template <int D>
double Simulation<D>::bytes_per_particle() const {
  auto bytes = [](const auto& v) { return v.capacity() * sizeof(v[0]); };
  std::size_t total = bytes(particles_) + bytes(diameter_) + bytes(mass_) + bytes(last_collision_) +
                      bytes(user_id_) + lists_.bytes() + queue_.bytes() + boundaries_.bytes();
  for (const auto& w : spin_) total += bytes(w);
  return static_cast<double>(total) / static_cast<double>(params_.particles);
}

template <int D>
std::int32_t Simulation<D>::cell_of(const Vector& r) const {
  const double xi = boundaries_.frame().sheared_x(r[0], r[1], strain());
  const int column = std::clamp(static_cast<int>(std::floor(xi / grid_.width)), 0, grid_.nx - 1);
  const int row = std::clamp(static_cast<int>(std::floor(r[1] / grid_.height)), 0, grid_.ny - 1);
  int layer = 0;
  if constexpr (D == 3) layer = std::clamp(static_cast<int>(std::floor(r[2] / grid_.depth)), 0, grid_.nz - 1);
  return grid_.index(column, row, layer);
}

template <int D>
void Simulation<D>::rebase() {
  const double delta = t_now_;
  // Every false position moves to the new base (particle_record.hpp).
  motion_.visit([&](const auto& flight) {
    for (ParticleRecord<D>& p : particles_) {
      if (p.partner == kAtRest) continue;  // no flight: its record holds its position
      for (int a = 0; a < D; ++a) flight.advance_base(a, p.r[a], p.v[a], delta);
    }
  });
  for (auto& t : last_collision_) t -= delta;
  queue_.shift_times(delta);
  collapse_detector_.shift_times(delta);
  actions_.shift_times(delta);
  t_ref_ -= delta;
  clock_base_ += delta;
  t_now_ = 0.0;
  events_since_rebase_ = 0;
  schedule_realignment();
}

template <int D>
void Simulation<D>::rebuild() {
  const auto n = static_cast<std::int32_t>(params_.particles);
  rebase();  // the records now hold the states now, which are wrapped into the box
  const double s = strain();
  for (auto& p : particles_) boundaries_.wrap_into_grid(p.r, p.v[0], s);
  lists_.reset(grid_.cell_count());
  queue_.reset(n);
  boundaries_.resting_grains().clear();
  // Filled in the order of user ids: the order within a list decides ties between candidates, and
  // must not follow the engine's numbering.  Grains at rest stand as supports, in no cell list.
  const std::vector<std::int32_t> engine_id = engine_ids();
  for (std::int32_t user = 0; user < n; ++user) {
    const std::int32_t i = engine_id.empty() ? user : engine_id[at(user)];
    slot(i).set_cell(cell_of(position_now(i)));
    if (at_rest(i)) {
      boundaries_.rest_grain(i, position_now(i), radius_of(i));
    } else {
      lists_.insert(particles_, i, slot(i).cell());
    }
  }
  for (std::int32_t i = 0; i < n; ++i) {
    if (at_rest(i)) {
      slot(i).set_kind(EventKind::kNone);
      queue_.update(i, kInf);
    } else {
      predict(i);
    }
  }
}

template <int D>
void Simulation<D>::set_surfaces(const SystemParams& p) {
  params_.set_surface_parameters(p);
  boundaries_.set_surfaces(p.surfaces());
}

template <int D>
BoxBoundaries<D> Simulation<D>::boundaries_of(const SystemParams& p, const CellGrid& grid) {
  const CellLayout cells{{grid.nx, grid.ny, grid.nz}, {grid.width, grid.height, grid.depth}};
  return BoxBoundaries<D>(p.surfaces(), ShearFrame{p.length_x, p.length_y, 0.0}, p.length_z, cells, 0.5 * p.diameter);
}

template <int D>
void Simulation<D>::start_production(const SystemParams& production) {
  params_.restitution = production.restitution;
  params_.restitution_law = production.restitution_law;
  params_.roughness.tangential_restitution = production.roughness.tangential_restitution;
  set_surfaces(production);
  clock_base_ = -t_now_;
  collisions_ = 0;
  events_ = 0;
  for (auto& t : last_collision_) t = -kInf;
  protocol_running_ = true;
  boundaries_.set_drives_running(true);
  enter_shear_segment(protocol_.segment_from(0.0));
  // Walls that move normal to themselves start now: the hits predicted at rest no longer hold.
  bool walls_move = false;
  for (int face = 0; face < 2 * D; ++face) walls_move = walls_move || boundaries_.moving(face);
  if (walls_move) {
    for (std::int32_t i = 0; i < static_cast<std::int32_t>(params_.particles); ++i) {
      if (!at_rest(i)) predict(i);
    }
  }
}

template <int D>
StopReason Simulation<D>::run(double until_time, std::int64_t until_collisions) {
  const std::int64_t rebase_interval = kRebaseEventsPerParticle * params_.particles;
  if (collisions_ >= until_collisions) return StopReason::kCollisionsReached;
  while (true) {
    if (interrupt_ && *interrupt_) return StopReason::kInterrupted;
    // Here, between events, no particle number is held anywhere but in the engine's own arrays.
    if (renumber_interval_ > 0 && events_since_renumber_ >= renumber_interval_) renumber();
    const double t_event = queue_.top_time();
    const double t_action = actions_.earliest_time();
    // The stop is decided on the absolute clock the caller reads, time() = clock_base_ + t_now_,
    // so that kTimeReached always means time() ≥ until_time: a stop one ulp short would make the
    // caller ask for the same stop forever.
    const bool stop_due = clock_base_ + t_event >= until_time;
    const double t_stop = until_time - clock_base_;
    // A global action due no later than the next event runs first, unless the stop comes first.
    if (t_action <= t_event && !(stop_due && t_stop <= t_action)) {
      t_now_ = std::max(t_now_, t_action);
      if (actions_.earliest() == TimedAction::kShearSegment) {
        enter_shear_segment(protocol_.segment_from(segment_end_));
      } else {
        realign_sheared_grid();
      }
      continue;
    }
    if (stop_due) {
      if (until_time == kInf) return StopReason::kNoEvents;
      // Stopping moves only the clock, never past the next event (which resets it to its own
      // time), so a stop changes nothing in the trajectory.
      t_now_ = std::max(t_now_, std::min(t_stop, t_event));
      while (clock_base_ + t_now_ < until_time) t_now_ = std::nextafter(t_now_, t_event);
      return StopReason::kTimeReached;
    }
    const std::int32_t i = queue_.top();
    prefetch_next_event();
    t_now_ = t_event;
    ++events_;
    // Re-based on a count of events alone, before any early return, so that the trajectory does
    // not depend on where run() is stopped.
    const bool rebase_due = ++events_since_rebase_ >= rebase_interval;
    ++events_since_renumber_;
#ifdef GRANULE_PARANOID
    check_popped_event(i);
#endif
    const EventKind kind = slot(i).kind();
    // The partner's record: read by a collision, and by a crossing that keeps its candidate.
    const std::int32_t j = particles_[at(i)].partner;
    if (j >= 0) prefetch_lines(particles_.data() + j, prefetches_records());
    if (kind == EventKind::kCollision) __builtin_prefetch(&slot(j));  // re-scheduled below, if valid
    bool collided = false;
    bool hit_surface_now = false;
    if (kind == EventKind::kCollision) {
      if (!candidate_valid(i)) {
        predict(i);  // the partner has collided since: stale
      } else {
        collided = commit(plan_collision(i, j));
      }
    } else if (kind == EventKind::kNone) {
      return StopReason::kNoEvents;  // its time is +inf, so the stop above returns first
    } else if (is_surface_hit(kind)) {
      commit(plan_surface_hit(i, hit_surface(kind)));
      hit_surface_now = true;
    } else {
      commit(plan_crossing(i, kind));
    }
    if (rebase_due) {
#ifdef GRANULE_PARANOID
      check_invariants();
#endif
      rebase();
    }
    // Surface hits count towards collapse too: a grain bouncing ever lower on a floor (without the
    // TC model) hits it infinitely often in a finite time.
    if (collided || hit_surface_now) {
      if (collapse_detector_.on_collision(t_now_)) {
        const Vector where = position_now(i);
        collapse_ = {time(), user_id(i), collided ? user_id(j) : -1, {where[0], where[1], D == 3 ? where[D - 1] : 0.0}};
        return StopReason::kInelasticCollapse;
      }
      if (collided && collisions_ >= until_collisions) return StopReason::kCollisionsReached;
    }
  }
}

template class Simulation<2>;
template class Simulation<3>;

}  // namespace granule
