// Exponential and cube root from IEEE-exact operations only (+ − × ÷ √, round, frexp/ldexp), so
// that log-normal diameters and the diameter solved from a 3D packing fraction are the same bit
// pattern on every platform and libm (libm's exp and cbrt may differ in the last bit).  Both are
// accurate to about 1 ulp (tested against std::exp and std::cbrt).
#pragma once

namespace granule {

// e^x for |x| ≤ 700 (the caller guarantees the domain).
double portable_exp(double x);

// x^(1/d) for finite x > 0 and d ∈ {2, 3} (d = 2 is std::sqrt, correctly rounded by IEEE 754).
double portable_root(double x, int d);

}  // namespace granule
