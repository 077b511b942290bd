// The engine's invariants, checked on demand (tests, restored checkpoints) and, in the
// GRANULE_PARANOID build, at every re-base and before every event (DynamO re-checks the event it
// is about to execute for the same reason: round-off can reorder near-simultaneous events).
#include <cmath>
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

void Simulation::check_invariants() const {
  const auto n = static_cast<std::int32_t>(params_.particles);
  if (!heap_.is_consistent()) fail("the event heap is out of order");
  // Every disk in exactly one list, the list of its own cell.
  std::vector<std::uint8_t> seen(at(n), 0);
  for (int c = 0; c < grid_.cell_count(); ++c) {
    std::int64_t steps = 0;
    for (std::int32_t j = lists_.first(c); j != CellLists::kEnd; j = lists_.next(j)) {
      if (j < 0 || j >= n || ++steps > n || seen[at(j)]++ || cell_[at(j)] != c) {
        fail("cell list ", c, " is corrupt at disk ", j);
      }
    }
  }
  const double s = strain();
  const double cell_tolerance = kDistanceTolerance * std::max(grid_.width, grid_.height);
  for (std::int32_t i = 0; i < n; ++i) {
    if (!seen[at(i)]) fail("disk ", i, " is in no cell list");
    const double dt = t_now_ - t_[at(i)];
    const double x = x_[at(i)] + vx_[at(i)] * dt;
    const double y = y_[at(i)] + vy_[at(i)] * dt;
    if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(vx_[at(i)]) || !std::isfinite(vy_[at(i)]) || dt < 0.0) {
      fail("disk ", i, " has a non-finite state or a local time after the clock");
    }
    const double xi = frame_.sheared_x(x, y, s);
    const int column = grid_.column_of(cell_[at(i)]);
    const int row = grid_.row_of(cell_[at(i)]);
    if (xi < column * grid_.width - cell_tolerance || xi > (column + 1) * grid_.width + cell_tolerance ||
        y < row * grid_.height - cell_tolerance || y > (row + 1) * grid_.height + cell_tolerance) {
      fail("disk ", i, " at (ξ, y) = (", xi, ", ", y, ") is outside its cell (", column, ", ", row, ")");
    }
    for_each_neighbour(i, [&](std::int32_t j, double shift_x, const ImageShift& row_shift) {
      const double dt_j = t_now_ - t_[at(j)];
      const double rx = x_[at(j)] + vx_[at(j)] * dt_j + shift_x - x;
      const double ry = y_[at(j)] + vy_[at(j)] * dt_j + row_shift.position.y - y;
      if (std::sqrt(rx * rx + ry * ry) < params_.diameter * (1.0 - kDistanceTolerance)) {
        fail("disks ", i, " and ", j, " overlap: distance ", std::sqrt(rx * rx + ry * ry) / params_.diameter, " σ");
      }
    });
    // One event per particle (Smallenburg 2022): a disk's slot is never later than its true next
    // event, unless the partner of that event holds it in its own slot.
    const double stored = heap_.time_of(i);
    if (stored < t_now_) fail("disk ", i, " has an event in the past");
    const Prediction fresh = next_event(i);
    const EventKind kind = fresh.kind();
    if (kind == EventKind::kNone) continue;
    const double due = t_now_ + fresh.delay() * (1.0 + kDelayTolerance);
    const bool held = stored <= due || (kind == EventKind::kCollision && heap_.time_of(fresh.partner) <= due);
    if (!held) {
      fail("disk ", i, " has its next event (", static_cast<int>(kind), " with ", fresh.partner, ") at t = ", t_now_ + fresh.delay(), " but its slot says ", stored);
    }
  }
}

void Simulation::check_popped_event(std::int32_t i) const {
  const EventKind kind = kind_[at(i)];
  const double dt = t_now_ - t_[at(i)];
  const double x = x_[at(i)] + vx_[at(i)] * dt;
  const double y = y_[at(i)] + vy_[at(i)] * dt;
  if (kind == EventKind::kCollision) {
    const std::int32_t j = partner_[at(i)];
    if (count_[at(j)] != partner_count_[at(i)]) return;  // stale: nothing to execute
    const double dt_j = t_now_ - t_[at(j)];
    const double dx = x_[at(j)] + vx_[at(j)] * dt_j - x;
    const double dy = y_[at(j)] + vy_[at(j)] * dt_j - y;
    const auto [iy, shift] = nearest_image(dx, dy);
    const double rx = dx + shift.position.x, ry = dy + shift.position.y;
    if (std::sqrt(rx * rx + ry * ry) > params_.diameter * (1.0 + kDistanceTolerance)) {
      fail("collision of disks ", i, " and ", j, " popped at distance ", std::sqrt(rx * rx + ry * ry) / params_.diameter, " σ");
    }
    return;
  }
  if (kind == EventKind::kNone) return;
  // A crossing: the disk must be on the face it is about to cross.
  const double xi = frame_.sheared_x(x, y, strain());
  const int column = grid_.column_of(cell_[at(i)]);
  const int row = grid_.row_of(cell_[at(i)]);
  const double face = kind == EventKind::kCrossRight ? (column + 1) * grid_.width - xi
                      : kind == EventKind::kCrossLeft ? xi - column * grid_.width
                      : kind == EventKind::kCrossUp   ? (row + 1) * grid_.height - y
                                                      : y - row * grid_.height;
  if (std::abs(face) > kDistanceTolerance * std::max(grid_.width, grid_.height)) {
    fail("crossing of disk ", i, " popped ", face, " away from its face");
  }
}

}  // namespace granule
