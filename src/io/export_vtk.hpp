// VTK XML files for ParaView: particles as PolyData (.vtp: points with velocity and radius, one
// vertex cell each), coarse-grained fields as ImageData (.vti: one value per coarse-graining cell,
// CellData, x fastest as in FieldGrid, in 2D or 3D), and a collection (.pvd) that makes a time series of either.
// Arrays are Float64, appended raw little-endian with UInt64 block sizes.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "analysis/field_grid.hpp"
#include "engine/system_params.hpp"

namespace granule {

// Positions (x, y, z), "velocity" (v_x, v_y, v_z) (z = 0 in 2D) and "radius" σ/2 of each particle
// (its own diameter when polydisperse, else `diameter`), and for rough grains "AngularVelocity"
// (ω_x, ω_y, ω_z; (0, 0, ω_z) for disks); the frame's time as TimeValue.
void write_vtp_particles(const std::string& path, const ParticleState& particles, double diameter, double time);

struct NamedCellArray {
  std::string name;
  std::vector<double> values;  // grid.cells() values, cell ix + nx·(iy + ny·iz)
};

// An nx × ny image of cells spanning the box [0, L_x] × [0, L_y] (3D: nx × ny × nz over
// [0, L_x] × [0, L_y] × [0, L_z]).
void write_vti_fields(const std::string& path, const FieldGrid& grid, const std::vector<NamedCellArray>& arrays, double time);

// A ParaView collection: (time, file name relative to the .pvd) per frame.
void write_pvd(const std::string& path, const std::vector<std::pair<double, std::string>>& frames);

}  // namespace granule
