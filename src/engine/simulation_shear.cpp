// The Lees–Edwards side of the engine (ARCHITECTURE.md, "Shear protocols"): images of partners and
// of disks leaving the box, the image offset, the re-alignment of the sheared grid, and the changes
// of the image velocity U that follow the shear protocol segment by segment (the last two are
// global timed actions beside the event heap).
#include <cmath>
#include <limits>

#include "engine/simulation.hpp"

namespace granule {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
inline std::size_t at(std::int32_t i) { return static_cast<std::size_t>(i); }
}  // namespace

double Simulation::shear_offset() const {
  const double lx = params_.length_x;
  const double offset = std::fmod(strain() * params_.length_y, lx);
  return offset < 0.0 ? offset + lx : offset;
}

void Simulation::schedule_realignment() {
  // Computed afresh from t_ref whenever it moves (never shifted), so that a restored checkpoint
  // schedules it bit for bit as the uninterrupted run did.
  const double half = 0.5 * grid_.strain_period;
  actions_.schedule(TimedAction::kRealignGrid,
                    shear_rate_ != 0.0 ? t_ref_ + (std::copysign(half, shear_rate_) - strain_ref_) / shear_rate_ : kInf);
}

void Simulation::enter_shear_segment(const ShearSegment& segment) {
  segment_end_ = segment.end;
  actions_.schedule(TimedAction::kShearSegment, segment.end - clock_base_);
  if (segment.velocity != frame_.shear_velocity) change_image_velocity(segment.velocity);
}

void Simulation::change_image_velocity(double velocity) {
  strain_ref_ = strain();
  t_ref_ = t_now_;
  frame_.shear_velocity = velocity;
  shear_rate_ = velocity / params_.length_y;
  schedule_realignment();
  repredict_after_shear_change();
}

void Simulation::repredict_after_shear_change() {
  const auto n = static_cast<std::int32_t>(params_.particles);
  if (collision_time_.empty()) {  // a constant protocol changes U once at most (a static start)
    for (std::int32_t i = 0; i < n; ++i) predict(i);
    return;
  }
  for (std::int32_t i = 0; i < n; ++i) {
    const int row = grid_.row_of(cell_[at(i)]);
    if (row == 0 || row == grid_.ny - 1) {
      predict(i);  // its 3×3 block reaches across the boundary, where the images' velocity changed
      continue;
    }
    // The earliest collision inside the box is unchanged; the crossing in ξ is not.
    const double dt = t_now_ - t_[at(i)];
    const Crossing crossing = next_crossing(i, x_[at(i)] + vx_[at(i)] * dt, y_[at(i)] + vy_[at(i)] * dt);
    const double t_crossing = t_now_ + crossing.delay;
    const bool collision_first = collision_time_[at(i)] < t_crossing;
    kind_[at(i)] = collision_first ? EventKind::kCollision : crossing.kind;
    heap_.update(i, collision_first ? collision_time_[at(i)] : t_crossing);
  }
}

void Simulation::realign_sheared_grid() {
  // |strain| reached half a period: move t_ref by one period, which shifts the image offset by
  // a whole number of box widths (cell_grid.hpp), then re-bin everything on the new grid.
  t_ref_ += grid_.strain_period / std::abs(shear_rate_);
  rebuild();
}

Simulation::PartnerImage Simulation::nearest_image(double dx, double dy) const {
  // The nearest image in the sheared frame, unambiguous because cells are at least as large as
  // a contact pair (cell_grid.hpp).
  const double lx = params_.length_x;
  const double ly = params_.length_y;
  const double s = strain();
  const int iy = dy > 0.5 * ly ? -1 : (dy < -0.5 * ly ? 1 : 0);
  ImageShift shift = frame_.image_shift(0, iy, s);
  const double dxi = (dx + shift.position.x) - s * (dy + shift.position.y);
  shift.position.x -= lx * std::round(dxi / lx);
  return {iy, shift};
}

void Simulation::enter_from_image(std::int32_t i, int image_y) {
  const ImageShift shift = frame_.image_shift(0, image_y, strain());
  const double vx_before = vx_[at(i)];
  x_[at(i)] += shift.position.x;
  y_[at(i)] += shift.position.y;
  vx_[at(i)] += shift.velocity_x;
  if (observers_.empty()) return;
  const BoundaryCrossingRecord record{time(), i, -image_y, vx_before, vx_[at(i)]};
  for (EventObserver* observer : observers_) observer->on_boundary_crossing(record);
}

}  // namespace granule
