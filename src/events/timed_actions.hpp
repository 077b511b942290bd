// The engine's global timed actions, kept beside the per-particle event queue: re-aligning the
// sheared cell grid and moving to the next segment of the shear protocol.  Each kind is pending at
// most once, so the list is a fixed array and "the earliest" a scan of two entries.  Stops and
// timed outputs are not in it: they are the caller's (the driver's) times, passed to run().
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>

namespace granule {

enum class TimedAction : std::uint8_t {
  kShearSegment,  // the image velocity U changes to the next segment's mean (shear_protocol.hpp)
  kRealignGrid,   // |strain| reached half a period: shift the grid by one period and re-bin
};

class TimedActions {
 public:
  static constexpr std::size_t kKinds = 2;

  void schedule(TimedAction action, double time) { times_[index(action)] = time; }
  double time_of(TimedAction action) const { return times_[index(action)]; }
  // The earliest pending action; ties go to the one listed first in TimedAction.
  TimedAction earliest() const { return times_[1] < times_[0] ? TimedAction::kRealignGrid : TimedAction::kShearSegment; }
  double earliest_time() const { return time_of(earliest()); }
  void shift_times(double delta) {
    for (double& t : times_) t -= delta;
  }

 private:
  static std::size_t index(TimedAction action) { return static_cast<std::size_t>(action); }
  std::array<double, kKinds> times_{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
};

}  // namespace granule
