#include <algorithm>
#include <limits>
#include <numbers>

#include "boundary/wall.hpp"

namespace granule {

ShearProtocol WallMotion::velocity() const {
  ShearHistory history;
  if (amplitude > 0.0) {
    // The velocity dh/dt for all t ≥ 0: 2πfA sin 2πft, whose integral from 0 is A (1 − cos 2πft); a
    // square wave of 4Af, whose integral is the triangle; a triangle wave of peak 8Af, whose integral
    // (its own integral over a cycle's first half is 8Af/(4f) = 2A) is the bi-parabolic h.
    const Waveform waveform = shape == VibrationShape::kSine       ? Waveform::kSine
                              : shape == VibrationShape::kTriangle ? Waveform::kSquare
                                                                   : Waveform::kTriangle;
    const double peak = shape == VibrationShape::kSine       ? 2.0 * std::numbers::pi * frequency * amplitude
                        : shape == VibrationShape::kTriangle ? 4.0 * frequency * amplitude
                                                             : 8.0 * frequency * amplitude;
    history.oscillation = ShearOscillation{peak, 1.0 / frequency, 0.0, std::numeric_limits<double>::infinity(), waveform};
  }
  if (!schedule.empty()) {
    // h piecewise linear: a velocity step at every point (two points at one time), 0 outside.
    history.schedule.push_back({schedule.front().time, 0.0});
    for (std::size_t k = 0; k + 1 < schedule.size(); ++k) {
      const WallPositionPoint& p = schedule[k];
      const WallPositionPoint& q = schedule[k + 1];
      const double u = (q.displacement - p.displacement) / (q.time - p.time);
      history.schedule.push_back({p.time, u});
      history.schedule.push_back({q.time, u});
    }
    history.schedule.push_back({schedule.back().time, 0.0});
  }
  return ShearProtocol(0.0, history);
}

double WallMotion::reach() const {
  double most = 0.0;
  for (const WallPositionPoint& p : schedule) most = std::max(most, p.displacement);
  return most + 2.0 * amplitude;
}

}  // namespace granule
