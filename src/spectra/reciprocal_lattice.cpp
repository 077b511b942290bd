#include "spectra/reciprocal_lattice.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace granule::spectra {

namespace {
constexpr double kTwoPi = 2.0 * std::numbers::pi;
}

double ReciprocalLattice::kx(int l) const { return kTwoPi * l / length_x; }

double ReciprocalLattice::ky(int l, int m) const { return kTwoPi * (m / length_y - l * tilt / length_x); }

double ReciprocalLattice::kz(int n) const { return kTwoPi * n / length_z; }

double ReciprocalLattice::phase(int l, int m, double x, double y) const { return kx(l) * x + ky(l, m) * y; }

double ReciprocalLattice::phase(int l, int m, int n, double x, double y, double z) const {
  return phase(l, m, x, y) + kz(n) * z;
}

double ReciprocalLattice::complete_radius(int max_mode) const {
  // |l| ≥ M+1 gives |k_x| ≥ 2π(M+1)/L_x; |l| ≤ M with |m| ≥ M+1 gives
  // |k_y| = 2π|m − l·tilt·L_y/L_x|/L_y ≥ 2π(M + 1 − M|tilt| L_y/L_x)/L_y.
  // In 3D |n| ≥ M+1 adds |k_z| ≥ 2π(M+1)/L_z (k3 is orthogonal to k1 and k2).
  const double shear = std::abs(tilt) * length_y / length_x;
  const double in_plane =
      std::min(kTwoPi * (max_mode + 1) / length_x, kTwoPi * (max_mode + 1 - max_mode * shear) / length_y);
  return dimension == 3 ? std::min(in_plane, kTwoPi * (max_mode + 1) / length_z) : in_plane;
}

ReciprocalLattice lattice_for_frame(const ShearFrame& frame, double shear_offset, int dimension, double length_z) {
  ReciprocalLattice lattice{frame.length_x, frame.length_y, 0.0, dimension, length_z};
  if (frame.sheared()) {
    const double period = frame.length_x / frame.length_y;  // [γt] is defined modulo L_x/L_y
    const double tilt = shear_offset / frame.length_y;
    lattice.tilt = tilt - period * std::floor(tilt / period + 0.5);
  }
  return lattice;
}

double complete_radius_at_any_strain(const ShearFrame& frame, int max_mode, int dimension, double length_z) {
  const double worst_tilt = frame.sheared() ? 0.5 * frame.length_x / frame.length_y : 0.0;
  return ReciprocalLattice{frame.length_x, frame.length_y, worst_tilt, dimension, length_z}.complete_radius(max_mode);
}

}  // namespace granule::spectra
