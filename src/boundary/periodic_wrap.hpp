// The periodic wrap of an axis without shear (x without Lees–Edwards, z): into [0, L).
#pragma once

#include <cmath>

namespace granule {

inline void wrap_periodic(double& z, double length) {
  z -= length * std::floor(z / length);
  if (z >= length) z = 0.0;  // a tiny negative z rounds up to L
}

}  // namespace granule
