// Extended XYZ frames for OVITO (and ASE): one block per frame,
//   N
//   Lattice="L_x 0 0 0 L_y 0 0 0 1" Properties=species:S:1:pos:R:3:velo:R:3:radius:R:1 Time=t ... pbc="T T F"
//   D x y 0 v_x v_y 0 σ/2
// and in 3D Lattice="L_x 0 0 0 L_y 0 0 0 L_z", pbc="T T T", rows "D x y z v_x v_y v_z σ/2".  The
// radius is each particle's own σ/2 when polydisperse (the `radius` column, which OVITO reads as its
// Radius property).  The comment line also records c (collisions_per_particle), the boundary and,
// for Lees–Edwards, the image offset Δ (shear_offset, along x between the images above and below in
// y) and U (shear_velocity): OVITO's box is plainly periodic.  Rough grains add the angular velocity
// as a last column triple `omega:R:3` (ω_x ω_y ω_z; 0 0 ω_z for disks).
#pragma once

#include <ostream>
#include <string>

#include "engine/system_params.hpp"

namespace granule {

struct XyzFrameInfo {
  double diameter = 0.0;  // σ of a monodisperse configuration
  double length_x = 1.0;
  double length_y = 1.0;
  double time = 0.0;
  double collisions_per_particle = 0.0;
  std::string boundary = "periodic";
  double shear_velocity = 0.0;
  double shear_offset = 0.0;
  double length_z = 1.0;  // 3D only
};

// Appends one frame (full double precision) to `out`.
void write_xyz_frame(std::ostream& out, const ParticleState& particles, const XyzFrameInfo& info);

}  // namespace granule
