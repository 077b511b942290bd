// Detects inelastic collapse (McNamara & Young 1994): collisions piling up in vanishing time.
// Every `window` collisions it compares the simulated time they took with the time the previous
// window took; a drop by more than `ratio`, or a clock that did not move, means a few disks are
// colliding infinitely often and the run cannot progress.
#pragma once

#include <cstdint>
#include <string>

#include "engine/state_archive.hpp"

namespace granule {

class CollapseDetector {
 public:
  // A window of N collisions is ~2 per particle: an ordinary run never speeds up by 1e7 there.
  static constexpr double kRatio = 1e-7;

  void reset(std::int64_t window, double now) {
    window_ = window;
    count_ = 0;
    start_ = now;
    previous_ = -1.0;
  }
  // Call once per collision at the current time; true when collapse is detected.
  bool on_collision(double now) {
    if (++count_ < window_) return false;
    const double span = now - start_;
    const bool collapsed = span <= 0.0 || (previous_ > 0.0 && span < kRatio * previous_);
    previous_ = span;
    count_ = 0;
    start_ = now;
    return collapsed;
  }
  void shift_times(double delta) { start_ -= delta; }

  void save(StateArchive& archive, const std::string& prefix) const {
    archive.put_integer(prefix + "window", window_);
    archive.put_integer(prefix + "count", count_);
    archive.put_scalar(prefix + "start", start_);
    archive.put_scalar(prefix + "previous", previous_);
  }
  void restore(const StateArchive& archive, const std::string& prefix) {
    window_ = archive.integer(prefix + "window");
    count_ = archive.integer(prefix + "count");
    start_ = archive.scalar(prefix + "start");
    previous_ = archive.scalar(prefix + "previous");
  }

 private:
  std::int64_t window_ = 1;
  std::int64_t count_ = 0;
  double start_ = 0.0;
  double previous_ = -1.0;
};

}  // namespace granule
