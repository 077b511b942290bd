// The Lees–Edwards side of the engine (ARCHITECTURE.md, "Shear protocols"): images of partners and
// of disks leaving the box, the image offset, the re-alignment of the sheared grid, and the changes
// of the image velocity U that follow the shear protocol segment by segment (the last two are
// global timed actions beside the event queue).
#include <cmath>
#include <limits>

#include "engine/simulation.hpp"

namespace granule {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
inline std::size_t at(std::int32_t i) { return static_cast<std::size_t>(i); }
}  // namespace

template <int D>
double Simulation<D>::shear_offset() const {
  const double lx = params_.length_x;
  const double offset = std::fmod(strain() * params_.length_y, lx);
  return offset < 0.0 ? offset + lx : offset;
}

template <int D>
void Simulation<D>::schedule_realignment() {
  // Computed afresh from t_ref whenever it moves (never shifted), so that a restored checkpoint
  // schedules it bit for bit as the uninterrupted run did.
  const double half = 0.5 * grid_.strain_period;
  actions_.schedule(TimedAction::kRealignGrid,
                    shear_rate_ != 0.0 ? t_ref_ + (std::copysign(half, shear_rate_) - strain_ref_) / shear_rate_ : kInf);
}

template <int D>
void Simulation<D>::enter_shear_segment(const ShearSegment& segment) {
  segment_end_ = segment.end;
  actions_.schedule(TimedAction::kShearSegment, segment.end - clock_base_);
  if (segment.velocity != frame_.shear_velocity) change_image_velocity(segment.velocity);
}

template <int D>
void Simulation<D>::change_image_velocity(double velocity) {
  strain_ref_ = strain();
  t_ref_ = t_now_;
  frame_.shear_velocity = velocity;
  shear_rate_ = velocity / params_.length_y;
  schedule_realignment();
  repredict_after_shear_change();
}

template <int D>
void Simulation<D>::repredict_after_shear_change() {
  const auto n = static_cast<std::int32_t>(params_.particles);
  for (std::int32_t i = 0; i < n; ++i) {
    const int row = cell_coordinates(slot(i).cell())[1];
    if (row == 0 || row == grid_.ny - 1 || !candidate_valid(i) || !recomputes_candidates()) {
      // Its block reaches across the boundary, where the images' velocity changed, or its
      // candidate is stale, or the grid too small to compute it again.
      predict(i);
      continue;
    }
    // The earliest collision inside the box is unchanged, and a candidate met through a y image
    // is computed again at the new U (candidate()); the crossing in ξ changes.
    const Candidate kept = candidate(i);
    const Crossing crossing = next_crossing(i, cell_coordinates(slot(i).cell()), position_now(i), velocity_now(i));
    const bool collision_first = kept.delay < crossing.delay;
    slot(i).set_kind(collision_first ? EventKind::kCollision : crossing.kind);
    queue_.update(i, t_now_ + (collision_first ? kept.delay : crossing.delay));
  }
}

template <int D>
void Simulation<D>::realign_sheared_grid() {
  // |strain| reached half a period: move t_ref by one period, which shifts the image offset by
  // a whole number of box widths (cell_grid.hpp), then re-bin everything on the new grid.
  t_ref_ += grid_.strain_period / std::abs(shear_rate_);
  rebuild();
}

template <int D>
typename Simulation<D>::PartnerImage Simulation<D>::nearest_image(const Vector& offset) const {
  // The nearest image in the sheared frame, unambiguous because cells are at least as large as
  // a contact pair (cell_grid.hpp); none across a wall axis.
  const double lx = params_.length_x;
  const double ly = params_.length_y;
  const double s = strain();
  const double dx = offset[0];
  const double dy = offset[1];
  const int iy = params_.walls[1] ? 0 : (dy > 0.5 * ly ? -1 : (dy < -0.5 * ly ? 1 : 0));
  const ImageShift row = frame_.image_shift(0, iy, s);
  FaceImage shift{};
  shift.position[0] = row.position.x;
  shift.position[1] = row.position.y;
  shift.velocity_x = row.velocity_x;
  const double dxi = (dx + shift.position[0]) - s * (dy + shift.position[1]);
  if (!params_.walls[0]) shift.position[0] -= lx * std::round(dxi / lx);
  if constexpr (D == 3) {
    if (!params_.walls[2]) shift.position[2] = -params_.length_z * std::round(offset[2] / params_.length_z);
  }
  return {iy, shift};
}

template <int D>
void Simulation<D>::enter_from_image(std::int32_t i, int image_y) {
  const ImageShift shift = frame_.image_shift(0, image_y, strain());
  ParticleRecord<D>& p = particles_[at(i)];
  p.r[0] += shift.position.x;
  p.r[1] += shift.position.y;
  Vector v = velocity_now(i);
  const double vx_before = v[0];
  v[0] += shift.velocity_x;
  set_velocity_now(i, v);
  if (observers_.empty()) return;
  const BoundaryCrossingRecord record{time(), user_id(i), -image_y, vx_before, v[0]};
  for (EventObserver<D>* observer : observers_) observer->on_boundary_crossing(record);
}

// The members defined in this file, for both dimensions (the class is instantiated in
// simulation.cpp, once).
template double Simulation<2>::shear_offset() const;
template void Simulation<2>::schedule_realignment();
template void Simulation<2>::enter_shear_segment(const ShearSegment&);
template void Simulation<2>::change_image_velocity(double);
template void Simulation<2>::repredict_after_shear_change();
template void Simulation<2>::realign_sheared_grid();
template Simulation<2>::PartnerImage Simulation<2>::nearest_image(const Vec<2>&) const;
template void Simulation<2>::enter_from_image(std::int32_t, int);
template double Simulation<3>::shear_offset() const;
template void Simulation<3>::schedule_realignment();
template void Simulation<3>::enter_shear_segment(const ShearSegment&);
template void Simulation<3>::change_image_velocity(double);
template void Simulation<3>::repredict_after_shear_change();
template void Simulation<3>::realign_sheared_grid();
template Simulation<3>::PartnerImage Simulation<3>::nearest_image(const Vec<3>&) const;
template void Simulation<3>::enter_from_image(std::int32_t, int);

}  // namespace granule
