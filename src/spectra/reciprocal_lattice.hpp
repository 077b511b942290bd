// The wavevectors a box allows (thesis §2.2 and §3.2.1): k = l k1 + m k2 with integers l, m.
//
// Periodic box: k1 = (2π/L_x, 0), k2 = (0, 2π/L_y), i.e. k = (2πp/L_x, 2πq/L_y).
// Lees–Edwards box: the images form the lattice a1 = (L_x, 0), a2 = ([γt] L_y, L_y) (3.6)–(3.7), whose
// reciprocal lattice is k1 = (2π/L_x, −2π[γt]/L_x), k2 = (0, 2π/L_y) (3.10)–(3.12), so that
// k·a1 = 2πl and k·a2 = 2πm.  [γt] is only defined modulo L_x/L_y (adding L_x/L_y relabels m → m + l);
// we take the representative in [−L_x/2L_y, L_x/2L_y), which keeps the tilted lattice closest to the
// rectangular one and so makes the computed modes |l|, |m| ≤ M cover the widest disc in k-space.
// 3D (spheres, thesis Appendix C): flow x, gradient y, vorticity z; the images along y are shifted along
// x as in 2D and z is plainly periodic, so the lattice gains k3 = (0, 0, 2π/L_z) and k = l k1 + m k2 + n k3
// with k1 = (2π/L_x, −2π[γt]/L_x, 0), k2 = (0, 2π/L_y, 0): k·a3 = 2πn for a3 = (0, 0, L_z).
// Units: k in radians per unit length of the box.
#pragma once

#include "boundary/shear_frame.hpp"

namespace granule::spectra {

struct ReciprocalLattice {
  double length_x = 1.0;  // L_x
  double length_y = 1.0;  // L_y
  double tilt = 0.0;      // [γt]: the image above is shifted by tilt · L_y (mod L_x); 0 when periodic
  int dimension = 2;      // d: 2 or 3
  double length_z = 1.0;  // L_z (3D only)

  double kx(int l) const;
  double ky(int l, int m) const;
  double kz(int n) const;
  // Phase k·r of mode (l, m) at a lab position: the exact sums (3.4)–(3.5) use this directly.
  double phase(int l, int m, double x, double y) const;
  // 3D: the phase of (l, m) plus k_z z.
  double phase(int l, int m, int n, double x, double y, double z) const;
  // The same phase written as l θ_ξ + m θ_y with θ_ξ = 2π (x − tilt·y)/L_x, θ_y = 2π y/L_y: in the
  // sheared coordinate ξ = x − tilt·y the lattice is rectangular (what the fast method grids on).
  double sheared_abscissa(double x, double y) const { return x - tilt * y; }
  // Radius below which every lattice point has |l|, |m| (, |n|) ≤ max_mode (annulus and shell sums
  // stop there).
  double complete_radius(int max_mode) const;
};

// The lattice of a snapshot: periodic, or Lees–Edwards with [γt] = Δ / L_y from the stored image
// offset Δ = U t mod L_x (README, snapshots.h5), so that a2 = (Δ, L_y) is exactly the image rule.
// In 3D (`dimension` = 3) the box has the periodic depth `length_z`.
ReciprocalLattice lattice_for_frame(const ShearFrame& frame, double shear_offset, int dimension = 2,
                                    double length_z = 1.0);

// The complete radius at the worst strain of a run (|[γt]| = L_x/2L_y when sheared), so that the
// annulus (shell) bins of every frame of a run are the same.
double complete_radius_at_any_strain(const ShearFrame& frame, int max_mode, int dimension = 2, double length_z = 1.0);

}  // namespace granule::spectra
