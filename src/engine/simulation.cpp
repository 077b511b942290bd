#include "engine/simulation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "physics/collision_rule.hpp"
#include "physics/collision_time.hpp"
#include "physics/crossing_time.hpp"

namespace granule {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
// Re-base the clock every this many events per particle: cheap (O(N)) and keeps local times
// small so that x + v (t − t_i) keeps full precision in arbitrarily long runs.
constexpr std::int64_t kRebaseEventsPerParticle = 16;

inline std::size_t at(std::int32_t i) { return static_cast<std::size_t>(i); }
}  // namespace

Simulation::Simulation(const SystemParams& params, const CellGrid& grid, const ParticleState& state,
                       const ClockState& clock)
    : params_(params),
      grid_(grid),
      frame_{params.length_x, params.length_y, 0.0},
      protocol_(params.shear_velocity, params.shear_history) {
  load(state);
  allocate_arrays();
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
  if (protocol_running_) {
    // The segment a run that got here would be in: the chain of segments is fixed by the protocol.
    const ShearSegment segment = protocol_.segment_containing(clock.time);
    frame_.shear_velocity = segment.velocity;
    segment_end_ = segment.end;
    actions_.schedule(TimedAction::kShearSegment, segment.end - clock_base_);
  } else {
    frame_.shear_velocity = clock.held_shear_velocity.value_or(protocol_.velocity(0.0));
  }
  shear_rate_ = frame_.shear_velocity / params.length_y;
  rebuild();
  collapse_detector_.reset(collapse_window(), t_now_);
}

void Simulation::allocate_arrays() {
  const auto n = static_cast<std::size_t>(params_.particles);
  count_.assign(n, 0);
  cell_.assign(n, 0);
  kind_.assign(n, EventKind::kNone);
  partner_.assign(n, -1);
  partner_count_.assign(n, 0);
  // Kept only where U changes over and over (a time-dependent protocol): +8 B per disk and one
  // store per prediction that a constant drive does not pay.
  if (!protocol_.constant()) collision_time_.assign(n, kInf);
}

double Simulation::bytes_per_particle() const {
  auto bytes = [](const auto& v) { return v.capacity() * sizeof(v[0]); };
  const std::size_t total = bytes(x_) + bytes(y_) + bytes(vx_) + bytes(vy_) + bytes(t_) +
                            bytes(count_) + bytes(cell_) + bytes(last_collision_) + bytes(kind_) +
                            bytes(partner_) + bytes(partner_count_) + bytes(collision_time_) + lists_.bytes() + heap_.bytes();
  return static_cast<double>(total) / static_cast<double>(params_.particles);
}

void Simulation::advance(std::int32_t i) {
  const double dt = t_now_ - t_[at(i)];
  x_[at(i)] += vx_[at(i)] * dt;
  y_[at(i)] += vy_[at(i)] * dt;
  t_[at(i)] = t_now_;
}

std::int32_t Simulation::cell_of(double x, double y) const {
  const double xi = frame_.sheared_x(x, y, strain());
  const int column = std::clamp(static_cast<int>(std::floor(xi / grid_.width)), 0, grid_.nx - 1);
  const int row = std::clamp(static_cast<int>(std::floor(y / grid_.height)), 0, grid_.ny - 1);
  return grid_.index(column, row);
}

void Simulation::rebase() {
  const double delta = t_now_;
  for (auto& t : t_) t -= delta;
  for (auto& t : last_collision_) t -= delta;
  for (auto& t : collision_time_) t -= delta;
  heap_.shift_times(delta);
  collapse_detector_.shift_times(delta);
  actions_.shift_times(delta);
  t_ref_ -= delta;
  clock_base_ += delta;
  t_now_ = 0.0;
  events_since_rebase_ = 0;
  schedule_realignment();
}

void Simulation::rebuild() {
  const auto n = static_cast<std::int32_t>(params_.particles);
  for (std::int32_t i = 0; i < n; ++i) advance(i);
  rebase();
  const double lx = params_.length_x;
  const double s = strain();
  for (std::int32_t i = 0; i < n; ++i) {
    double& x = x_[at(i)];
    frame_.wrap_into_box(x, y_[at(i)], vx_[at(i)], s);
    // Then into [0, L_x) in the sheared abscissa, where the cell grid lives.
    x -= lx * std::floor(frame_.sheared_x(x, y_[at(i)], s) / lx);
  }
  lists_.reset(grid_.cell_count(), params_.particles);
  for (std::int32_t i = 0; i < n; ++i) {
    cell_[at(i)] = cell_of(x_[at(i)], y_[at(i)]);
    lists_.insert(i, cell_[at(i)]);
  }
  heap_.reset(n);
  for (std::int32_t i = 0; i < n; ++i) predict(i);
}

void Simulation::load(const ParticleState& state) {
  x_ = state.x;
  y_ = state.y;
  vx_ = state.vx;
  vy_ = state.vy;
  t_.assign(state.size(), t_now_);
}

ParticleState Simulation::state() const {
  ParticleState out;
  out.resize(static_cast<std::size_t>(params_.particles));
  const double s = strain();
  for (std::size_t i = 0; i < out.size(); ++i) {
    const double dt = t_now_ - t_[i];
    out.x[i] = x_[i] + vx_[i] * dt;
    out.y[i] = y_[i] + vy_[i] * dt;
    out.vx[i] = vx_[i];
    out.vy[i] = vy_[i];
    frame_.wrap_into_box(out.x[i], out.y[i], out.vx[i], s);
  }
  return out;
}

ClockState Simulation::clock_state() const {
  ClockState clock;
  clock.time = time();
  clock.strain_reference = t_ref_ - t_now_;
  clock.strain_at_reference = strain_ref_;
  clock.protocol_running = protocol_running_;
  clock.held_shear_velocity = frame_.shear_velocity;
  clock.collisions = collisions_;
  clock.events = events_;
  clock.last_collision = last_collision_;
  for (auto& t : clock.last_collision) t -= t_now_;
  return clock;
}

void Simulation::start_production(double restitution) {
  params_.restitution = restitution;
  clock_base_ = -t_now_;
  collisions_ = 0;
  events_ = 0;
  for (auto& t : last_collision_) t = -kInf;
  protocol_running_ = true;
  enter_shear_segment(protocol_.segment_from(0.0));
}

Simulation::Crossing Simulation::next_crossing(std::int32_t i, double xi, double yi) const {
  const double vxi = vx_[at(i)];
  const double vyi = vy_[at(i)];
  const int cell = cell_[at(i)];
  const int column = grid_.column_of(cell);
  const int row = grid_.row_of(cell);

  // In the sheared frame ξ(τ) = ξ0 + bτ + aτ² (shear_frame.hpp); periodic boxes have a = 0 and
  // b = v_x.
  const double s = strain();
  const double y_rel = yi - 0.5 * params_.length_y;
  const double xi0 = xi - s * y_rel;
  const double a = -shear_rate_ * vyi;
  const double b = vxi - shear_rate_ * y_rel - s * vyi;
  const double left = column * grid_.width;
  const double right = left + grid_.width;
  double best = first_exit_time(a, b, xi0 - right);
  EventKind kind = EventKind::kCrossRight;
  if (const double t = first_exit_time(-a, -b, left - xi0); t < best) {
    best = t;
    kind = EventKind::kCrossLeft;
  }
  if (vyi > 0.0) {
    if (const double t = std::max(0.0, ((row + 1) * grid_.height - yi) / vyi); t < best) {
      best = t;
      kind = EventKind::kCrossUp;
    }
  } else if (vyi < 0.0) {
    if (const double t = std::max(0.0, (row * grid_.height - yi) / vyi); t < best) {
      best = t;
      kind = EventKind::kCrossDown;
    }
  }
  if (best == kInf) kind = EventKind::kNone;
  return {kind, best};
}

Simulation::Prediction Simulation::next_event(std::int32_t i) const {
  const double dt_i = t_now_ - t_[at(i)];
  const double vxi = vx_[at(i)];
  const double vyi = vy_[at(i)];
  const double xi = x_[at(i)] + vxi * dt_i;
  const double yi = y_[at(i)] + vyi * dt_i;
  const Crossing crossing = next_crossing(i, xi, yi);

  // Collisions with the disks of the 3×3 block of cells.
  const double sigma = params_.diameter;
  std::int32_t partner = -1;
  double best = kInf;
  for_each_neighbour(i, [&](std::int32_t j, double shift_x, const ImageShift& row_shift) {
    const double dt_j = t_now_ - t_[at(j)];
    const Vec2 rel_position{x_[at(j)] + vx_[at(j)] * dt_j + shift_x - xi,
                            y_[at(j)] + vy_[at(j)] * dt_j + row_shift.position.y - yi};
    const Vec2 rel_velocity{vx_[at(j)] + row_shift.velocity_x - vxi, vy_[at(j)] - vyi};
    if (const double t = collision_time(rel_position, rel_velocity, sigma); t < best) {
      best = t;
      partner = j;
    }
  });
  return {crossing, partner, best};
}

void Simulation::predict(std::int32_t i) {
  const Prediction next = next_event(i);
  kind_[at(i)] = next.kind();
  partner_[at(i)] = next.partner;
  partner_count_[at(i)] = next.partner >= 0 ? count_[at(next.partner)] : 0;
  if (!collision_time_.empty()) collision_time_[at(i)] = t_now_ + next.collision_delay;
  heap_.update(i, t_now_ + next.delay());
}

void Simulation::execute_crossing(std::int32_t i, EventKind kind) {
  advance(i);
  const int old_cell = cell_[at(i)];
  int column = grid_.column_of(old_cell);
  int row = grid_.row_of(old_cell);
  switch (kind) {
    case EventKind::kCrossRight:
      if (++column == grid_.nx) {
        column = 0;
        x_[at(i)] -= params_.length_x;
      }
      break;
    case EventKind::kCrossLeft:
      if (--column < 0) {
        column = grid_.nx - 1;
        x_[at(i)] += params_.length_x;
      }
      break;
    case EventKind::kCrossUp:
      if (++row == grid_.ny) {
        // Out through the top, in at the bottom from the image below (thesis §1.4.2).
        row = 0;
        enter_from_image(i, -1);
      }
      break;
    case EventKind::kCrossDown:
      if (--row < 0) {
        row = grid_.ny - 1;
        enter_from_image(i, 1);
      }
      break;
    default:
      break;
  }
  const int new_cell = grid_.index(column, row);
  lists_.remove(i, old_cell);
  lists_.insert(i, new_cell);
  cell_[at(i)] = new_cell;
  predict(i);
}

bool Simulation::execute_collision(std::int32_t i, std::int32_t j) {
  advance(i);
  advance(j);
  const double s = strain();
  const auto [iy, shift] = nearest_image(x_[at(j)] - x_[at(i)], y_[at(j)] - y_[at(i)]);

  const Vec2 r{x_[at(j)] + shift.position.x - x_[at(i)], y_[at(j)] + shift.position.y - y_[at(i)]};
  const Vec2 v1{vx_[at(i)], vy_[at(i)]};
  const Vec2 v2{vx_[at(j)] + shift.velocity_x, vy_[at(j)]};
  // Re-validate (Bannerman et al. 2014): near-simultaneous events may have been reordered by
  // round-off; a pair that is no longer approaching must not collide.
  if (dot(r, v2 - v1) >= 0.0) {
    predict(i);
    return false;
  }
  const Vec2 k_hat = (1.0 / norm(r)) * r;
  double e = params_.restitution;
  if (!last_collision_.empty()) {
    const double tc = params_.tc_duration;
    if (t_now_ - last_collision_[at(i)] < tc || t_now_ - last_collision_[at(j)] < tc) e = 1.0;
    last_collision_[at(i)] = t_now_;
    last_collision_[at(j)] = t_now_;
  }
  const PostCollisionVelocities after = collide(v1, v2, k_hat, e);
  vx_[at(i)] = after.v1.x;
  vy_[at(i)] = after.v1.y;
  vx_[at(j)] = after.v2.x - shift.velocity_x;
  vy_[at(j)] = after.v2.y;
  ++count_[at(i)];
  ++count_[at(j)];
  ++collisions_;

  if (!observers_.empty()) {
    CollisionRecord record;
    record.time = time();
    record.first = i;
    record.second = j;
    record.first_position = {x_[at(i)], y_[at(i)]};
    record.contact_point = record.first_position + (0.5 * params_.diameter) * k_hat;
    double unused_vx = 0.0;
    frame_.wrap_into_box(record.contact_point.x, record.contact_point.y, unused_vx, s);
    record.first_velocity_before = v1;
    record.second_velocity_before = {v2.x - shift.velocity_x, v2.y};
    record.first_velocity_after = after.v1;
    record.second_velocity_after = {vx_[at(j)], vy_[at(j)]};
    record.contact_normal = k_hat;
    record.relative_velocity = v1 - v2;
    record.impulse = normal_impulse(v1 - v2, k_hat, e);
    record.restitution = e;
    record.image_y = iy;
    record.image_velocity_x = shift.velocity_x;
    for (EventObserver* observer : observers_) observer->on_collision(record);
  }
  predict(i);
  predict(j);
  return true;
}

StopReason Simulation::run(double until_time, std::int64_t until_collisions) {
  const std::int64_t rebase_interval = kRebaseEventsPerParticle * params_.particles;
  if (collisions_ >= until_collisions) return StopReason::kCollisionsReached;
  while (true) {
    if (interrupt_ && *interrupt_) return StopReason::kInterrupted;
    const double t_event = heap_.top_time();
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
    const std::int32_t i = heap_.top();
    t_now_ = t_event;
    ++events_;
    // Re-based on a count of events alone, before any early return, so that the trajectory does
    // not depend on where run() is stopped.
    const bool rebase_due = ++events_since_rebase_ >= rebase_interval;
#ifdef GRANULE_PARANOID
    check_popped_event(i);
#endif
    const EventKind kind = kind_[at(i)];
    const std::int32_t j = partner_[at(i)];
    bool collided = false;
    if (kind == EventKind::kCollision) {
      if (count_[at(j)] != partner_count_[at(i)]) {
        predict(i);  // the partner has collided since: stale
      } else {
        collided = execute_collision(i, j);
      }
    } else if (kind == EventKind::kNone) {
      return StopReason::kNoEvents;  // only reachable when every time is +inf
    } else {
      execute_crossing(i, kind);
    }
    if (rebase_due) {
#ifdef GRANULE_PARANOID
      check_invariants();
#endif
      rebase();
    }
    if (collided) {
      if (collapse_detector_.on_collision(t_now_)) {
        collapse_ = {time(), i, j, {x_[at(i)], y_[at(i)]}};
        return StopReason::kInelasticCollapse;
      }
      if (collisions_ >= until_collisions) return StopReason::kCollisionsReached;
    }
  }
}

}  // namespace granule
