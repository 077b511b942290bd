// A flat wall at one end of an axis (thesis Appendix A.1, "reflective boundaries"): a grain touches
// it when its centre is one radius away.  The wall moves tangentially at `velocity` (a wall-driven
// Couette flow moves the y walls at ±U/2 along x) and reflects the grain's velocity relative to it
// at the contact point: normal part × −restitution, tangential part × −tangential_restitution
// (physics/collision_law.hpp, the same law as between grains).
#pragma once

#include <array>

namespace granule {

struct WallParams {
  double restitution = 1.0;              // e_w ∈ (0, 1]
  double tangential_restitution = -1.0;  // β_w ∈ [−1, 1]: −1 a smooth wall, +1 a perfectly rough one
  std::array<double, 3> velocity{};      // tangential: its component along the wall's axis is 0
};

}  // namespace granule
