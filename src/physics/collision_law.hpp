// The collision law: which restitution a collision gets, applied in one place by the engine
// (execute_collision).  Today one law, smooth grains with a constant normal restitution ẽ
// (thesis eq 1.2) and, optionally, the TC model; rough grains (tangential restitution, spin)
// join as a second law next, beside this one, without touching the event loop.
#pragma once

#include <vector>

namespace granule {

struct CollisionLaw {
  double restitution = 1.0;  // ẽ ∈ (0, 1]
  // TC model (Luding & McNamara 1998): a collision is elastic if either partner collided less
  // than tc_duration ago; 0 switches it off (and then no per-particle history is kept).
  double tc_duration = 0.0;

  bool keeps_history() const { return tc_duration > 0.0; }
  // The restitution of a collision at time `now` between particles whose last collisions were at
  // `last_first` and `last_second`.
  double restitution_at(double now, double last_first, double last_second) const {
    if (keeps_history() && (now - last_first < tc_duration || now - last_second < tc_duration)) return 1.0;
    return restitution;
  }
};

}  // namespace granule
