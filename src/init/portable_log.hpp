// Natural logarithm from IEEE-exact operations only (+ − × ÷, frexp/ldexp), so that its result
// is the same bit pattern on every platform and libm (libm's log may differ in the last bit, and
// the initial velocities would then differ).  Accurate to about 1 ulp (tested against std::log).
#pragma once

namespace granule {

// ln x for finite x > 0 (normal or subnormal); the caller guarantees the domain.
double portable_log(double x);

}  // namespace granule
