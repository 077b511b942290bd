// A one-line progress display on a terminal: percent done, collisions per second and ETA.
#pragma once

#include <chrono>
#include <cstdio>
#include <unistd.h>

namespace granule::driver {

class Progress {
 public:
  Progress() : enabled_(isatty(fileno(stderr)) != 0), start_(Clock::now()), last_(start_) {}

  // fraction ∈ [0, 1]; redraws at most every half second.
  void update(double fraction, double c, double t, double collisions_per_second) {
    if (!enabled_) return;
    const auto now = Clock::now();
    if (now - last_ < std::chrono::milliseconds(500)) return;
    last_ = now;
    const double elapsed = seconds_since_start();
    const double eta = fraction > 0.0 ? elapsed * (1.0 - fraction) / fraction : 0.0;
    std::fprintf(stderr, "\r  %5.1f%%  c = %-10.4g t = %-10.4g %8.3g collisions/s  ETA %3d:%02d ",
                 100.0 * fraction, c, t, collisions_per_second, static_cast<int>(eta) / 60,
                 static_cast<int>(eta) % 60);
    std::fflush(stderr);
  }
  void finish() {
    if (enabled_) std::fprintf(stderr, "\n");
  }
  double seconds_since_start() const {
    return std::chrono::duration<double>(Clock::now() - start_).count();
  }

 private:
  using Clock = std::chrono::steady_clock;
  bool enabled_;
  Clock::time_point start_;
  Clock::time_point last_;
};

}  // namespace granule::driver
