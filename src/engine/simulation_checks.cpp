// The engine's invariants, checked on demand (tests, restored checkpoints) and, in the
// GRANULE_PARANOID build, at every re-base and before every event (DynamO re-checks the event it
// is about to execute for the same reason: round-off can reorder near-simultaneous events).
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

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
// The surfaces below this are walls (faces 0 … 5); the last one is the obstacles.
constexpr int kWalls = BoxBoundaries<2>::kObstacles;
// The ulps of a box length within which a stored position is known after re-bases and flights.
constexpr double kRoundOffUlps = 16.0;

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
  for (std::int32_t i = 0; i < n; ++i) {
    if (!seen[at(i)]) fail("particle ", user_id(i), " is in no cell list");
    const Vector r = position_now(i);
    bool finite = true;
    for (int a = 0; a < D; ++a) finite = finite && std::isfinite(r[a]) && std::isfinite(particles_[at(i)].v[a]);
    for (const auto& w : spin_) finite = finite && (w.empty() || std::isfinite(w[at(i)]));
    if (!finite) fail("particle ", user_id(i), " has a non-finite state");
    for (int a = 0; a < D; ++a) {  // a grain never passes into a wall beyond round-off
      if (boundaries_.wall_penetration(a, r[a], radius_of(i), kDistanceTolerance * boundaries_.length(a), time()) > 0.0) {
        fail("particle ", user_id(i), " is in a wall along axis ", a, " at ", r[a]);
      }
    }
    for (const auto& obstacle : boundaries_.obstacle_lists().in_cell(slot(i).cell())) {  // nor into an obstacle
      const double contact = obstacle.radius + radius_of(i);
      if (norm(r - obstacle.centre) < contact * (1.0 - kDistanceTolerance)) {
        fail("particle ", user_id(i), " is inside obstacle ", obstacle.obstacle, ": distance ", norm(r - obstacle.centre) / contact, " of contact");
      }
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
    } else if (is_surface_hit(kind) && hit_surface(kind) < kWalls && !boundaries_.moving(hit_surface(kind)) &&
               params_.gravity[static_cast<std::size_t>(hit_surface(kind) / 2)] != 0.0) {
      // A grain resting on a floor: its position is known to a few ulps ε of L, and a parabola
      // that barely leaves the floor closes that gap in up to √(2ε/|g|) (seen: 2·10⁻¹³).
      const int axis = hit_surface(kind) / 2;
      const double gap = kRoundOffUlps * std::numeric_limits<double>::epsilon() * boundaries_.length(axis);
      slack = std::sqrt(2.0 * gap / std::abs(params_.gravity[static_cast<std::size_t>(axis)]));
    } else if (is_surface_hit(kind) && hit_surface(kind) < kWalls && boundaries_.moving(hit_surface(kind))) {
      // A hit on a moving wall is found within the wall's gap tolerance (boundary/moving_wall_hit.hpp):
      // two searches from different instants stop up to tolerance / closing speed apart.
      const int face = hit_surface(kind);
      const int axis = face / 2;
      const double delay = fresh.delay();
      const double speed_then = motion_.velocity_at(particles_[at(i)].v, t_now_ + delay)[axis];
      const double closing = std::abs(moving_gap_rate(boundaries_.moving_plane(face, radius_of(i)), speed_then, time() + delay));
      slack = 2.0 * boundaries_.gap_tolerance(axis) / closing;
    } else if (is_surface_hit(kind)) {
      // Likewise within the obstacles' tolerance (boundary/obstacle_hit.hpp), at the closing speed then.
      const double then = t_now_ + fresh.delay();
      const Vector at_hit = position_at(i, then);
      const Vector v_hit = motion_.velocity_at(particles_[at(i)].v, then);
      double closing = kInf;
      for (const auto& obstacle : boundaries_.obstacle_lists().in_cell(slot(i).cell())) {
        const Vector d = at_hit - obstacle.centre;
        if (std::abs(norm(d) - obstacle.radius - radius_of(i)) <= 2.0 * boundaries_.obstacle_lists().tolerance()) closing = std::abs(dot(d, v_hit)) / norm(d);
      }
      slack = 2.0 * boundaries_.obstacle_lists().tolerance() / closing;
    }
    const double due = t_now_ + fresh.delay() * (1.0 + kDelayTolerance) + slack;
    const bool held = stored <= due || (kind == EventKind::kCollision && queue_.time_of(fresh.partner) <= due);
    if (!held) {
      fail("particle ", user_id(i), " has its next event (", static_cast<int>(kind), " with ", fresh.partner < 0 ? -1 : user_id(fresh.partner), ") at t = ",
           t_now_ + fresh.delay(), " but its slot says ", stored, " (approach cosine ", cosine, ")");
    }
  }
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
  if (is_surface_hit(kind) && hit_surface(kind) < kWalls) {  // the grain must touch the wall (or, moving walls, not have passed it)
    const int face = hit_surface(kind);
    const int axis = face / 2;
    const double shift = boundaries_.displacement(face, time());
    const double wall = face % 2 == 0 ? shift : boundaries_.length(axis) - shift;
    const double gap = std::abs(r[axis] - wall) - radius_of(i);
    const bool rechecked = boundaries_.moving(face) && gap > 0.0;  // a search that stopped short (moving_wall_hit.hpp)
    if (!rechecked && std::abs(gap) > kDistanceTolerance * boundaries_.length(axis)) {
      fail("wall hit of particle ", user_id(i), " popped ", std::abs(r[axis] - wall) / radius_of(i), " radii from the wall");
    }
    return;
  }
  if (is_surface_hit(kind)) {  // an obstacle: the grain must touch one its cell lists
    double nearest = kInf;
    double contact = 0.0;
    for (const auto& obstacle : boundaries_.obstacle_lists().in_cell(slot(i).cell())) {
      const double gap = norm(r - obstacle.centre) - obstacle.radius - radius_of(i);
      if (std::abs(gap) < std::abs(nearest)) {
        nearest = gap;
        contact = obstacle.radius + radius_of(i);
      }
    }
    const bool rechecked = nearest > 0.0 && nearest < kInf && params_.has_gravity();  // a search that gave up (obstacle_hit.hpp)
    if (!rechecked && !(std::abs(nearest) <= boundaries_.obstacle_lists().tolerance() + kDistanceTolerance * contact)) {
      fail("obstacle hit of particle ", user_id(i), " popped ", nearest, " from the nearest obstacle's contact");
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
