// The engine's invariants, checked on demand (tests, restored checkpoints) and, in the
// GRANULE_PARANOID build, at every re-base and before every event (DynamO re-checks the event it
// is about to execute for the same reason: round-off can reorder near-simultaneous events).
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "boundary/surface_checks.hpp"
#include "engine/simulation.hpp"

namespace granule {

namespace {
inline std::size_t at(std::int32_t i) { return static_cast<std::size_t>(i); }
// Round-off allowance of a relative distance (an approaching pair may overlap by a few ulps).
constexpr double kDistanceTolerance = 1e-9;
// Round-off allowance between a stored event time and a fresh prediction of it, relative to the
// predicted delay; grazing collisions make the root ill-conditioned, hence far above 1 ulp.
constexpr double kDelayTolerance = 1e-6;
constexpr double kInf = std::numeric_limits<double>::infinity();

// Throws with the parts of the message written one after another (full precision for numbers).
template <typename... Parts>
[[noreturn]] void fail(const Parts&... parts) {
  std::ostringstream message;
  message.precision(17);
  message << "engine invariant violated: ";
  (message << ... << parts);
  throw std::logic_error(message.str());
}
}  // namespace

template <int D>
void Simulation<D>::check_invariants() const {
  const auto n = static_cast<std::int32_t>(params_.particles);
  if (!queue_.is_consistent()) fail("the event queue is inconsistent");
  // Every particle in exactly one list, the list of its own cell.
  std::vector<std::uint8_t> seen(at(n), 0);
  for (std::int64_t c = 0; c < grid_.cell_count(); ++c) {
    std::int64_t steps = 0;
    const auto cell = static_cast<std::int32_t>(c);
    for (std::int32_t j = lists_.first(cell); j != CellLists::kEnd; j = particles_[at(j)].next) {
      if (j < 0 || j >= n || ++steps > n || seen[at(j)]++ || slot(j).cell() != cell) {
        fail("cell list ", c, " is corrupt at particle ", j >= 0 && j < n ? user_id(j) : j, j >= 0 && j < n ? "" : " (an engine index)");
      }
    }
  }
  const double s = strain();
  const double cell_tolerance = kDistanceTolerance * std::max({grid_.width, grid_.height, grid_.depth});
  std::int64_t resting = 0;
  for (std::int32_t i = 0; i < n; ++i) {
    if (at_rest(i)) {
      // A support (physics/rest_rule.hpp): the moving grains' checks measure their distance to it.
      if (seen[at(i)]) fail("particle ", user_id(i), " is at rest but in a cell list");
      if (queue_.time_of(i) != std::numeric_limits<double>::infinity()) fail("particle ", user_id(i), " is at rest but has an event");
      ++resting;
      continue;
    }
    if (!seen[at(i)]) fail("particle ", user_id(i), " is in no cell list");
    const Vector r = position_now(i);
    bool finite = true;
    for (int a = 0; a < D; ++a) finite = finite && std::isfinite(r[a]) && std::isfinite(particles_[at(i)].v[a]);
    for (const auto& w : spin_) finite = finite && (w.empty() || std::isfinite(w[at(i)]));
    if (!finite) fail("particle ", user_id(i), " has a non-finite state");
    // A grain never passes into a surface beyond round-off.
    if (const SurfaceOverlap o = surface_overlap(boundaries_, slot(i).cell(), r, radius_of(i), kDistanceTolerance, time()); o.surface.found()) {
      fail("particle ", user_id(i), " is inside ", o.surface.name(), " by ", o.depth);
    }
    // Its cell, from the sheared abscissa ξ and the plain other coordinates.
    const std::array<int, D> cell = cell_coordinates(slot(i).cell());
    for (int a = 0; a < D; ++a) {
      const double coordinate = a == 0 ? boundaries_.frame().sheared_x(r[0], r[1], s) : r[a];
      if (coordinate < cell[a] * grid_.size(a) - cell_tolerance || coordinate > (cell[a] + 1) * grid_.size(a) + cell_tolerance) {
        fail("particle ", user_id(i), " is outside its cell along axis ", a, " (coordinate ", coordinate, ", cell ", cell[a], ")");
      }
    }
    for_each_neighbour(i, [&](std::int32_t j, const Vector& shift, double) {
      const double distance = norm(position_now(j) + shift - r);
      const double sigma = contact_distance(i, j);
      if (distance < sigma * (1.0 - kDistanceTolerance)) fail("particles ", user_id(i), " and ", user_id(j), " overlap: distance ", distance / sigma, " σ_ij");
    });
    // One event per particle (Smallenburg 2022): a particle's slot is never later than its true
    // next event, unless the partner of that event holds it in its own slot.
    const double stored = queue_.time_of(i);
    if (stored < t_now_) fail("particle ", user_id(i), " has an event in the past");
    const Prediction fresh = next_event(i);
    const EventKind kind = fresh.kind();
    if (kind == EventKind::kNone) continue;
    // A collision time is known only as well as the gap it closes: a separation known to
    // kDistanceTolerance σ_ij at a normal speed v_n gives the time to kDistanceTolerance σ_ij / v_n,
    // which inside an inelastic collapse (v_n → 0 while the grains still move) is no longer small.
    double slack = 0.0;
    double cosine = 0.0;
    if (kind == EventKind::kCollision) {
      const Vector offset = position_now(fresh.partner) - r;
      const PartnerImage image = nearest_image(offset);
      Vector v = velocity_now(fresh.partner) - velocity_now(i);
      v[0] += image.shift.velocity_x;
      const Vector d = offset + image.shift.position;
      const double normal_speed = std::abs(dot(d, v)) / norm(d);
      cosine = dot(d, v) / (norm(d) * norm(v));
      slack = kDistanceTolerance * contact_distance(i, fresh.partner) / normal_speed;
    } else if (is_surface_hit(kind)) {
      const double then = t_now_ + fresh.delay();
      slack = surface_hit_slack(boundaries_, hit_surface(kind), slot(i).cell(), position_at(i, then),
                                motion_.velocity_at(particles_[at(i)].v, then), radius_of(i), time() + fresh.delay(), params_.gravity);
    }
    const double due = t_now_ + fresh.delay() * (1.0 + kDelayTolerance) + slack;
    const bool held = stored <= due || (kind == EventKind::kCollision && queue_.time_of(fresh.partner) <= due);
    if (!held) {
      fail("particle ", user_id(i), " has its next event (", static_cast<int>(kind), " with ", fresh.partner < 0 ? -1 : user_id(fresh.partner), ") at t = ",
           t_now_ + fresh.delay(), " but its slot says ", stored, " (approach cosine ", cosine, ")");
    }
  }
  if (resting != boundaries_.resting_grains().count()) fail(resting, " grains are at rest but the boundaries list ", boundaries_.resting_grains().count());
}

template <int D>
void Simulation<D>::check_popped_event(std::int32_t i) const {
  const EventKind kind = slot(i).kind();
  const Vector r = position_now(i);
  if (kind == EventKind::kCollision) {
    const std::int32_t j = particles_[at(i)].partner;
    if (!candidate_valid(i)) return;  // stale: nothing to execute
    const Vector offset = position_now(j) - r;
    const double distance = norm(offset + nearest_image(offset).shift.position);
    const double sigma = contact_distance(i, j);
    if (distance > sigma * (1.0 + kDistanceTolerance)) {
      fail("collision of particles ", user_id(i), " and ", user_id(j), " popped at distance ", distance / sigma, " σ_ij");
    }
    return;
  }
  if (kind == EventKind::kNone) return;
  if (is_surface_hit(kind)) {  // the grain must touch the surface (or be short of it where a search may stop short)
    const SurfaceHitGap g = surface_hit_gap(boundaries_, hit_surface(kind), slot(i).cell(), r, radius_of(i), kDistanceTolerance,
                                            time(), params_.has_gravity());
    if (!g.may_fall_short && !(std::abs(g.gap) <= g.allowed)) {
      fail("hit of ", g.surface.name(), " by particle ", user_id(i), " popped at a gap of ", g.gap,
           " (allowed: ", g.allowed, ")");
    }
    return;
  }
  // A crossing: the particle must be on the face it is about to cross.
  const int axis = crossing_axis(kind);
  const double coordinate = axis == 0 ? boundaries_.frame().sheared_x(r[0], r[1], strain()) : r[axis];
  const int cell = cell_coordinates(slot(i).cell())[static_cast<std::size_t>(axis)];
  const double face = (cell + (crossing_direction(kind) > 0 ? 1 : 0)) * grid_.size(axis);
  if (std::abs(face - coordinate) > kDistanceTolerance * std::max({grid_.width, grid_.height, grid_.depth})) {
    fail("crossing of particle ", user_id(i), " popped ", face - coordinate, " away from its face");
  }
}

// The members defined in this file, for both dimensions (the class is instantiated in
// simulation.cpp, once).
template void Simulation<2>::check_invariants() const;
template void Simulation<2>::check_popped_event(std::int32_t) const;
template void Simulation<3>::check_invariants() const;
template void Simulation<3>::check_popped_event(std::int32_t) const;

}  // namespace granule
