// Periodic and Lees–Edwards boundaries in one description (thesis §1.4.2, Appendix A.1).
//
// The images above and below the box slide at ±U; a particle leaving through the top re-enters at
// the bottom shifted by the current image offset Δ and with v_x − U (and the reverse).  Granule
// works in the sheared (Lagrangian) frame of the mean flow u(y) = γ (y − L_y/2), γ = U/L_y:
//     ξ = x − s (y − L_y/2),   s = γ (t − t_ref)   (the strain since the grid was last aligned).
// Choosing t_ref with U t_ref ≡ 0 (mod L_x) makes the offset Δ ≡ s L_y (mod L_x), so that ξ is
// simply periodic in L_x across the sheared boundary: the cell grid lives in (ξ, y) and never
// sees the boundary move.  Periodic boxes are the special case U = 0, s = 0.
//
// Every relative position and velocity across the boundary goes through image_shift(): a missing
// velocity shift is the classic Lees–Edwards bug.
#pragma once

#include <cmath>

#include "geometry/vec.hpp"

namespace granule {

struct ImageShift {
  Vec2 position;     // add to the partner's lab position
  double velocity_x;  // add to the partner's lab v_x
};

struct ShearFrame {
  double length_x = 1.0;        // L_x
  double length_y = 1.0;        // L_y
  double shear_velocity = 0.0;  // U: velocity of the upper image relative to the box

  double shear_rate() const { return shear_velocity / length_y; }  // γ = U / L_y
  bool sheared() const { return shear_velocity != 0.0; }

  // The image (ix, iy) of a particle: ix boxes to the right in ξ, iy boxes up, at strain s.
  // Upper images (iy = +1) sit at x + s L_y and move at v_x + U (thesis §1.4.2).
  ImageShift image_shift(int ix, int iy, double strain) const {
    return {{ix * length_x + iy * strain * length_y, iy * length_y}, iy * shear_velocity};
  }

  // Sheared abscissa ξ of a lab position at strain s.
  double sheared_x(double x, double y, double strain) const {
    return x - strain * (y - 0.5 * length_y);
  }

  // Map a lab position (and v_x) into the box x ∈ [0, L_x), y ∈ [0, L_y), applying the image rule
  // of thesis §1.4.2 when y is outside.  Idempotent on points already inside.
  void wrap_into_box(double& x, double& y, double& vx, double strain) const {
    const int iy = y < 0.0 ? 1 : (y >= length_y ? -1 : 0);
    if (iy != 0) {
      const double y_in = y + iy * length_y;
      if (y_in >= 0.0 && y_in < length_y) {
        const ImageShift shift = image_shift(0, iy, strain);
        x += shift.position.x;
        y = y_in;
        vx += shift.velocity_x;
      } else {
        y = 0.0;  // a hair below 0 that rounds onto L_y: the bottom edge itself
      }
    }
    x -= length_x * std::floor(x / length_x);
    if (x >= length_x) x = 0.0;
  }

  // Mean-flow velocity u(y) = γ (y − L_y/2): the boundaries move at ±U/2.
  double mean_flow(double y) const { return shear_rate() * (y - 0.5 * length_y); }
};

}  // namespace granule
