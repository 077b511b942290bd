// Detects inelastic collapse (McNamara & Young 1994): collisions piling up in vanishing time.
// Every `window` collisions it compares the simulated time they took with the longest time any
// window took since the reset; a drop by more than `ratio`, or a clock that did not move, means a
// few disks are colliding infinitely often and the run cannot progress.  The longest window, not
// the previous one: a slow pile-up shrinks each window by a modest factor only (r^w = 0.37 for
// r = 0.999 per collision), and the clock re-bases keep its time from ever freezing.  A genuine
// speed-up by 10⁷ would need the temperature to rise by 10¹⁴.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "archive/state_archive.hpp"

namespace granule {

class CollapseDetector {
 public:
  // A window of N collisions is ~2 per particle: an ordinary run never speeds up by 1e7 there.
  static constexpr double kRatio = 1e-7;

  void reset(std::int64_t window, double now) {
    window_ = window;
    count_ = 0;
    start_ = now;
    longest_ = -1.0;
  }
  // Call once per collision at the current time; true when collapse is detected.
  bool on_collision(double now) {
    if (++count_ < window_) return false;
    const double span = now - start_;
    const bool collapsed = span <= 0.0 || (longest_ > 0.0 && span < kRatio * longest_);
    longest_ = std::max(longest_, span);
    count_ = 0;
    start_ = now;
    return collapsed;
  }
  void shift_times(double delta) { start_ -= delta; }

  void save(StateArchive& archive, const std::string& prefix) const {
    archive.put_integer(prefix + "window", window_);
    archive.put_integer(prefix + "count", count_);
    archive.put_scalar(prefix + "start", start_);
    archive.put_scalar(prefix + "longest", longest_);
  }
  void restore(const StateArchive& archive, const std::string& prefix) {
    window_ = archive.integer(prefix + "window");
    count_ = archive.integer(prefix + "count");
    start_ = archive.scalar(prefix + "start");
    longest_ = archive.scalar(prefix + "longest");
    if (window_ < 1 || count_ < 0 || !std::isfinite(start_) || !(std::isfinite(longest_) && longest_ >= -1.0)) {
      throw std::runtime_error("checkpoint entries " + prefix + "*: the collapse detector's window, count or times are not of a run");
    }
  }

 private:
  std::int64_t window_ = 1;
  std::int64_t count_ = 0;
  double start_ = 0.0;
  double longest_ = -1.0;
};

}  // namespace granule
