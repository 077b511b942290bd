#include <algorithm>
#include <limits>
#include <numbers>

#include "boundary/wall.hpp"

namespace granule {

ShearProtocol WallMotion::velocity() const {
  ShearHistory history;
  if (amplitude > 0.0) {
    // u = 2πfA sin 2πft for all t ≥ 0, whose integral from 0 is A (1 − cos 2πft).
    history.oscillation = ShearOscillation{2.0 * std::numbers::pi * frequency * amplitude, 1.0 / frequency, 0.0,
                                           std::numeric_limits<double>::infinity()};
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
