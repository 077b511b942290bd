// The Lees–Edwards side of the engine (ARCHITECTURE.md, "Shear protocols"): the image offset, the
// re-alignment of the sheared grid, and the changes of the image velocity U that follow the shear
// protocol segment by segment (the last two are global timed actions beside the event queue).
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
  if (segment.velocity != image_velocity()) change_image_velocity(segment.velocity);
}

template <int D>
void Simulation<D>::change_image_velocity(double velocity) {
  strain_ref_ = strain();
  t_ref_ = t_now_;
  boundaries_.set_image_velocity(velocity);
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

// The members defined in this file, for both dimensions (the class is instantiated in
// simulation.cpp, once).
template double Simulation<2>::shear_offset() const;
template void Simulation<2>::schedule_realignment();
template void Simulation<2>::enter_shear_segment(const ShearSegment&);
template void Simulation<2>::change_image_velocity(double);
template void Simulation<2>::repredict_after_shear_change();
template void Simulation<2>::realign_sheared_grid();
template double Simulation<3>::shear_offset() const;
template void Simulation<3>::schedule_realignment();
template void Simulation<3>::enter_shear_segment(const ShearSegment&);
template void Simulation<3>::change_image_velocity(double);
template void Simulation<3>::repredict_after_shear_change();
template void Simulation<3>::realign_sheared_grid();

}  // namespace granule
